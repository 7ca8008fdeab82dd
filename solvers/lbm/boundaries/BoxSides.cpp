#include "solvers/lbm/boundaries/BoxSides.h"

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
  if (s.type == Type::MovingWall || s.type == Type::VelocityInlet)
    s.velocity = {u.toLatticeVelocity(w.velocity[0]), u.toLatticeVelocity(w.velocity[1]),
                  u.toLatticeVelocity(w.velocity_z)};
  return s;
}

}  // namespace

BoxSides BoxSides::fromParams(const WallsParams& w, const LatticeUnits& u) {
  BoxSides b;
  b.side = {sideFromParams(w.x_min, u), sideFromParams(w.x_max, u), sideFromParams(w.y_min, u),
            sideFromParams(w.y_max, u), sideFromParams(w.z_min, u), sideFromParams(w.z_max, u)};
  return b;
}

}  // namespace fluidviz::lbm
