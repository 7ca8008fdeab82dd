#pragma once
// The 3D vector field the volume topology works on, in INDEX SPACE (positions in cells, node
// (i, j, k) at q = (i, j, k); velocities in cells per unit time, w = (v_x/dx, v_y/dy, v_z/dz)),
// with its piecewise-linear interpolant on the Freudenthal (Kuhn) split of every cell into six
// tetrahedra.
//
// The split: with local coordinates s in [0, 1]^3, the tetrahedron of the axis permutation
// (a, b, c) is { s_a >= s_b >= s_c } with vertices 0, e_a, e_a + e_b, (1, 1, 1): all six share
// the cell's main diagonal. Why this split rather than VTK's five tetrahedra per voxel
// (vtkDataSetTriangleFilter, two mirrored patterns alternating with the cell's parity): it is the
// same in every cell, so it is conforming across cell faces by translation alone (the face
// diagonals of neighbouring cells match), the tetrahedron holding a point is found by sorting its
// local coordinates, and its barycentric coordinates are differences of the sorted ones
// (Freudenthal 1942; Kuhn 1960). Both splits reproduce linear fields exactly, and fields of the
// form (f(x), g(y), h(z)) too (the interpolant of f(x) in a tetrahedron with vertices at cell
// corners is f's 1D linear interpolant), so their zeros agree with VTK's on such fields.
//
// Index space changes neither the zeros nor the degree of v/|v| (positive diagonal scaling), and
// leaves the eigenvalues of the Jacobian unchanged (J_index = D^-1 J_world D, D = diag(h)).
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "fieldviz/core/Field.h"

namespace fluidviz::topology {

using Mat3 = Eigen::Matrix3d;

/// One tetrahedron of the Kuhn split of cell `cell`: vertex k at cell + corner[k] (index space).
struct KuhnTetrahedron {
  std::array<int, 3> cell;
  std::array<Eigen::Vector3i, 4> corner;  ///< 0, e_a, e_a + e_b, (1, 1, 1)
};

/// The six tetrahedra of a cell, in a fixed order (permutations of the axes).
std::array<KuhnTetrahedron, 6> kuhnTetrahedra(const std::array<int, 3>& cell);

class VolumeField {
 public:
  /// Throws std::invalid_argument when the grid has fewer than 2 nodes along some axis or the
  /// value count does not match.
  explicit VolumeField(const VectorField& field);

  const Grid& grid() const { return grid_; }
  int n(int axis) const { return grid_.dims[axis]; }

  /// Index-space velocity at node (i, j, k).
  Vec3 node(int i, int j, int k) const { return w_[grid_.index(i, j, k)]; }
  Vec3 node(const Eigen::Vector3i& p) const { return node(p.x(), p.y(), p.z()); }
  /// Piecewise-linear (Kuhn) interpolant at index-space q (clamped into the domain).
  Vec3 operator()(const Vec3& q) const;
  /// Cell whose closed cube contains q (the last cell on the upper boundaries).
  std::array<int, 3> cellOf(const Vec3& q) const;

  /// Central differences of the interpolant with a step of one cell (one-sided where that
  /// leaves the domain); index space.
  Mat3 jacobianFiniteDifference(const Vec3& q) const;
  /// Index-space Jacobian to world units: J_world(i, j) = J_index(i, j) * h_i / h_j.
  Mat3 toWorldJacobian(const Mat3& j_index) const;
  /// RMS of the Frobenius norm of the world-space finite-difference Jacobian (1/s) over the
  /// nodes of the cube of half-width `radius` cells around q (clipped to the grid): the local
  /// field scale against which det J is judged. O(1) per query (summed-volume table).
  double gradientScale(const Vec3& q, double radius) const;

  Vec3 toWorld(const Vec3& q) const;
  /// Distance (cells) from q to the nearest domain face; negative outside.
  double distanceToBoundary(const Vec3& q) const;

 private:
  void buildGradientTable();

  Grid grid_;
  std::vector<Vec3> w_;
  std::vector<double> table_;  // summed-volume table of |J_world|_F^2 at the nodes
};

}  // namespace fluidviz::topology
