#pragma once
// SPH continuity equation (the density rate of model B):
//   d rho_i / dt = sum_j m_j (v_i - v_j) . grad_i W_ij.
// Unlike summation it needs no particles beyond a free surface, so the density of surface
// particles stays at rho0 and Tait pressure stays >= 0 there.
//
// References:
//   J. J. Monaghan, "Smoothed particle hydrodynamics", Annu. Rev. Astron. Astrophys. 30 (1992)
//   543-574, sec. 2.3 (continuity equation).
#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct DensityContinuity {
  /// Contribution of neighbour j: m_j v_ij . grad_i W_ij (kg/m^3/s).
  static double rate(double mj, const Vec3& vij, const Vec3& gradW) { return mj * vij.dot(gradW); }
};

}  // namespace fluidviz::sph
