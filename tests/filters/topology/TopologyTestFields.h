#pragma once
// Analytic planar fields sampled on grids, for the topology tests (tests/support/AnalyticFields.h
// holds the grid and sampling they share with the streamline tests).
#include <functional>

#include "fieldviz/core/Field.h"
#include "filters/topology/CriticalPoint.h"
#include "tests/support/AnalyticFields.h"

namespace fluidviz::topology::testing {

using PlanarFunction = std::function<Vec2(double x, double y)>;

using fluidviz::testing::squareGrid;

/// The planar function f sampled at the grid's nodes (array name "v").
inline VectorField sampleField(const Grid& g, const PlanarFunction& f) {
  return fluidviz::testing::sampleField(
      g, [&f](const Vec3& p) { const Vec2 w = f(p.x(), p.y()); return Vec3(w.x(), w.y(), 0.0); }, "v");
}

/// Linear field v = A (x - x0).
inline PlanarFunction linearField(const Mat2& a, const Vec2& x0) {
  return [=](double x, double y) { return Vec2(a * (Vec2(x, y) - x0)); };
}

}  // namespace fluidviz::topology::testing
