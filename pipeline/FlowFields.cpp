#include "pipeline/FlowFields.h"

#include <algorithm>
#include <array>
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

// d(component c)/d(axis a) at node (i, j, k): central inside, one-sided at the border, 0 along
// an axis with one node (a 2D field has no z derivative).
double derivative(const VectorField& v, int c, int a, int i, int j, int k = 0) {
  const Grid& g = v.grid;
  const int n = g.dims[a];
  if (n < 2) return 0.0;
  std::array<int, 3> at{i, j, k};
  const int lo = std::max(at[a] - 1, 0), hi = std::min(at[a] + 1, n - 1);
  const auto value = [&](int m) {
    at[a] = m;
    return v.values[g.index(at[0], at[1], at[2])][c];
  };
  return (value(hi) - value(lo)) / ((hi - lo) * g.spacing[a]);
}

// J(c, a) = d v_c / d x_a at node (i, j, k).
Eigen::Matrix3d velocityGradient(const VectorField& v, int i, int j, int k) {
  Eigen::Matrix3d J;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 3; ++a) J(c, a) = derivative(v, c, a, i, j, k);
  return J;
}

void require3D(const VectorField& v, const char* what) {
  const Grid& g = v.grid;
  if (g.is2D() || g.dims[0] < 2 || g.dims[1] < 2)
    throw std::invalid_argument(std::string(what) + " of '" + v.name + "' needs a 3D field with "
                                "at least 2 x 2 x 2 nodes, got " + g.describe());
}

// Calls f(n, J) for every node n of v with the velocity gradient J there.
template <class F>
void forEachGradient(const VectorField& v, F&& f) {
  const Grid& g = v.grid;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) f(g.index(i, j, k), velocityGradient(v, i, j, k));
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

VectorField vorticityVector(const VectorField& velocity, const std::string& name) {
  require3D(velocity, "the vorticity vector");
  VectorField w{name, velocity.grid, std::vector<Vec3>(velocity.grid.nodeCount())};
  forEachGradient(velocity, [&](std::size_t n, const Eigen::Matrix3d& J) {
    w.values[n] = Vec3(J(2, 1) - J(1, 2), J(0, 2) - J(2, 0), J(1, 0) - J(0, 1));
  });
  return w;
}

ScalarField qCriterion(const VectorField& velocity, const std::string& name) {
  require3D(velocity, "the Q-criterion");
  ScalarField q{name, velocity.grid, std::vector<double>(velocity.grid.nodeCount())};
  forEachGradient(velocity, [&](std::size_t n, const Eigen::Matrix3d& J) {
    // |Omega|^2 - |S|^2 = -sum_ab J_ab J_ba with S, Omega the symmetric and antisymmetric parts.
    q.values[n] = -0.5 * J.cwiseProduct(J.transpose()).sum();
  });
  return q;
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
