#pragma once
// Cohesion ("surface tension" of Becker & Teschner) as a short-range attraction between
// particles of the same fluid:
//   a_i = - (kappa / m_i) sum_j m_j W_ij x_ij,    x_ij = x_i - x_j.
//
// References:
//   M. Becker, M. Teschner, "Weakly compressible SPH for free surface flows", Proc. SCA 2007,
//   209-217, sec. 4 (surface tension).
#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct CohesionBeckerTeschner2007 {
  /// Acceleration of i from j; kappa in m^d/s^2 when m_i = m_j.
  static Vec3 acceleration(double kappa, double mi, double mj, double W, const Vec3& xij) {
    return (-kappa / mi * mj * W) * xij;
  }
};

}  // namespace fluidviz::sph
