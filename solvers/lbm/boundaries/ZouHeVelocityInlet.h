#pragma once
// Velocity boundary of Zou & He 1997 ("On pressure and velocity boundary conditions for the
// lattice Boltzmann BGK model", Phys. Fluids 9:1591, sec. III): on a flat side of the box the
// populations coming from outside (c_q . n > 0, n the inward normal) are unknown after streaming.
// Zou & He close them by bouncing back their non-equilibrium part,
//   f_q - f_q^eq = f_opp(q) - f_opp(q)^eq   =>   f_q = f_opp(q) + 2 w_q rho (c_q . u) / cs2,
// and fix the density from the known populations (for the D2Q9 inlet x = 0:
// rho = (f_0 + f_2 + f_4 + 2 (f_3 + f_6 + f_7)) / (1 - u_x)); for any side:
//   rho (1 - u . n) = sum_{c.n = 0} f + 2 sum_{c.n < 0} f.
// The momentum along the side is then corrected by spreading the missing part over the unknown
// populations that move along it (Zou & He's terms -+(f_2 - f_4)/2 in D2Q9; for D3Q19 the
// transverse momentum corrections N_t of Hecht & Harting 2010, J. Stat. Mech. P01018, sec. 3). The
// closure below is written once for any lattice and any side; for the D2Q9 inlet x = 0 it
// reproduces Zou & He's f_1 = f_3 + 2/3 rho u_x,
// f_5 = f_7 - (f_2 - f_4)/2 + rho u_x / 6 + rho u_y / 2, f_8 = f_6 + (f_2 - f_4)/2 + rho u_x / 6 -
// rho u_y / 2 exactly (tests/solvers/lbm/ZouHe_test.cpp).
//
// With a body force the velocity of a node is (sum f c + F/2) / rho (Guo et al. 2002), so the
// populations are closed for the momentum rho (u - g/2). Populations are shifted, g_q = f_q - w_q
// (Equilibrium.h); in these sum_{c.n=0} f + 2 sum_{c.n<0} f = 1 + sum_{c.n=0} g + 2 sum_{c.n<0} g.
#include "solvers/lbm/kernel/KernelInline.h"

namespace fluidviz::lbm {

/// A flat open side in lattice units: inward normal n = sign e_axis.
struct OpenSideGeometry {
  int axis = 0;  ///< 0, 1, 2 for x, y, z
  int sign = 1;  ///< +1 on the min side (normal points into the box), -1 on the max side
};

/// c_q . n for the side.
template <class L>
FLUIDVIZ_LBM_INLINE int normalComponent(int q, const OpenSideGeometry& s) {
  const int c = s.axis == 0 ? L::cx[q] : (s.axis == 1 ? L::cy[q] : L::cz[q]);
  return c * s.sign;
}

/// sum_{c.n = 0} g + 2 sum_{c.n < 0} g of the known shifted populations.
template <class L, class T>
FLUIDVIZ_LBM_INLINE T knownDensitySum(const T* g, const OpenSideGeometry& s) {
  T sum = 0;
  for (int q = 0; q < L::Q; ++q) {
    const int cn = normalComponent<L>(q, s);
    if (cn == 0) sum += g[q];
    if (cn < 0) sum += T(2) * g[q];
  }
  return sum;
}

/// Sets the unknown populations (c.n > 0) so that the node has density 1 + drho and momentum
/// (jx, jy, jz) (lattice units, j = rho (u - g/2)).
template <class L, class T>
FLUIDVIZ_LBM_INLINE void zouHeClosure(T* g, const OpenSideGeometry& s, T jx, T jy, T jz) {
  const T j[3] = {jx, jy, jz};
  // Non-equilibrium bounce-back of the unknowns.
  for (int q = 0; q < L::Q; ++q)
    if (normalComponent<L>(q, s) > 0)
      g[q] = g[L::opposite[q]] +
             T(6.0 * L::w[q]) * (T(L::cx[q]) * jx + T(L::cy[q]) * jy + T(L::cz[q]) * jz);
  // Transverse momentum: add c_t N_t to every unknown moving along t so that sum g c_t = j_t.
  for (int t = 0; t < L::D; ++t) {
    if (t == s.axis) continue;
    T current = 0;
    int movers = 0;
    for (int q = 0; q < L::Q; ++q) {
      const int ct = t == 0 ? L::cx[q] : (t == 1 ? L::cy[q] : L::cz[q]);
      current += T(ct) * g[q];
      if (ct != 0 && normalComponent<L>(q, s) > 0) ++movers;
    }
    const T perMover = (j[t] - current) / T(movers);
    for (int q = 0; q < L::Q; ++q) {
      const int ct = t == 0 ? L::cx[q] : (t == 1 ? L::cy[q] : L::cz[q]);
      if (ct != 0 && normalComponent<L>(q, s) > 0) g[q] += T(ct) * perMover;
    }
  }
}

/// Zou-He velocity inlet: the node gets velocity u (lattice units) and the density that the
/// known populations imply. gx, gy, gz: lattice body acceleration (0 without force).
template <class L, class T>
FLUIDVIZ_LBM_INLINE void zouHeVelocity(T* g, const OpenSideGeometry& s, T ux, T uy, T uz, T gx,
                                       T gy, T gz) {
  const T vx = ux - T(0.5) * gx, vy = uy - T(0.5) * gy, vz = uz - T(0.5) * gz;
  const T vn = T(s.sign) * (s.axis == 0 ? vx : (s.axis == 1 ? vy : vz));
  // rho (1 - v.n) = 1 + K  =>  rho = (1 + K) / (1 - v.n)
  const T rho = (T(1) + knownDensitySum<L, T>(g, s)) / (T(1) - vn);
  zouHeClosure<L, T>(g, s, rho * vx, rho * vy, rho * vz);
}

}  // namespace fluidviz::lbm
