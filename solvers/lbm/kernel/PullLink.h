#pragma once
// One incoming link of the pull scheme: node n receives population q for the next step as
//   f_q(n, t+1) = f*[source] + delta
// where f* is the post-collision array of the current step, addressed flat as
// q_src * stride + node_src. A plain neighbour has source = q * stride + (n - c_q) and delta = 0;
// boundary rules (BounceBackWall.h, MovingWallBounceBack.h, PeriodicBoundary.h) produce the others.
#include <cstdint>

namespace fluidviz::lbm {

struct PullLink {
  std::int64_t source = 0;  ///< flat index into the post-collision populations
  double delta = 0.0;       ///< momentum added by a moving wall (lattice units), else 0
};

}  // namespace fluidviz::lbm
