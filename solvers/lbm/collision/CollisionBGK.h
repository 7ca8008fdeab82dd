#pragma once
// The LBM collision step: BGK single-relaxation-time operator (Bhatnagar, Gross & Krook 1954;
// as a lattice model Qian, d'Humieres & Lallemand 1992):
//   f_q* = f_q - omega (f_q - f_q^eq(rho, u)) + (1 - omega / 2) S_q,   omega = 1 / tau,
// with the optional Guo body-force term S_q (GuoForcing.h). Kinematic viscosity
// nu = cs2 (tau - 1/2) in lattice units. A collision operator is a small value type with a
// `collide` member used by the stream-collide kernel (StreamCollidePull.h); CollisionTRT.h is the
// other one. Both act on SHIFTED populations g_q = f_q - w_q (Equilibrium.h), in the precision T
// of the populations (float or double).
#include "solvers/lbm/collision/GuoForcing.h"
#include "solvers/lbm/kernel/KernelInline.h"
#include "solvers/lbm/lattice/Equilibrium.h"

namespace fluidviz::lbm {

struct CollisionBGK {
  double omega = 1.0;  ///< 1 / tau, in (0, 2)
  double gx = 0.0;     ///< lattice body acceleration g dt^2 / dx (used when Forced)
  double gy = 0.0;
  double gz = 0.0;

  /// Replaces the pre-collision shifted populations g of one node by the post-collision ones.
  /// Same arithmetic as equilibrium() and guoSourceTerm(), split into the parts even and odd in
  /// c_q so that each opposite pair (q, opp(q)) shares them: f^eq_q - w_q = E + A,
  /// f^eq_opp - w_q = E - A with E = w ((rho - 1) + rho (4.5 (c.u)^2 - 1.5 u.u)),
  /// A = 3 w rho (c.u); likewise for S_q.
  template <class L, bool Forced, class T>
  FLUIDVIZ_LBM_INLINE void collide(T* f) const {
    const T gxT = Forced ? T(gx) : T(0), gyT = Forced ? T(gy) : T(0), gzT = Forced ? T(gz) : T(0);
    const NodeMoments<T> m = nodeMoments<L, T>(f, gxT, gyT, gzT);
    const T om = T(omega);
    const T uu = T(1.5) * (m.ux * m.ux + m.uy * m.uy + m.uz * m.uz);
    const T forceX = m.rho * gxT, forceY = m.rho * gyT, forceZ = m.rho * gzT;  // F = rho g
    const T uF = T(3) * (m.ux * forceX + m.uy * forceY + m.uz * forceZ);
    const T forcePrefactor = T(1) - T(0.5) * om;
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) {
      const int o = L::opposite[q];
      if (o < q) continue;  // done with its pair (resolved at compile time after unrolling)
      const T w = T(L::w[q]);
      const T cu = latticeDot<L, T>(q, m.ux, m.uy, m.uz);
      const T even = w * (m.drho + m.rho * (T(4.5) * cu * cu - uu));
      const T odd = T(3) * w * m.rho * cu;
      T forceEven = T(0), forceOdd = T(0);
      if constexpr (Forced) {
        const T cF = latticeDot<L, T>(q, forceX, forceY, forceZ);
        forceEven = forcePrefactor * w * (T(9) * cu * cF - uF);
        forceOdd = forcePrefactor * w * T(3) * cF;
      }
      if (o == q) {
        f[q] += om * (even - f[q]) + forceEven;
      } else {
        const T fq = f[q], fo = f[o];
        f[q] = fq + om * (even + odd - fq) + forceEven + forceOdd;
        f[o] = fo + om * (even - odd - fo) + forceEven - forceOdd;
      }
    }
  }
};

}  // namespace fluidviz::lbm
