#include "fieldviz/core/FieldSlices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "fieldviz/core/Sampling.h"

namespace fluidviz {

namespace {

const char* kAxisNames = "xyz";

std::string axisName(int axis) { return std::string(1, kAxisNames[axis]); }

Vec3 remap(const Vec3& v, int axis) {
  const auto [a, b] = inPlaneAxes(axis);
  return {v[a], v[b], v[axis]};
}
double remap(double v, int) { return v; }

template <class Field>
Field layer(const Field& f, int axis, int index) {
  const Grid& g = f.grid;
  if (axis < 0 || axis > 2) throw std::invalid_argument("slice axis must be 0, 1 or 2");
  if (index < 0 || index >= g.dims[axis])
    throw std::invalid_argument(axisName(axis) + " layer " + std::to_string(index) +
                                " of field '" + f.name + "' is outside [0, " +
                                std::to_string(g.dims[axis] - 1) + "]");
  const auto [a, b] = inPlaneAxes(axis);
  Field out{f.name, {}, {}};
  out.grid.dims = {g.dims[a], g.dims[b], 1};
  out.grid.origin = {g.origin[a], g.origin[b], g.origin[axis] + index * g.spacing[axis]};
  out.grid.spacing = {g.spacing[a], g.spacing[b], g.spacing[axis]};
  out.values.reserve(out.grid.nodeCount());
  std::array<int, 3> n{};
  n[axis] = index;
  for (n[b] = 0; n[b] < g.dims[b]; ++n[b])
    for (n[a] = 0; n[a] < g.dims[a]; ++n[a])
      out.values.push_back(remap(f.values[g.index(n[0], n[1], n[2])], axis));
  return out;
}

template <class Field>
Field layerAt(const Field& f, int axis, double coordinate) {
  const Grid& g = f.grid;
  const double lo = g.origin[axis], hi = lo + (g.dims[axis] - 1) * g.spacing[axis];
  const double q = (coordinate - lo) / g.spacing[axis];
  constexpr double kOnLayer = 1e-9;  // cells: a coordinate this close to a layer is that layer
  if (!(q >= -kOnLayer && q <= g.dims[axis] - 1 + kOnLayer))
    throw std::invalid_argument(axisName(axis) + " = " + std::to_string(coordinate) +
                                " is outside the grid's extent [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "] along " + axisName(axis));
  const int k = std::clamp(static_cast<int>(std::floor(q + kOnLayer)), 0, g.dims[axis] - 1);
  const double w = q - k;
  Field out = layer(f, axis, k);
  out.grid.origin[2] = coordinate;
  if (std::abs(w) <= kOnLayer || k + 1 >= g.dims[axis]) return out;
  const Field next = layer(f, axis, k + 1);
  for (std::size_t n = 0; n < out.values.size(); ++n)
    out.values[n] = (1 - w) * out.values[n] + w * next.values[n];
  return out;
}

// The lattice of `plane` over the grid's projection: origin (s0, t0) and node counts.
struct Lattice {
  double s0 = 0, t0 = 0, h = 1;
  int ns = 0, nt = 0;
  Vec3 node(const SlicePlane& p, int i, int j) const {
    return p.origin + (s0 + i * h) * p.e1 + (t0 + j * h) * p.e2;
  }
};

Lattice latticeOf(const Grid& g, const SlicePlane& p) {
  double smin = std::numeric_limits<double>::infinity(), smax = -smin, tmin = smin, tmax = -smin;
  double dmin = smin, dmax = -smin;
  const Vec3 lo = g.position(0, 0, 0), hi = g.upperCorner();
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner{c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z()};
    const Vec3 d = corner - p.origin;
    smin = std::min(smin, d.dot(p.e1)), smax = std::max(smax, d.dot(p.e1));
    tmin = std::min(tmin, d.dot(p.e2)), tmax = std::max(tmax, d.dot(p.e2));
    dmin = std::min(dmin, d.dot(p.normal)), dmax = std::max(dmax, d.dot(p.normal));
  }
  if (dmin > 0 || dmax < 0)
    throw std::invalid_argument("the plane misses the grid " + g.describe());
  Lattice l;
  l.h = *std::min_element(g.spacing.begin(), g.spacing.end());
  // Nodes on multiples of h from the plane's origin, so that the origin is a lattice node.
  l.s0 = std::floor(smin / l.h) * l.h, l.t0 = std::floor(tmin / l.h) * l.h;
  const double ns = std::ceil((smax - l.s0) / l.h) + 1, nt = std::ceil((tmax - l.t0) / l.h) + 1;
  if (ns * nt > static_cast<double>(kMaxPlaneNodes))
    throw std::invalid_argument("the plane's lattice would have " + std::to_string(ns * nt) +
                                " nodes, more than " + std::to_string(kMaxPlaneNodes));
  l.ns = static_cast<int>(ns), l.nt = static_cast<int>(nt);
  return l;
}

Grid latticeGrid(const Lattice& l) {
  Grid g;
  g.dims = {l.ns, l.nt, 1};
  g.origin = {l.s0, l.t0, 0.0};
  g.spacing = {l.h, l.h, l.h};
  return g;
}

}  // namespace

std::array<int, 2> inPlaneAxes(int axis) {
  return axis == 0 ? std::array<int, 2>{1, 2}
                   : axis == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1};
}

