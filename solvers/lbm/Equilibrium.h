#pragma once
// Second-order Maxwell-Boltzmann equilibrium and the macroscopic moments of a node, for any 2D
// lattice L (LatticeD2Q9.h):
//   f_q^eq = w_q rho (1 + c.u / cs2 + (c.u)^2 / (2 cs2^2) - u.u / (2 cs2))
// (Qian, d'Humieres & Lallemand 1992; with cs2 = 1/3 the factors are 3, 4.5 and 1.5).
#include "solvers/lbm/KernelInline.h"

namespace fluidviz::lbm {

struct NodeMoments {
  double rho;  ///< lattice density sum_q f_q
  double ux;   ///< lattice velocity, including the half-force shift of Guo et al. 2002
  double uy;
};

/// Density and velocity of one node's populations. With a body acceleration g the velocity is
/// u = (sum_q f_q c_q + F/2) / rho with F = rho g (Guo, Zheng & Shi 2002, with dt = 1),
/// which keeps the forcing second-order accurate.
template <class L>
FLUIDVIZ_LBM_INLINE NodeMoments nodeMoments(const double* f, double gx, double gy) {
  double rho = 0, jx = 0, jy = 0;
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) {
    rho += f[q];
    jx += f[q] * L::cx[q];
    jy += f[q] * L::cy[q];
  }
  const double inv = 1.0 / rho;
  return {rho, jx * inv + 0.5 * gx, jy * inv + 0.5 * gy};
}

/// f_q^eq(rho, u) of a 2D lattice.
template <class L>
inline double equilibrium(int q, double rho, double ux, double uy) {
  static_assert(L::cs2 > 0.333333 && L::cs2 < 0.333334, "factors below assume cs2 = 1/3");
  const double cu = L::cx[q] * ux + L::cy[q] * uy;
  const double uu = ux * ux + uy * uy;
  return L::w[q] * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * uu);
}

}  // namespace fluidviz::lbm
