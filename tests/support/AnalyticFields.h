#pragma once
// Vector fields with known streamlines, sampled on regular grids, shared by the streamline, LIC
// and topology tests and the flow benches (one definition, so that a bench measures the field a
// test validates). Linear fields (rotation, saddle, uniform) are reproduced EXACTLY by bilinear
// interpolation, so integration errors are the integrator's alone.
#include <cmath>
#include <functional>
#include <numbers>
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

/// n^3 nodes on the cube [lo, hi]^3.
inline Grid cubeGrid(int n, double lo, double hi) {
  Grid g;
  g.dims = {n, n, n};
  g.origin = {lo, lo, lo};
  const double h = (hi - lo) / (n - 1);
  g.spacing = {h, h, h};
  return g;
}

/// The Arnold-Beltrami-Childress flow (Dombre et al. 1986, J. Fluid Mech. 167) on [0, 2 pi]^3:
/// v = (A sin z + C cos y, B sin x + A cos z, C sin y + B cos x), chaotic for A = sqrt 3,
/// B = sqrt 2, C = 1, with no zero of |v| on the lattice to stop lines.
inline VectorField abcFlow(int nodes, double A = std::sqrt(3.0), double B = std::sqrt(2.0),
                           double C = 1.0) {
  return sampleField(cubeGrid(nodes, 0.0, 2.0 * std::numbers::pi), [=](const Vec3& p) {
    return Vec3(A * std::sin(p.z()) + C * std::cos(p.y()), B * std::sin(p.x()) + A * std::cos(p.z()),
                C * std::sin(p.y()) + B * std::cos(p.x()));
  });
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

/// Four Lamb-Oseen vortices of alternating sign (circulation +-1, Gaussian core radius `core`)
/// in a weak uniform stream (0.3, 0.1) on [0, 1]^2, `nodes` x `nodes` nodes: curved lines, speed
/// varying by 10x, closed orbits, saddles between the vortices and lines that leave the domain,
/// like a mixing flow. Lamb (1932), Hydrodynamics, art. 334a: v_theta = Gamma / (2 pi r) (1 -
/// exp(-r^2 / core^2)).
inline VectorField fourLambOseenVortices(int nodes, double core) {
  return sampleField(squareGrid(nodes, 0.0, 1.0), [core](const Vec3& p) {
    const double cx[4] = {0.25, 0.75, 0.25, 0.75}, cy[4] = {0.25, 0.25, 0.75, 0.75};
    const double gamma[4] = {1.0, -1.0, -1.0, 1.0};
    Vec3 u(0.3, 0.1, 0.0);
    for (int k = 0; k < 4; ++k) {
      const double dx = p.x() - cx[k], dy = p.y() - cy[k], r2 = dx * dx + dy * dy + 1e-12;
      const double s = gamma[k] / (2 * M_PI * r2) * (1 - std::exp(-r2 / (core * core)));
      u += Vec3(-dy * s, dx * s, 0.0);
    }
    return u;
  });
}

}  // namespace fluidviz::testing
