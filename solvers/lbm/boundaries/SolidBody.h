#pragma once
// A solid obstacle inside the box, in physical units. Nodes whose centre lies inside are solid;
// every lattice link from a fluid node into the body bounces back with the body's velocity
// (MovingWallBounceBack.h): at the link mid-point (staircase, halfway bounce-back), or at the
// point where the link crosses the surface (interpolated, BouzidiInterpolatedBounceBack.h).
// Rollers (RotatingRoller.h) are one kind; tests add others (e.g. the fixed outer cylinder of
// Taylor-Couette flow). Bodies are 2D shapes; in a 3D box they are extruded along z (cylinders
// through the whole depth): `contains` and `velocity` see the (x, y) of a point.
#include <functional>
#include <string>

#include <Eigen/Core>

namespace fluidviz::lbm {

using Vec2 = Eigen::Vector2d;

struct SolidBody {
  std::string name;                           ///< for messages, e.g. "rollers[0]"
  std::function<bool(const Vec2&)> contains;  ///< true if the point (m) is inside the body
  std::function<Vec2(const Vec2&)> velocity;  ///< m/s of the body's material at a point (m)
  /// Boundary rule: false = staircase (halfway bounce-back), true = Bouzidi interpolation at
  /// the surface (found by bisection of `contains` along each link).
  bool interpolated = false;
};

}  // namespace fluidviz::lbm
