#pragma once
// Second-order Maxwell-Boltzmann equilibrium and the macroscopic moments of a node, for any
// lattice L with c_s^2 = 1/3 (LatticeD2Q9.h, LatticeD3Q19.h):
//   f_q^eq = w_q rho (1 + c.u / cs2 + (c.u)^2 / (2 cs2^2) - u.u / (2 cs2))
// (Qian, d'Humieres & Lallemand 1992; with cs2 = 1/3 the factors are 3, 4.5 and 1.5).
//
// Shifted populations. The solver stores g_q = f_q - w_q, the deviation from the equilibrium at
// rest with density 1 (Skordos 1993, Phys. Rev. E 48:4823; "DDF shifting" in Lehmann, Krause,
// Amati, Sega, Harting & Gekle 2022, Phys. Rev. E 106:015308). The g_q are small, so their
// round-off is small relative to the flow they carry: in single precision this is the difference
// between a usable and a noisy velocity field. Everything linear in f (streaming, bounce-back,
// moving walls, Bouzidi interpolation, Zou-He) reads the same for g, because each rule maps a
// population onto one of equal weight (opposite directions share w_q) or mixes with weights
// summing to 1. Moments: rho = 1 + sum g, rho u = sum g c (sum_q w_q c_q = 0).
#include "solvers/lbm/kernel/KernelInline.h"

namespace fluidviz::lbm {

template <class T>
struct NodeMoments {
  T drho;  ///< rho - 1 = sum_q g_q (kept separately: exact where 1 + drho rounds)
  T rho;   ///< lattice density 1 + sum_q g_q
  T ux;   ///< lattice velocity, including the half-force shift of Guo et al. 2002
  T uy;
  T uz;
};

/// Density and velocity of one node's shifted populations g. With a body acceleration g the
/// velocity is u = (sum_q f_q c_q + F/2) / rho with F = rho g (Guo, Zheng & Shi 2002, with
/// dt = 1), which keeps the forcing second-order accurate.
template <class L, class T>
FLUIDVIZ_LBM_INLINE NodeMoments<T> nodeMoments(const T* g, T gx, T gy, T gz) {
  // Four interleaved partial sums per moment, added pairwise at the end: the dependency chain
  // of a sum over 19 populations is 6 additions long instead of 19, which matters where the
  // stream-collide kernel is latency bound (StreamCollidePull.h). After unrolling the velocity
  // components are constants: the branches fold away and no multiplication by 0 or +-1 is left
  // (GCC may not drop "+ 0 * x" without -ffast-math).
  T d[4] = {0, 0, 0, 0}, x[4] = {0, 0, 0, 0}, y[4] = {0, 0, 0, 0}, z[4] = {0, 0, 0, 0};
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) {
    d[q % 4] += g[q];
    if (L::cx[q] != 0) x[q % 4] += L::cx[q] > 0 ? g[q] : -g[q];
    if (L::cy[q] != 0) y[q % 4] += L::cy[q] > 0 ? g[q] : -g[q];
    if (L::cz[q] != 0) z[q % 4] += L::cz[q] > 0 ? g[q] : -g[q];
  }
  const T drho = (d[0] + d[1]) + (d[2] + d[3]);
  const T jx = (x[0] + x[1]) + (x[2] + x[3]), jy = (y[0] + y[1]) + (y[2] + y[3]),
          jz = (z[0] + z[1]) + (z[2] + z[3]);
  const T rho = T(1) + drho;
  const T inv = T(1) / rho;
  return {drho, rho, jx * inv + T(0.5) * gx, jy * inv + T(0.5) * gy, jz * inv + T(0.5) * gz};
}

/// c_q . v, written so that after unrolling only the non-zero components cost arithmetic.
template <class L, class T>
FLUIDVIZ_LBM_INLINE T latticeDot(int q, T x, T y, T z) {
  T s = T(0);
  bool first = true;
  if (L::cx[q] != 0) {
    s = L::cx[q] > 0 ? x : -x;
    first = false;
  }
  if (L::cy[q] != 0) {
    s = first ? (L::cy[q] > 0 ? y : -y) : (L::cy[q] > 0 ? s + y : s - y);
    first = false;
  }
  if (L::cz[q] != 0) s = first ? (L::cz[q] > 0 ? z : -z) : (L::cz[q] > 0 ? s + z : s - z);
  return s;
}

/// f_q^eq(rho, u), the full (unshifted) equilibrium.
template <class L>
inline double equilibrium(int q, double rho, double ux, double uy, double uz = 0.0) {
  static_assert(L::cs2 > 0.333333 && L::cs2 < 0.333334, "factors below assume cs2 = 1/3");
  const double cu = L::cx[q] * ux + L::cy[q] * uy + L::cz[q] * uz;
  const double uu = ux * ux + uy * uy + uz * uz;
  return L::w[q] * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * uu);
}

/// f_q^eq - w_q, the equilibrium as a shifted population, computed without cancellation:
/// w_q ((rho - 1) + rho (3 c.u + 4.5 (c.u)^2 - 1.5 u.u)).
template <class L>
inline double shiftedEquilibrium(int q, double rho, double ux, double uy, double uz = 0.0) {
  const double cu = L::cx[q] * ux + L::cy[q] * uy + L::cz[q] * uz;
  const double uu = ux * ux + uy * uy + uz * uz;
  return L::w[q] * ((rho - 1.0) + rho * (3.0 * cu + 4.5 * cu * cu - 1.5 * uu));
}

}  // namespace fluidviz::lbm
