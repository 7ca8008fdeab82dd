#include "solvers/lbm/boundaries/BoxSides.h"

#include <cmath>
#include <numbers>

namespace fluidviz::lbm {

namespace {

SideCondition sideFromParams(const WallParams& w, const LatticeUnits& u) {
  SideCondition s;
  using Type = SideCondition::Type;
  if (w.type == WallType::periodic) s.type = Type::Periodic;
  if (w.type == WallType::moving_wall) s.type = Type::MovingWall;
  if (w.type == WallType::velocity_inlet) s.type = Type::VelocityInlet;
  if (w.type == WallType::pressure_outlet || w.type == WallType::pressure_inlet) {
    s.type = Type::Pressure;
    s.density = u.pressureToLatticeDensity(w.pressure);
  }
  s.parabolic = s.type == Type::VelocityInlet && w.profile == InletProfile::parabolic;
  if (s.type == Type::VelocityInlet) s.rampSteps = w.ramp_time / u.dt;
  if (s.type == Type::MovingWall || s.type == Type::VelocityInlet)
    s.velocity = {u.toLatticeVelocity(w.velocity[0]), u.toLatticeVelocity(w.velocity[1]),
                  u.toLatticeVelocity(w.velocity_z)};
  return s;
}

}  // namespace

double inletProfileFactor(const SideCondition& side, int axis, const int (&ijk)[3],
                          const int (&dims)[3]) {
  if (!side.parabolic) return 1.0;
  double factor = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (a == axis) continue;
    const double s = (ijk[a] + 0.5) / dims[a];
    factor *= 4.0 * s * (1.0 - s);
  }
  return factor;
}

double inletRampFactor(const SideCondition& side, long long step) {
  if (!(static_cast<double>(step) < side.rampSteps)) return 1.0;
  const double s = std::sin(0.5 * std::numbers::pi * static_cast<double>(step) / side.rampSteps);
  return s * s;
}

BoxSides BoxSides::fromParams(const WallsParams& w, const LatticeUnits& u) {
  BoxSides b;
  b.side = {sideFromParams(w.x_min, u), sideFromParams(w.x_max, u), sideFromParams(w.y_min, u),
            sideFromParams(w.y_max, u), sideFromParams(w.z_min, u), sideFromParams(w.z_max, u)};
  return b;
}

}  // namespace fluidviz::lbm
