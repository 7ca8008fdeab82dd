#include "fieldviz/core/Sampling.h"

#include <algorithm>
#include <cmath>

namespace fluidviz {

namespace {
// Cell base index and fractional offset along one axis; a point on the last node uses the last
// cell with offset 1 so that the upper boundary is inside.
struct AxisCell {
  int base;
  double t;
};

std::optional<AxisCell> locate(double q, int n) {
  const double eps = 1e-9;
  if (n == 1) {
    if (std::abs(q) > eps) return std::nullopt;
    return AxisCell{0, 0.0};
  }
  if (q < -eps || q > n - 1 + eps) return std::nullopt;
  q = std::clamp(q, 0.0, double(n - 1));
  int b = std::min(static_cast<int>(std::floor(q)), n - 2);
  return AxisCell{b, q - b};
}

// Bilinear interpolation on a 2D grid with at least two nodes per axis: the hot path of the
// streamline integrator, so it avoids the general 3D loop.
template <class T, class Values>
std::optional<T> interpolatePlanar(const Grid& g, const Values& values, const Vec3& q) {
  const auto cx = locate(q[0], g.dims[0]);
  const auto cy = locate(q[1], g.dims[1]);
  if (!cx || !cy || std::abs(q[2]) > 1e-9) return std::nullopt;
  const std::size_t n = static_cast<std::size_t>(cy->base) * g.dims[0] + cx->base;
  const double tx = cx->t, ty = cy->t;
  return (1.0 - ty) * ((1.0 - tx) * values[n] + tx * values[n + 1]) +
         ty * ((1.0 - tx) * values[n + g.dims[0]] + tx * values[n + g.dims[0] + 1]);
}

template <class T, class Values>
std::optional<T> interpolate(const Grid& g, const Values& values, const Vec3& q) {
  if (g.dims[2] == 1 && g.dims[0] > 1 && g.dims[1] > 1)
    return interpolatePlanar<T>(g, values, q);
  std::optional<AxisCell> c[3];
  for (int a = 0; a < 3; ++a) {
    c[a] = locate(q[a], g.dims[a]);
    if (!c[a]) return std::nullopt;
  }
  const int di = g.dims[0] > 1 ? 1 : 0, dj = g.dims[1] > 1 ? 1 : 0, dk = g.dims[2] > 1 ? 1 : 0;
  T acc = values[0] * 0.0;
  for (int k = 0; k <= dk; ++k)
    for (int j = 0; j <= dj; ++j)
      for (int i = 0; i <= di; ++i) {
        const double w = (i ? c[0]->t : 1.0 - c[0]->t) * (j ? c[1]->t : 1.0 - c[1]->t) *
                         (k ? c[2]->t : 1.0 - c[2]->t);
        if (w != 0.0) acc += w * values[g.index(c[0]->base + i, c[1]->base + j, c[2]->base + k)];
      }
  return acc;
}
}  // namespace

std::optional<double> sampleIndexSpace(const ScalarField& f, const Vec3& q) {
  return interpolate<double>(f.grid, f.values, q);
}
std::optional<Vec3> sampleIndexSpace(const VectorField& f, const Vec3& q) {
  return interpolate<Vec3>(f.grid, f.values, q);
}
std::optional<double> sample(const ScalarField& f, const Vec3& p) {
  return sampleIndexSpace(f, f.grid.toIndexSpace(p));
}
std::optional<Vec3> sample(const VectorField& f, const Vec3& p) {
  return sampleIndexSpace(f, f.grid.toIndexSpace(p));
}

}  // namespace fluidviz
