#include "pipeline/FlowFields.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fluidviz {

namespace {

template <class Field>
Field sliceLayer(const Field& f, int k) {
  const int nz = f.grid.dims[2];
  if (k < 0 || k >= nz)
    throw std::invalid_argument("z layer " + std::to_string(k) + " of field '" + f.name +
                                "' is outside [0, " + std::to_string(nz - 1) + "]");
  Field out{f.name, f.grid, {}};
  out.grid.dims[2] = 1;
  out.grid.origin[2] = f.grid.origin[2] + k * f.grid.spacing[2];
  const std::size_t layer = static_cast<std::size_t>(f.grid.dims[0]) * f.grid.dims[1];
  out.values.assign(f.values.begin() + static_cast<std::ptrdiff_t>(k * layer),
                    f.values.begin() + static_cast<std::ptrdiff_t>((k + 1) * layer));
  return out;
}

// d(component c)/d(axis a) at node (i, j): central inside, one-sided at the border.
double derivative(const VectorField& v, int c, int a, int i, int j) {
  const Grid& g = v.grid;
  const int n = g.dims[a], at = a == 0 ? i : j;
  const int lo = std::max(at - 1, 0), hi = std::min(at + 1, n - 1);
  const auto value = [&](int m) {
    return a == 0 ? v.values[g.index(m, j)][c] : v.values[g.index(i, m)][c];
  };
  return (value(hi) - value(lo)) / ((hi - lo) * g.spacing[a]);
}

}  // namespace

VectorField sliceZ(const VectorField& field, int k) { return sliceLayer(field, k); }
ScalarField sliceZ(const ScalarField& field, int k) { return sliceLayer(field, k); }

VectorField inPlaneVelocity(const VectorField& velocity) {
  VectorField v = velocity;
  for (Vec3& x : v.values) x.z() = 0.0;
  return v;
}

ScalarField vorticity(const VectorField& velocity, const std::string& name) {
  const Grid& g = velocity.grid;
  if (!g.is2D() || g.dims[0] < 2 || g.dims[1] < 2)
    throw std::invalid_argument("vorticity of '" + velocity.name + "' needs a 2D field with at "
                                "least 2 x 2 nodes, got " + g.describe());
  ScalarField w{name, g, std::vector<double>(g.nodeCount())};
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i)
      w.values[g.index(i, j)] = derivative(velocity, 1, 0, i, j) - derivative(velocity, 0, 1, i, j);
  return w;
}

std::optional<ScalarField> derivedScalar(const VectorField& velocity, const std::string& name) {
  if (name == "speed") return magnitude(velocity, "speed");
  if (name == "vorticity") return vorticity(velocity);
  return std::nullopt;
}

void useSymmetricRange(const ScalarField& field, FieldImageParams& picture) {
  if (picture.range_min || picture.range_max) return;
  double m = 0.0;
  for (double v : field.values)
    if (std::isfinite(v)) m = std::max(m, std::abs(v));
  if (m == 0.0) m = 1.0;
  picture.range_min = -m;
  picture.range_max = m;
}

}  // namespace fluidviz
