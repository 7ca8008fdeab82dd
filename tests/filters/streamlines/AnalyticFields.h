#pragma once
// Vector fields with known streamlines, sampled on regular grids, shared by the streamline and
// LIC tests. Linear fields (rotation, saddle, uniform) are reproduced EXACTLY by bilinear
// interpolation, so integration errors are the integrator's alone.
#include <cmath>
#include <functional>
#include <limits>

#include "fieldviz/core/Field.h"

namespace fluidviz::testing {

inline VectorField sampleField(const Grid& g, const std::function<Vec3(const Vec3&)>& f,
                               const std::string& name = "velocity") {
  VectorField v{name, g, {}};
  v.values.reserve(g.nodeCount());
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) v.values.push_back(f(g.position(i, j, k)));
  return v;
}

/// n x n nodes covering [lo, hi]^2 (2D).
inline Grid squareGrid(int n, double lo, double hi) {
  Grid g;
  g.dims = {n, n, 1};
  g.origin = {lo, lo, 0.0};
  g.spacing = {(hi - lo) / (n - 1), (hi - lo) / (n - 1), 1.0};
  return g;
}

/// Rigid rotation v = (-y, x): circles about the origin, period 2 pi.
inline VectorField rotationField(const Grid& g) {
  return sampleField(g, [](const Vec3& p) { return Vec3(-p.y(), p.x(), 0.0); });
}
/// Saddle v = (x, -y): hyperbolae x y = const.
inline VectorField saddleField(const Grid& g) {
  return sampleField(g, [](const Vec3& p) { return Vec3(p.x(), -p.y(), 0.0); });
}
inline VectorField uniformField(const Grid& g, const Vec3& v) {
  return sampleField(g, [v](const Vec3&) { return v; });
}

}  // namespace fluidviz::testing
