#pragma once
// Bounce-back from a moving wall (Ladd 1994, J. Fluid Mech. 271:285, sec. 3): a wall moving with
// velocity u_w at the link's mid-point reflects the population with the momentum it imparts,
//   f_q(n, t+1) = f*_{opp(q)}(n, t) + 2 w_q rho_w (c_q . u_w) / cs2,
// where c_q points from the wall into the fluid. rho_w is the lattice reference density 1 rather
// than the local density: the added terms then sum to zero over a flat sliding wall and over the
// surface of a rigidly rotating body, so total mass is conserved exactly.
// Used for moving lids (u_w constant) and rollers (u_w = omega x (x_mid - centre) per link).
#include <cstdint>

#include "solvers/lbm/boundaries/BounceBackWall.h"

namespace fluidviz::lbm {

/// Momentum term 2 w_q (c_q . u_w) / cs2 of a wall moving with u_w (lattice units, dx / dt).
template <class L>
inline double movingWallDelta(int q, double uwx, double uwy, double uwz = 0.0) {
  return 2.0 * L::w[q] * (L::cx[q] * uwx + L::cy[q] * uwy + L::cz[q] * uwz) / L::cs2;
}

/// uwx, uwy, uwz: wall velocity at the link mid-point in lattice units (dx / dt).
template <class L>
inline PullLink movingWallLink(std::int64_t node, int q, std::int64_t stride, double uwx,
                               double uwy, double uwz = 0.0) {
  PullLink link = bounceBackLink<L>(node, q, stride);
  link.delta = movingWallDelta<L>(q, uwx, uwy, uwz);
  return link;
}

}  // namespace fluidviz::lbm
