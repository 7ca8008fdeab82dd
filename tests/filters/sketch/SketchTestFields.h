#pragma once
// Strokes and grids shared by the sketch tests.
#include <cmath>
#include <numbers>
#include <vector>

#include "filters/sketch/strokes/Stroke.h"

namespace fluidviz::sketch::testing {

/// n x m nodes, spacing 1, origin 0 (lattice units).
inline Grid latticeGrid(int n, int m) {
  Grid g;
  g.dims = {n, m, 1};
  return g;
}

/// A circle of radius r about c, counter-clockwise, `segments` chords, closed.
inline Stroke circleStroke(const Vec3& c, double r, int segments, double speed) {
  Stroke s{.points = {}, .speed = speed};
  for (int k = 0; k <= segments; ++k) {
    const double a = 2.0 * std::numbers::pi * k / segments;
    s.points.push_back(c + r * Vec3(std::cos(a), std::sin(a), 0.0));
  }
  return s;
}

inline Stroke lineStroke(const Vec3& a, const Vec3& b, double speed) {
  return Stroke{.points = {a, b}, .speed = speed};
}

}  // namespace fluidviz::sketch::testing
