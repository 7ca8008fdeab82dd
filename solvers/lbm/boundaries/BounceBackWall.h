#pragma once
// Halfway bounce-back at a wall at rest (Ziegler 1993; Ladd 1994, J. Fluid Mech. 271:285, sec. 3):
// the wall sits halfway along the link, so the population arriving at fluid node n from the wall
// side is the one that left n towards the wall in the previous step, reversed:
//   f_q(n, t+1) = f*_{opp(q)}(n, t).
// No-slip is second-order accurate with the wall at the half-way point; the exact wall location
// drifts with tau for BGK (He, Zou, Luo & Dembo 1997; exact for Poiseuille at
// tau = 1/2 + sqrt(3/16)), not for TRT at a fixed magic parameter (CollisionTRT.h).
#include <cstdint>

#include "solvers/lbm/kernel/PullLink.h"

namespace fluidviz::lbm {

template <class L>
inline PullLink bounceBackLink(std::int64_t node, int q, std::int64_t stride) {
  return {L::opposite[q] * stride + node, 0.0};
}

}  // namespace fluidviz::lbm
