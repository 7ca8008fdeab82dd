#include "solvers/lbm/boundaries/RotatingRoller.h"

namespace fluidviz::lbm {

SolidBody rotatingRoller(const RollerParams& r, std::string name) {
  const Vec2 centre(r.center[0], r.center[1]);
  const double radius = r.radius, omega = r.angular_velocity;
  SolidBody body;
  body.name = std::move(name);
  body.contains = [=](const Vec2& p) { return (p - centre).squaredNorm() <= radius * radius; };
  // omega e_z x (p - c) = omega (-(p_y - c_y), p_x - c_x)
  body.velocity = [=](const Vec2& p) {
    const Vec2 d = p - centre;
    return Vec2(-omega * d.y(), omega * d.x());
  };
  body.interpolated = r.boundary == RollerBoundary::interpolated;
  return body;
}

std::vector<SolidBody> sceneBodies(const LbmParams& p, std::vector<SolidBody> extra) {
  std::vector<SolidBody> bodies;
  for (std::size_t i = 0; i < p.rollers.size(); ++i)
    bodies.push_back(rotatingRoller(p.rollers[i], "rollers[" + std::to_string(i) + "]"));
  for (SolidBody& b : extra) bodies.push_back(std::move(b));
  return bodies;
}

}  // namespace fluidviz::lbm
