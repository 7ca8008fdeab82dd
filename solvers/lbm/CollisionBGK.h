#pragma once
// The LBM collision step: BGK single-relaxation-time operator (Bhatnagar, Gross & Krook 1954;
// as a lattice model Qian, d'Humieres & Lallemand 1992):
//   f_q* = f_q - omega (f_q - f_q^eq(rho, u)) + (1 - omega / 2) S_q,   omega = 1 / tau,
// with the optional Guo body-force term S_q (GuoForcing.h). Kinematic viscosity
// nu = cs2 (tau - 1/2) in lattice units. A collision operator is a small value type with a
// `collide` member used by the stream-collide kernel (StreamCollidePull.h); TRT will be another.
#include "solvers/lbm/Equilibrium.h"
#include "solvers/lbm/GuoForcing.h"
#include "solvers/lbm/KernelInline.h"

namespace fluidviz::lbm {

struct CollisionBGK {
  double omega = 1.0;  ///< 1 / tau, in (0, 2)
  double gx = 0.0;     ///< lattice body acceleration g dt^2 / dx (used when Forced)
  double gy = 0.0;

  /// Replaces the pre-collision populations f of one node by the post-collision ones.
  /// Same arithmetic as equilibrium() and guoSourceTerm(), split into the parts even and odd in
  /// c_q so that each opposite pair (q, opp(q)) shares them: f^eq_q = E + A, f^eq_opp = E - A
  /// with E = w rho (1 + 4.5 (c.u)^2 - 1.5 u.u), A = 3 w rho (c.u); likewise for S_q.
  template <class L, bool Forced>
  FLUIDVIZ_LBM_INLINE void collide(double* f) const {
    const NodeMoments m = nodeMoments<L>(f, Forced ? gx : 0.0, Forced ? gy : 0.0);
    const double uu = 1.5 * (m.ux * m.ux + m.uy * m.uy);
    const double forceX = m.rho * gx, forceY = m.rho * gy;  // F = rho g
    const double uF = 3.0 * (m.ux * forceX + m.uy * forceY);
    const double forcePrefactor = 1.0 - 0.5 * omega;
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) {
      const int o = L::opposite[q];
      if (o < q) continue;  // done with its pair (resolved at compile time after unrolling)
      const double cu = L::cx[q] * m.ux + L::cy[q] * m.uy;
      const double wr = L::w[q] * m.rho;
      const double even = wr * (1.0 + 4.5 * cu * cu - uu);
      const double odd = 3.0 * wr * cu;
      double forceEven = 0.0, forceOdd = 0.0;
      if constexpr (Forced) {
        const double cF = L::cx[q] * forceX + L::cy[q] * forceY;
        forceEven = forcePrefactor * L::w[q] * (9.0 * cu * cF - uF);
        forceOdd = forcePrefactor * L::w[q] * 3.0 * cF;
      }
      if (o == q) {
        f[q] += omega * (even - f[q]) + forceEven;
      } else {
        const double fq = f[q], fo = f[o];
        f[q] = fq + omega * (even + odd - fq) + forceEven + forceOdd;
        f[o] = fo + omega * (even - odd - fo) + forceEven - forceOdd;
      }
    }
  }
};

}  // namespace fluidviz::lbm
