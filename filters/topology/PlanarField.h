#pragma once
// The planar vector field the topology filter works on: the in-plane components of a 2D field
// (or of one z-slice of a 3D field), expressed in INDEX SPACE — positions in cells (node (i, j)
// at q = (i, j)) and velocities in cells per unit time (w = (v_x / dx, v_y / dy)).
//
// Index space changes neither the zeros, nor the winding numbers, nor the sectors (a positive
// diagonal scaling of space and field), and it leaves the eigenvalues of the Jacobian unchanged
// (J_index = D^-1 J_world D with D = diag(dx, dy)), so everything downstream works in cells.
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/topology/CriticalPoint.h"
#include "filters/topology/WindowRms.h"

namespace fluidviz::topology {

/// Bilinear patch over one cell: F(s, t) = c0 + c1 s + c2 t + c3 s t for (s, t) in [0, 1]^2.
struct BilinearPatch {
  Vec2 c0, c1, c2, c3;
  static BilinearPatch fromCorners(const Vec2& f00, const Vec2& f10, const Vec2& f01,
                                   const Vec2& f11);
  Vec2 operator()(double s, double t) const { return c0 + c1 * s + c2 * t + c3 * (s * t); }
  /// dF/d(s, t); its determinant is affine in (s, t) (the st terms cancel).
  Mat2 jacobian(double s, double t) const;
};

class PlanarField {
 public:
  /// The (v_x, v_y) components of node layer `slice` (ignored for 2D). Throws ParamError
  /// ("slice_index") when the slice does not exist and std::invalid_argument when the grid has
  /// fewer than 2 x 2 nodes or the value count does not match.
  PlanarField(const VectorField& field, int slice);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int slice() const { return slice_; }
  const Grid& grid() const { return grid_; }

  /// Index-space velocity at node (i, j).
  Vec2 node(int i, int j) const {
    const std::size_t n = static_cast<std::size_t>(j) * nx_ + i;
    return {u_[n], v_[n]};
  }
  /// Bilinear interpolant at index-space point q (clamped into the domain).
  Vec2 operator()(const Vec2& q) const;
  BilinearPatch cellPatch(int i, int j) const;
  /// Cell (i, j) whose closed square contains q (the last cell on the upper boundary).
  std::array<int, 2> cellOf(const Vec2& q) const;

  /// Central differences of the interpolant with a step of one cell (one-sided where that
  /// leaves the domain); index space.
  Mat2 jacobianFiniteDifference(const Vec2& q) const;
  /// Jacobian of the bilinear interpolant of cell `cell` at q; index space.
  Mat2 jacobianInterpolant(const Vec2& q, const std::array<int, 2>& cell) const;
  /// Exact Jacobian of the interpolant at q: that of the cell holding q; on an edge or node
  /// shared by several cells (where the interpolant is only continuous) the mean of theirs, which
  /// there equals the central difference with a one-cell step along the crossing axes. Index
  /// space.
  Mat2 jacobianAtPoint(const Vec2& q) const;
  /// Index-space Jacobian to world units: J_world(i, j) = J_index(i, j) * h_i / h_j.
  Mat2 toWorldJacobian(const Mat2& j_index) const;
  /// RMS of the Frobenius norm of the world-space finite-difference Jacobian (1/s) over the
  /// nodes of the square window of half-width `radius` cells around q (clipped to the grid): the
  /// local field scale against which det J is judged. O(1) per query (summed-area table).
  double gradientScale(const Vec2& q, double radius) const;

  Vec3 toWorld(const Vec2& q) const;
  Vec2 toIndex(const Vec3& p) const;
  /// World direction (unit) of an index-space direction.
  Vec2 toWorldDirection(const Vec2& d) const;
  /// Distance (cells) from q to the nearest domain edge; negative outside.
  double distanceToBoundary(const Vec2& q) const;

 private:
  void buildGradientTable();

  Grid grid_;
  int slice_ = 0;
  int nx_ = 0, ny_ = 0;
  std::vector<double> u_, v_;  // index-space components, x fastest
  WindowRms jacobian_rms_;  // of |J_world|_F
};

}  // namespace fluidviz::topology
