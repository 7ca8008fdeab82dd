#pragma once
// Viscosity force of Mueller, Charypar & Gross (2003), model A:
//   f_i = mu sum_j m_j (v_j - v_i) / rho_j lap W_visc(r_ij)       (eq. 14, force density)
// Against boundary particles v_j is the wall velocity and rho_j = rho0.
//
// References:
//   M. Mueller, D. Charypar, M. Gross, Proc. SCA 2003, 154-159, sec. 4.2.
#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct ViscosityMuller2003 {
  /// Force density on i from j (N/m^3); mu in Pa s, vji = v_j - v_i.
  static Vec3 force(double mu, double mj, double rhoj, const Vec3& vji, double lapViscosity) {
    return (mu * mj / rhoj * lapViscosity) * vji;
  }
};

}  // namespace fluidviz::sph
