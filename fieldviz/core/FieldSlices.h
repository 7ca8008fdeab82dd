#pragma once
// 2D fields cut out of 3D fields: a node layer normal to x, y or z (by index, or at a world
// coordinate between two layers), an arbitrary plane (origin + normal) sampled on a square
// lattice, and a rectangular crop of a 2D field. The 2D field's x and y are the slice's two
// in-plane axes and its vector components are projected onto them (z = the normal component),
// so LIC, streamlines and topology of any slice follow the in-plane velocity.
#include <array>
#include <cstdint>
#include <vector>

#include "fieldviz/core/Field.h"

namespace fluidviz {

/// In-plane axes of a layer normal to `axis`: x -> (y, z), y -> (x, z), z -> (x, y).
std::array<int, 2> inPlaneAxes(int axis);

/// Node layer `index` normal to `axis` (0, 1, 2) as a 2D field: grid axes = inPlaneAxes(axis),
/// origin[2] = the layer's coordinate along `axis`, values (v_a, v_b, v_axis). Throws
/// std::invalid_argument when index is outside [0, n - 1].
VectorField sliceAxis(const VectorField& f, int axis, int index);
ScalarField sliceAxis(const ScalarField& f, int axis, int index);

/// The field at world coordinate `coordinate` along `axis`, linearly interpolated between the two
/// nearest layers (exact for fields linear along the axis; the layer itself when it lies on one).
/// Throws std::invalid_argument when the coordinate is outside the grid's extent along `axis`.
VectorField sliceAt(const VectorField& f, int axis, double coordinate);
ScalarField sliceAt(const ScalarField& f, int axis, double coordinate);

/// A plane through `origin` with unit normal n: e1 = the grid axis least aligned with n, made
/// orthogonal to n; e2 = n x e1. The lattice covers the grid's projection onto the plane with
/// spacing = the grid's smallest spacing; node (i, j) sits at origin + (s0 + i h) e1 + (t0 + j h)
/// e2 and its 2D coordinates are (s0 + i h, t0 + j h).
struct SlicePlane {
  Vec3 origin, normal, e1, e2;
};
/// Throws std::invalid_argument for a zero normal.
SlicePlane slicePlane(const Vec3& origin, const Vec3& normal);

/// Values of `f` on the plane's lattice: trilinear samples, vectors projected onto (e1, e2, n).
/// Nodes outside the grid get NaN and outside[n] = 1. Throws std::invalid_argument when the
/// plane misses the grid or the lattice would exceed kMaxPlaneNodes nodes.
struct PlaneSlice {
  VectorField velocity;
  std::vector<std::uint8_t> outside;  ///< 1 = lattice node outside the 3D grid
};
inline constexpr std::size_t kMaxPlaneNodes = 16'777'216;
PlaneSlice sliceOnPlane(const VectorField& f, const SlicePlane& plane);
/// A scalar on the same lattice as sliceOnPlane(vector field of f's grid, plane).
ScalarField sliceOnPlane(const ScalarField& f, const SlicePlane& plane);

/// Node index range [lo, hi] along x and y of a 2D grid.
struct NodeBox {
  std::array<int, 2> lo{0, 0}, hi{0, 0};
};
/// The nodes inside [x0, x1] x [y0, y1] (world coordinates of the 2D grid). Throws
/// std::invalid_argument naming the allowed ranges when the box is empty (x0 >= x1), reaches
/// outside the grid, or holds fewer than 2 x 2 nodes.
NodeBox cropBox(const Grid& grid, const std::array<double, 4>& box);
VectorField crop(const VectorField& f, const NodeBox& box);
ScalarField crop(const ScalarField& f, const NodeBox& box);
std::vector<std::uint8_t> crop(const std::vector<std::uint8_t>& nodes, const Grid& grid,
                               const NodeBox& box);

}  // namespace fluidviz
