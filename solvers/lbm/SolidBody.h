#pragma once
// A solid obstacle inside the box, in physical units. Nodes whose centre lies inside are solid;
// every lattice link from a fluid node into the body bounces back with the body's velocity at
// the link mid-point (MovingWallBounceBack.h). Rollers (RotatingRoller.h) are one kind; tests
// and later issues add others (e.g. the fixed outer cylinder of Taylor-Couette flow).
#include <functional>
#include <string>

#include <Eigen/Core>

namespace fluidviz::lbm {

using Vec2 = Eigen::Vector2d;

struct SolidBody {
  std::string name;                           ///< for messages, e.g. "rollers[0]"
  std::function<bool(const Vec2&)> contains;  ///< true if the point (m) is inside the body
  std::function<Vec2(const Vec2&)> velocity;  ///< m/s of the body's material at a point (m)
};

}  // namespace fluidviz::lbm
