#pragma once
// Analytic velocity fields shared by tests and benches (one definition, so that a bench measures
// the field a test validates).
#include <cmath>

#include "fieldviz/core/Field.h"

namespace fluidviz::testing {

/// Four Lamb-Oseen vortices of alternating sign (circulation +-1, Gaussian core radius `core`)
/// in a weak uniform stream (0.3, 0.1) on [0, 1]^2, `nodes` x `nodes` nodes: curved lines, speed
/// varying by 10x, closed orbits, saddles between the vortices and lines that leave the domain,
/// like a mixing flow. Lamb (1932), Hydrodynamics, art. 334a: v_theta = Gamma / (2 pi r) (1 -
/// exp(-r^2 / core^2)).
inline VectorField fourLambOseenVortices(int nodes, double core) {
  VectorField v{"velocity", {}, {}};
  v.grid.dims = {nodes, nodes, 1};
  v.grid.spacing = {1.0 / (nodes - 1), 1.0 / (nodes - 1), 1.0};
  const double cx[4] = {0.25, 0.75, 0.25, 0.75}, cy[4] = {0.25, 0.25, 0.75, 0.75};
  const double gamma[4] = {1.0, -1.0, -1.0, 1.0};
  for (int j = 0; j < nodes; ++j)
    for (int i = 0; i < nodes; ++i) {
      const Vec3 p = v.grid.position(i, j);
      Vec3 u(0.3, 0.1, 0.0);
      for (int k = 0; k < 4; ++k) {
        const double dx = p.x() - cx[k], dy = p.y() - cy[k], r2 = dx * dx + dy * dy + 1e-12;
        const double s = gamma[k] / (2 * M_PI * r2) * (1 - std::exp(-r2 / (core * core)));
        u += Vec3(-dy * s, dx * s, 0.0);
      }
      v.values.push_back(u);
    }
  return v;
}

}  // namespace fluidviz::testing
