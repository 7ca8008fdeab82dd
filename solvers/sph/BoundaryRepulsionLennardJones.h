#pragma once
// Boundary force of Monaghan (1994): a boundary particle at distance r < r0 pushes a fluid
// particle away with the Lennard-Jones-like acceleration
//   a = D [ (r0/r)^n1 - (r0/r)^n2 ] x_ij / r^2,   zero for r >= r0,
// n1 = 12, n2 = 4, D ~ 5 g H (the square of the largest speed), r0 = the initial spacing.
//
// References:
//   J. J. Monaghan, "Simulating free surface flows with SPH", J. Comput. Phys. 110 (1994)
//   399-406, sec. 4 (boundary forces).
#include <cmath>

#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct BoundaryRepulsionLennardJones {
  double D = 0.0;                ///< m^2/s^2, strength
  double r0 = 0.0;               ///< m, cut-off distance (particle spacing)
  double n1 = 12.0, n2 = 4.0;    ///< exponents, n1 > n2

  /// Acceleration of fluid particle i from boundary particle j, x_ij = x_i - x_j.
  Vec3 acceleration(const Vec3& xij, double r2) const {
    if (r2 >= r0 * r0 || r2 <= 0.0) return Vec3::Zero();
    const double s = r0 / std::sqrt(r2);
    return (D * (std::pow(s, n1) - std::pow(s, n2)) / r2) * xij;
  }
};

}  // namespace fluidviz::sph
