#pragma once
// Analytic planar fields sampled on grids, for the topology tests.
#include <functional>

#include "fieldviz/core/Field.h"
#include "filters/topology/CriticalPoint.h"

namespace fluidviz::topology::testing {

using PlanarFunction = std::function<Vec2(double x, double y)>;

/// n x n nodes covering [lo, hi]^2 (2D grid).
inline Grid squareGrid(int n, double lo, double hi) {
  Grid g;
  g.dims = {n, n, 1};
  g.origin = {lo, lo, 0.0};
  g.spacing = {(hi - lo) / (n - 1), (hi - lo) / (n - 1), 1.0};
  return g;
}

inline VectorField sampleField(const Grid& g, const PlanarFunction& f) {
  VectorField v{"v", g, {}};
  v.values.reserve(g.nodeCount());
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const Vec3 p = g.position(i, j, k);
        const Vec2 w = f(p.x(), p.y());
        v.values.emplace_back(w.x(), w.y(), 0.0);
      }
  return v;
}

/// Linear field v = A (x - x0).
inline PlanarFunction linearField(const Mat2& a, const Vec2& x0) {
  return [=](double x, double y) { return Vec2(a * (Vec2(x, y) - x0)); };
}

}  // namespace fluidviz::topology::testing
