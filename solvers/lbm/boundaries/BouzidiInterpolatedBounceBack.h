#pragma once
// Interpolated bounce-back for curved walls (Bouzidi, Firdaouss & Lallemand 2001, "Momentum
// transfer of a Boltzmann-lattice fluid with boundaries", Phys. Fluids 13:3452, eq. 5, linear
// version). A link from fluid node x_f towards a solid node crosses the wall at the fraction
// qw in (0, 1] of its length (qw = 1/2 is the halfway wall of BounceBackWall.h). With i the
// direction pointing into the wall and i' = opp(i) the one returning from it:
//   qw <  1/2:  f_i'(x_f, t+1) = 2 qw f*_i(x_f) + (1 - 2 qw) f*_i(x_f + c_i')
//   qw >= 1/2:  f_i'(x_f, t+1) = f*_i(x_f) / (2 qw) + (2 qw - 1) / (2 qw) f*_i'(x_f)
// (post-collision values f*, in the pull scheme all from the previous step's array). A moving
// wall adds the momentum term of MovingWallBounceBack.h, 2 w (c_i' . u_w) / cs2 with u_w at the
// wall point, for qw < 1/2 and divided by 2 qw for qw >= 1/2 (Lallemand & Luo 2003,
// J. Comput. Phys. 184:406, sec. 3). The wall is then second-order accurate at any position,
// where the staircase of halfway bounce-back is first order for curved walls.
// Mass: the interpolation does not conserve mass (Bouzidi et al. 2001, sec. V; Lallemand & Luo
// 2003, sec. 5). Measured on circular Couette flow (tests/solvers/lbm/CurvedBoundary_test.cpp):
// the density gradient along the links makes the fluid gain ~1e-3 of its mass per 2000 steps
// without end, and because the moving-wall term uses the reference density the flow then slows
// down and never becomes steady. Here each interpolated link's difference from halfway
// bounce-back (the staircase value of the same link, which conserves mass exactly) is therefore
// added to the node's rest population: the node receives the interpolated momentum but the mass
// of halfway bounce-back, so total mass is conserved to round-off, like the staircase
// (StreamCollidePull.h, gatherBoundaryNode). The rest population carries no momentum, so the
// velocity the wall imposes is unchanged; the local density near the wall is perturbed by
// O(dx) of the interpolation defect.
// When x_f + c_i' is not a fluid node (a thin gap), qw < 1/2 falls back to halfway bounce-back.
#include <cstdint>

#include "solvers/lbm/boundaries/SolidBody.h"

namespace fluidviz::lbm {

/// Wall fraction of a link: the fraction t in (0, 1] of the way from the fluid end to the solid
/// end where the body's surface lies, by bisection of `contains` (60 halvings: exact to round-off).
inline double wallFraction(const SolidBody& body, const Vec2& fluidEnd, const Vec2& solidEnd) {
  double lo = 0.0, hi = 1.0;
  if (body.contains(fluidEnd)) return 0.5;  // degenerate (wrapped link): halfway bounce-back
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (body.contains(fluidEnd + mid * (solidEnd - fluidEnd)))
      hi = mid;
    else
      lo = mid;
  }
  return hi;
}

/// One incoming population of a boundary node replaced by the interpolation
/// f_q = w1 post[s1] + w2 post[s2] + delta.
struct InterpolatedLink {
  int q = 0;
  std::int64_t s1 = 0, s2 = 0;  ///< flat indices into the post-collision populations
  double w1 = 1.0, w2 = 0.0;    ///< weights, w1 + w2 = 1
  double delta = 0.0;           ///< moving-wall momentum (already scaled by 1/(2 qw) if needed)
};

/// The Bouzidi rule for incoming direction q at `node` with wall fraction qw. opp = opp(q);
/// secondNode = flat index of x_f + c_q, or -1 if that is not a fluid node; wallDelta = the
/// moving-wall term 2 w (c_q . u_w) / cs2 (0 at rest).
inline InterpolatedLink bouzidiLink(int q, int opp, std::int64_t node, std::int64_t secondNode,
                                    std::int64_t stride, double qw, double wallDelta) {
  InterpolatedLink l;
  l.q = q;
  if (qw < 0.5) {
    if (secondNode < 0) {  // no second node: halfway bounce-back
      l.s1 = l.s2 = opp * stride + node;
      l.w1 = 1.0;
      l.w2 = 0.0;
      l.delta = wallDelta;
      return l;
    }
    l.s1 = opp * stride + node;
    l.w1 = 2.0 * qw;
    l.s2 = opp * stride + secondNode;
    l.w2 = 1.0 - 2.0 * qw;
    l.delta = wallDelta;
  } else {
    l.s1 = opp * stride + node;
    l.w1 = 1.0 / (2.0 * qw);
    l.s2 = q * stride + node;
    l.w2 = (2.0 * qw - 1.0) / (2.0 * qw);
    l.delta = wallDelta / (2.0 * qw);
  }
  return l;
}

}  // namespace fluidviz::lbm
