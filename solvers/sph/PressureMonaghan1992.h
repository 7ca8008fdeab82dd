#pragma once
// Symmetric SPH pressure gradient (conserves linear and angular momentum):
//   a_i = - sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2) grad_i W_ij.
//
// References:
//   J. J. Monaghan, "Smoothed particle hydrodynamics", Annu. Rev. Astron. Astrophys. 30 (1992)
//   543-574, sec. 2.4 (momentum equation from the Lagrangian).
#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct PressureMonaghan1992 {
  /// pOverRho2i = p_i / rho_i^2 (m^5/(kg s^2)); returns the acceleration from neighbour j.
  static Vec3 acceleration(double mj, double pOverRho2i, double pOverRho2j, const Vec3& gradW) {
    return -mj * (pOverRho2i + pOverRho2j) * gradW;
  }
};

}  // namespace fluidviz::sph