VectorField sliceAxis(const VectorField& f, int axis, int index) { return layer(f, axis, index); }
ScalarField sliceAxis(const ScalarField& f, int axis, int index) { return layer(f, axis, index); }
VectorField sliceAt(const VectorField& f, int axis, double c) { return layerAt(f, axis, c); }
ScalarField sliceAt(const ScalarField& f, int axis, double c) { return layerAt(f, axis, c); }

SlicePlane slicePlane(const Vec3& origin, const Vec3& normal) {
  if (!(normal.norm() > 0.0)) throw std::invalid_argument("the plane's normal is zero");
  SlicePlane p;
  p.origin = origin;
  p.normal = normal.normalized();
  int least = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(p.normal[a]) < std::abs(p.normal[least])) least = a;
  const Vec3 axis = Vec3::Unit(least);
  p.e1 = (axis - axis.dot(p.normal) * p.normal).normalized();
  p.e2 = p.normal.cross(p.e1);
  return p;
}

PlaneSlice sliceOnPlane(const VectorField& f, const SlicePlane& plane) {
  const Lattice l = latticeOf(f.grid, plane);
  PlaneSlice out;
  out.velocity = {f.name, latticeGrid(l), {}};
  out.velocity.values.reserve(out.velocity.grid.nodeCount());
  out.outside.reserve(out.velocity.grid.nodeCount());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int j = 0; j < l.nt; ++j)
    for (int i = 0; i < l.ns; ++i) {
      const std::optional<Vec3> v = sample(f, l.node(plane, i, j));
      out.outside.push_back(!v);
      out.velocity.values.push_back(
          v ? Vec3(v->dot(plane.e1), v->dot(plane.e2), v->dot(plane.normal)) : Vec3(nan, nan, nan));
    }
  return out;
}

ScalarField sliceOnPlane(const ScalarField& f, const SlicePlane& plane) {
  const Lattice l = latticeOf(f.grid, plane);
  ScalarField out{f.name, latticeGrid(l), {}};
  out.values.reserve(out.grid.nodeCount());
  for (int j = 0; j < l.nt; ++j)
    for (int i = 0; i < l.ns; ++i)
      out.values.push_back(
          sample(f, l.node(plane, i, j)).value_or(std::numeric_limits<double>::quiet_NaN()));
  return out;
}

NodeBox cropBox(const Grid& g, const std::array<double, 4>& box) {
  NodeBox b;
  constexpr double kOnNode = 1e-9;  // cells
  for (int a = 0; a < 2; ++a) {
    const double lo = g.origin[a], hi = lo + (g.dims[a] - 1) * g.spacing[a];
    const double x0 = box[2 * a], x1 = box[2 * a + 1];
    const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!(x0 < x1))
      throw std::invalid_argument(axisName(a) + " range " + std::to_string(x0) + ", " +
                                  std::to_string(x1) + " is empty (needs " + axisName(a) +
                                  "0 < " + axisName(a) + "1)");
    const double q0 = (x0 - lo) / g.spacing[a], q1 = (x1 - lo) / g.spacing[a];
    if (q0 < -kOnNode || q1 > g.dims[a] - 1 + kOnNode)
      throw std::invalid_argument(axisName(a) + " range [" + std::to_string(x0) + ", " +
                                  std::to_string(x1) + "] reaches outside the grid's " + range);
    b.lo[a] = static_cast<int>(std::ceil(q0 - kOnNode));
    b.hi[a] = std::min(static_cast<int>(std::floor(q1 + kOnNode)), g.dims[a] - 1);
    if (b.hi[a] - b.lo[a] < 1)
      throw std::invalid_argument(axisName(a) + " range [" + std::to_string(x0) + ", " +
                                  std::to_string(x1) + "] holds fewer than 2 nodes (spacing " +
                                  std::to_string(g.spacing[a]) + ")");
  }
  return b;
}

namespace {

template <class T>
std::vector<T> cropValues(const std::vector<T>& values, const Grid& g, const NodeBox& b) {
  std::vector<T> out;
  out.reserve(static_cast<std::size_t>(b.hi[0] - b.lo[0] + 1) * (b.hi[1] - b.lo[1] + 1));
  for (int j = b.lo[1]; j <= b.hi[1]; ++j)
    for (int i = b.lo[0]; i <= b.hi[0]; ++i) out.push_back(values[g.index(i, j)]);
  return out;
}

Grid croppedGrid(const Grid& g, const NodeBox& b) {
  Grid out = g;
  for (int a = 0; a < 2; ++a) {
    out.dims[a] = b.hi[a] - b.lo[a] + 1;
    out.origin[a] = g.origin[a] + b.lo[a] * g.spacing[a];
  }
  return out;
}

}  // namespace

VectorField crop(const VectorField& f, const NodeBox& b) {
  return {f.name, croppedGrid(f.grid, b), cropValues(f.values, f.grid, b)};
}
ScalarField crop(const ScalarField& f, const NodeBox& b) {
  return {f.name, croppedGrid(f.grid, b), cropValues(f.values, f.grid, b)};
}
std::vector<std::uint8_t> crop(const std::vector<std::uint8_t>& nodes, const Grid& g,
                               const NodeBox& b) {
  return nodes.empty() ? nodes : cropValues(nodes, g, b);
}

}  // namespace fluidviz
