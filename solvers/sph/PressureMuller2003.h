#pragma once
// Pressure of Mueller, Charypar & Gross (2003), model A:
//   p_i = k (rho_i - rho0)                                       (eq. 12, k = c0^2)
//   f_i = - sum_j m_j (p_i + p_j) / (2 rho_j) grad W_spiky(x_ij)  (eq. 10, force density)
// The symmetric average of eq. 10 makes the pair forces equal and opposite. p may be negative
// (rho < rho0 at free surfaces), which gives these fluids a weak cohesion.
//
// References:
//   M. Mueller, D. Charypar, M. Gross, "Particle-based fluid simulation for interactive
//   applications", Proc. SCA 2003, 154-159, sec. 4.1.
#include <algorithm>

#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct PressureMuller2003 {
  double k = 0.0;     ///< m^2/s^2, gas stiffness (= c0^2)
  double rho0 = 0.0;  ///< kg/m^3, rest density

  double pressure(double rho) const { return std::max(0.0, k * (rho - rho0)); }
  /// Force density on i from j (N/m^3); gradSpiky = grad_i W_spiky(x_i - x_j).
  static Vec3 force(double mj, double pi, double pj, double rhoj, const Vec3& gradSpiky) {
    return (-mj * (pi + pj) / (2.0 * rhoj)) * gradSpiky;
  }
};

}  // namespace fluidviz::sph
