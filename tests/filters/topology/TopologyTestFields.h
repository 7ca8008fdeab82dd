#pragma once
// Analytic planar fields sampled on grids, for the topology tests (tests/support/AnalyticFields.h
// holds the grid and sampling they share with the streamline tests).
#include <cmath>
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

/// Weak spiral sink off-node (issue 15, defect 5), on squareGrid(41, -20, 20) (unit cells):
/// v = J (x - x0) + (0.3 phi(x), 0), J = [[-0.02, -1], [1, -0.02]], x0 = (2.8, -2.65) in cell
/// (22, 17), phi(x) = (x - 2)(x - 3)(x - x0)^2 exp(-((x - x0) / 1.5)^2). phi vanishes with its
/// slope at x0 and on the columns x = 2, 3 of x0's cell, so there the interpolant is exactly
/// J (x - x0); central differences (step one cell) see phi at x = 1 and 4 and add
/// 0.3 * 0.454 to du/dx: trace +0.096 instead of -0.04.
struct WeakSpiralSink {
  static Mat2 jacobian() {
    Mat2 j;
    j << -0.02, -1.0, 1.0, -0.02;
    return j;
  }
  static Vec2 zero() { return {2.8, -2.65}; }
  static double phi(double x) {
    const double d = x - zero().x();
    return (x - 2) * (x - 3) * d * d * std::exp(-(d / 1.5) * (d / 1.5));
  }
  static Vec2 field(double x, double y) {
    return jacobian() * (Vec2(x, y) - zero()) + Vec2(0.3 * phi(x), 0.0);
  }
  static Grid grid() { return squareGrid(41, -20.0, 20.0); }
};

}  // namespace fluidviz::topology::testing
