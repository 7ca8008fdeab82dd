#pragma once
// Pressure of wall (boundary) particles extrapolated from the fluid, so that the pressure
// gradient near a wall sees a complete kernel support and holds a hydrostatic column:
//   p_w = ( sum_f p_f W_wf + (g - a_w) . sum_f rho_f (x_w - x_f) W_wf ) / sum_f W_wf,
//   rho_w from the equation of state (Tait inverted),
// where a_w is the wall's acceleration (centripetal for a roller). The wall particle then enters
// the fluid's pressure gradient (PressureMonaghan1992) and continuity equation with p_w, rho_w
// and the wall velocity. Clamped at p_w >= 0 so that walls never pull fluid (free surfaces).
// Complements the Lennard-Jones repulsion (Monaghan 1994), which alone leaves the near-wall
// kernel support empty and the pressure of the bottom layers far from hydrostatic.
//
// References:
//   S. Adami, X. Y. Hu, N. A. Adams, "A generalized wall boundary condition for smoothed
//   particle hydrodynamics", J. Comput. Phys. 231 (2012) 7057-7075, sec. 2.
#include <algorithm>

#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct WallPressureAdami2012 {
  double sumW = 0.0;                 ///< sum_f W_wf
  double sumPW = 0.0;                ///< sum_f p_f W_wf
  Vec3 sumRhoRW = Vec3::Zero();      ///< sum_f rho_f (x_w - x_f) W_wf

  void add(double W, double pf, double rhof, const Vec3& xwf) {
    sumW += W;
    sumPW += pf * W;
    sumRhoRW += (rhof * W) * xwf;
  }
  /// p_w (Pa) given g - a_w (m/s^2); 0 when no fluid particle is near.
  double pressure(const Vec3& gMinusAw) const {
    return sumW > 0.0 ? std::max(0.0, (sumPW + gMinusAw.dot(sumRhoRW)) / sumW) : 0.0;
  }
};

}  // namespace fluidviz::sph
