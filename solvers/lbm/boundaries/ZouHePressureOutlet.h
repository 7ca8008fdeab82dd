#pragma once
// Pressure (density) boundary of Zou & He 1997 (Phys. Fluids 9:1591, sec. III): the density
// rho_0 is prescribed on a flat side and the velocity along the side is zero;
// the normal velocity follows from the known populations,
//   u . n = 1 - (sum_{c.n = 0} f + 2 sum_{c.n < 0} f) / rho_0,
// and the unknown populations are closed as for the velocity boundary (ZouHeVelocityInlet.h).
// Used for outlets (and for pressure-driven inlets: the rule does not care which way the fluid
// goes). Pressure and lattice density are related by p = cs2 rho (dx/dt)^2 in physical units.
#include "solvers/lbm/boundaries/ZouHeVelocityInlet.h"

namespace fluidviz::lbm {

/// Zou-He pressure side: density 1 + drho (lattice units), tangential velocity 0.
template <class L, class T>
FLUIDVIZ_LBM_INLINE void zouHePressure(T* g, const OpenSideGeometry& s, T drho, T gx, T gy,
                                       T gz) {
  const T rho = T(1) + drho;
  // v.n = 1 - (1 + K) / rho = (drho - K) / rho, with v = u - g/2 the population velocity.
  const T vn = (drho - knownDensitySum<L, T>(g, s)) / rho;
  T v[3] = {-T(0.5) * gx, -T(0.5) * gy, -T(0.5) * gz};  // u_t = 0
  v[s.axis] = T(s.sign) * vn;
  zouHeClosure<L, T>(g, s, rho * v[0], rho * v[1], rho * v[2]);
}

}  // namespace fluidviz::lbm
