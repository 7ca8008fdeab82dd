#pragma once
// Two-relaxation-time collision (Ginzburg, Verhaeghe & d'Humieres 2008, "Two-relaxation-time
// lattice Boltzmann scheme: about parametrization, velocity, pressure and mixed boundary
// conditions", Commun. Comput. Phys. 3:427). Each opposite pair is split into its symmetric and
// antisymmetric parts, f+_q = (f_q + f_opp)/2 and f-_q = (f_q - f_opp)/2, relaxed at their own
// rates:
//   f_q* = f_q - omega+ (f+_q - f+eq_q) - omega- (f-_q - f-eq_q) + (1 - omega+/2) S+_q
//          + (1 - omega-/2) S-_q
// omega+ = 1 / tau+ sets the viscosity nu = cs2 (tau+ - 1/2) (as BGK's tau); omega- follows
// from the "magic" parameter Lambda = (tau+ - 1/2)(tau- - 1/2) (Ginzburg 2008, sec. 2; d'Humieres
// & Ginzburg 2009, Comput. Math. Appl. 58:823). At fixed Lambda the steady solutions do not
// depend on the viscosity; Lambda = 3/16 places halfway bounce-back walls exactly halfway for
// Poiseuille flow (the error of plane Poiseuille flow vanishes for every tau), Lambda = 1/4 is
// the most stable, 1/12 cancels the third-order advection error, 1/6 the fourth-order diffusion
// error. BGK is the special case tau- = tau+ (Lambda = (tau - 1/2)^2). S+- are the even and odd
// parts of the Guo force term (GuoForcing.h). Acts on shifted populations g_q = f_q - w_q.
#include "solvers/lbm/collision/GuoForcing.h"
#include "solvers/lbm/kernel/KernelInline.h"
#include "solvers/lbm/lattice/Equilibrium.h"

namespace fluidviz::lbm {

struct CollisionTRT {
  double omegaPlus = 1.0;   ///< 1 / tau+, in (0, 2): viscosity
  double omegaMinus = 1.0;  ///< 1 / tau-, from the magic parameter
  double gx = 0.0;          ///< lattice body acceleration g dt^2 / dx (used when Forced)
  double gy = 0.0;
  double gz = 0.0;

  /// omega- for relaxation time tau+ and magic parameter Lambda: tau- = 1/2 + Lambda/(tau+ - 1/2).
  static double omegaMinusFor(double tauPlus, double magic) {
    return 1.0 / (0.5 + magic / (tauPlus - 0.5));
  }

  template <class L, bool Forced, class T>
  FLUIDVIZ_LBM_INLINE void collide(T* f) const {
    const T gxT = Forced ? T(gx) : T(0), gyT = Forced ? T(gy) : T(0), gzT = Forced ? T(gz) : T(0);
    const NodeMoments<T> m = nodeMoments<L, T>(f, gxT, gyT, gzT);
    const T op = T(omegaPlus), om = T(omegaMinus);
    const T uu = T(1.5) * (m.ux * m.ux + m.uy * m.uy + m.uz * m.uz);
    const T forceX = m.rho * gxT, forceY = m.rho * gyT, forceZ = m.rho * gzT;
    const T uF = T(3) * (m.ux * forceX + m.uy * forceY + m.uz * forceZ);
    const T prefactorPlus = T(1) - T(0.5) * op, prefactorMinus = T(1) - T(0.5) * om;
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) {
      const int o = L::opposite[q];
      if (o < q) continue;
      const T w = T(L::w[q]);
      const T cu = latticeDot<L, T>(q, m.ux, m.uy, m.uz);
      const T even = w * (m.drho + m.rho * (T(4.5) * cu * cu - uu));  // f+eq - w
      const T odd = T(3) * w * m.rho * cu;                           // f-eq
      T forceEven = T(0), forceOdd = T(0);
      if constexpr (Forced) {
        const T cF = latticeDot<L, T>(q, forceX, forceY, forceZ);
        forceEven = prefactorPlus * w * (T(9) * cu * cF - uF);
        forceOdd = prefactorMinus * w * T(3) * cF;
      }
      if (o == q) {
        f[q] += op * (even - f[q]) + forceEven;
      } else {
        const T fq = f[q], fo = f[o];
        const T plus = T(0.5) * (fq + fo), minus = T(0.5) * (fq - fo);
        const T relaxPlus = op * (even - plus) + forceEven;
        const T relaxMinus = om * (odd - minus) + forceOdd;
        f[q] = fq + relaxPlus + relaxMinus;
        f[o] = fo + relaxPlus - relaxMinus;
      }
    }
  }
};

}  // namespace fluidviz::lbm
