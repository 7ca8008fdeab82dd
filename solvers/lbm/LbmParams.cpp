#include "solvers/lbm/LbmParams.h"

#include <algorithm>
#include <cmath>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::lbm {

namespace {

void checkViscosityOrReynolds(const LbmParams& p) {
  if (p.viscosity && p.reynolds)
    throw ParamError("viscosity",
                     "and lbm.reynolds are both given; give exactly one of them (the other "
                     "follows from Re = U_ref L_ref / nu)");
  if (!p.viscosity && !p.reynolds)
    throw ParamError("viscosity",
                     "is missing: give exactly one of lbm.viscosity (m^2/s) or lbm.reynolds");
}

void checkPeriodicPairs(const WallsParams& w, bool threeD) {
  auto pair = [](const WallParams& lo, const WallParams& hi, const std::string& loKey,
                 const std::string& hiKey) {
    const bool a = lo.type == WallType::periodic, b = hi.type == WallType::periodic;
    if (a != b)
      throw ParamError(a ? "walls." + hiKey + ".type" : "walls." + loKey + ".type",
                       "is \"" + choiceName(a ? hi.type : lo.type) + "\" but walls." + (a ? loKey : hiKey) +
                           " is periodic; periodic sides come in pairs: make both walls." +
                           loKey + " and walls." + hiKey + " periodic, or neither");
  };
  pair(w.x_min, w.x_max, "x_min", "x_max");
  pair(w.y_min, w.y_max, "y_min", "y_max");
  if (threeD) pair(w.z_min, w.z_max, "z_min", "z_max");
}

bool isOpen(const WallParams& w) {
  return w.type == WallType::velocity_inlet || w.type == WallType::pressure_outlet ||
         w.type == WallType::pressure_inlet;
}

// normalAxis: 0 for the x sides (normal along x), 1 for the y sides, 2 for the z sides.
void checkWallVelocity(const WallParams& w, const std::string& key, int normalAxis) {
  const bool moving = w.type == WallType::moving_wall, inlet = w.type == WallType::velocity_inlet;
  const double velocity[3] = {w.velocity[0], w.velocity[1], w.velocity_z};
  const bool hasVelocity = velocity[0] != 0.0 || velocity[1] != 0.0 || velocity[2] != 0.0;
  if (!moving && !inlet && hasVelocity)
    throw ParamError(w.velocity_z != 0.0 ? "walls." + key + ".velocity_z" : "walls." + key + ".velocity",
                     "is non-zero but walls." + key + ".type is \"" + choiceName(w.type) +
                         "\"; set the type to moving_wall or velocity_inlet, or the velocity to 0");
  if (moving && velocity[normalAxis] != 0.0)
    throw ParamError(normalAxis == 2 ? "walls." + key + ".velocity_z" : "walls." + key + ".velocity",
                     std::string("has a component normal to the wall (") +
                         (normalAxis == 0 ? "x" : normalAxis == 1 ? "y" : "z") + " = " +
                         formatNumber(velocity[normalAxis]) +
                         " m/s); a wall can only slide along itself: set it to 0");
  if (!inlet && w.ramp_time != 0.0)
    throw ParamError("walls." + key + ".ramp_time",
                     "is non-zero but walls." + key + ".type is \"" + choiceName(w.type) +
                         "\"; only a velocity_inlet starts with a ramp");
  if (!inlet && w.profile != InletProfile::uniform)
    throw ParamError("walls." + key + ".profile",
                     "is \"" + choiceName(w.profile) + "\" but walls." + key + ".type is \"" +
                         choiceName(w.type) + "\"; only a velocity_inlet has a profile");
  const bool pressureSide =
      w.type == WallType::pressure_outlet || w.type == WallType::pressure_inlet;
  if (!pressureSide && w.pressure != 0.0)
    throw ParamError("walls." + key + ".pressure",
                     "is non-zero but walls." + key + ".type is \"" + choiceName(w.type) +
                         "\"; only pressure_outlet and pressure_inlet sides hold a pressure");
}

// Open sides (Zou-He) are closed node by node along their normal; two open sides meeting at an
// edge would leave the corner nodes with two normals.
void checkOpenSidesApart(const WallsParams& w) {
  const std::pair<const WallParams*, const char*> sides[6] = {
      {&w.x_min, "x_min"}, {&w.x_max, "x_max"}, {&w.y_min, "y_min"},
      {&w.y_max, "y_max"}, {&w.z_min, "z_min"}, {&w.z_max, "z_max"}};
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b) {
      if (a / 2 == b / 2) continue;  // opposite sides do not meet
      if (isOpen(*sides[a].first) && isOpen(*sides[b].first))
        throw ParamError(std::string("walls.") + sides[b].second + ".type",
                         "is \"" + choiceName(sides[b].first->type) + "\" and walls." + sides[a].second +
                             " is \"" + choiceName(sides[a].first->type) +
                             "\": open sides (velocity_inlet, pressure_*) may not meet at an "
                             "edge; make one of them a wall or periodic (open sides may face "
                             "each other)");
    }
}

void checkDimension(const LbmParams& p) {
  const bool threeD = is3D(p);
  if (threeD && p.domain_depth <= 0.0)
    throw ParamError("domain_depth",
                     "is 0 but lbm.lattice is D3Q19 (3D): give the depth Lz of the box in m, or "
                     "use lattice D2Q9 for a 2D scene");
  if (!threeD && p.domain_depth != 0.0)
    throw ParamError("domain_depth", "is " + formatNumber(p.domain_depth) +
                                         " m but lbm.lattice is D2Q9 (2D): set lattice to "
                                         "D3Q19 for a 3D box, or remove domain_depth");
  if (threeD) return;
  if (p.body_force_z != 0.0)
    throw ParamError("body_force_z", "is non-zero in a 2D scene (lattice D2Q9): set it to 0 or "
                                     "use lattice D3Q19");
  const WallParams plain;
  for (const auto& [w, key] : {std::pair{&p.walls.z_min, "z_min"}, std::pair{&p.walls.z_max, "z_max"}})
    if (w->type != plain.type || w->velocity != plain.velocity || w->velocity_z != 0.0 ||
        w->pressure != 0.0)
      throw ParamError(std::string("walls.") + key,
                       "is set in a 2D scene (lattice D2Q9): the z sides exist only in 3D; "
                       "remove it or use lattice D3Q19 with domain_depth");
  for (const auto& [w, key] : {std::pair{&p.walls.x_min, "x_min"}, std::pair{&p.walls.x_max, "x_max"},
                               std::pair{&p.walls.y_min, "y_min"}, std::pair{&p.walls.y_max, "y_max"}})
    if (w->velocity_z != 0.0)
      throw ParamError(std::string("walls.") + key + ".velocity_z",
                       "is non-zero in a 2D scene (lattice D2Q9): set it to 0");
}

void checkInitialFlow(const LbmParams& p) {
  if (p.initial_flow == InitialFlow::rest) {
    if (p.initial_speed != 0.0)
      throw ParamError("initial_speed", "is " + formatNumber(p.initial_speed) +
                                            " m/s but lbm.initial_flow is rest; set "
                                            "initial_flow (e.g. taylor_green) or remove it");
    return;
  }
  if (p.initial_flow == InitialFlow::sketch) {  // initial_speed 0: the strokes' speeds as drawn
    if (is3D(p))
      throw ParamError("initial_flow", "is sketch, which is 2D, but lbm.lattice is D3Q19: use "
                                       "lattice D2Q9");
    return;
  }
  if (p.initial_speed <= 0.0)
    throw ParamError("initial_speed", "is 0 but lbm.initial_flow is " + choiceName(p.initial_flow) +
                                          ": give the amplitude U0 in m/s");
  const WallsParams& w = p.walls;
  for (const auto& [side, key] : {std::pair{&w.x_min, "x_min"}, std::pair{&w.y_min, "y_min"},
                                  std::pair{&w.z_min, "z_min"}}) {
    if (std::string(key) == "z_min" && !is3D(p)) continue;
    if (side->type != WallType::periodic)
      throw ParamError(std::string("walls.") + key + ".type",
                       "is \"" + choiceName(side->type) +
                           "\" but lbm.initial_flow taylor_green is a periodic vortex array: "
                           "make all sides periodic");
  }
}

void checkRollers(const LbmParams& p) {
  const double lx = p.domain_size[0], ly = p.domain_size[1];
  for (std::size_t i = 0; i < p.rollers.size(); ++i) {
    const RollerParams& r = p.rollers[i];
    const std::string key = "rollers[" + std::to_string(i) + "]";
    const double x = r.center[0], y = r.center[1];
    if (x - r.radius < 0 || x + r.radius > lx || y - r.radius < 0 || y + r.radius > ly)
      throw ParamError(key, "(centre [" + formatNumber(x) + ", " + formatNumber(y) +
                                "] m, radius " + formatNumber(r.radius) +
                                " m) does not lie inside the box [0, " + formatNumber(lx) +
                                "] x [0, " + formatNumber(ly) +
                                "] m; move its centre or reduce its radius");
    for (std::size_t k = 0; k < i; ++k) {
      const RollerParams& o = p.rollers[k];
      if (std::hypot(x - o.center[0], y - o.center[1]) < r.radius + o.radius)
        throw ParamError(key, "overlaps rollers[" + std::to_string(k) +
                                  "]; move the centres apart or reduce the radii");
    }
  }
}

}  // namespace

void validateLbmParams(const LbmParams& p) {
  params::checkRanges(p);
  checkViscosityOrReynolds(p);
  checkDimension(p);
  checkPeriodicPairs(p.walls, is3D(p));
  checkWallVelocity(p.walls.x_min, "x_min", 0);
  checkWallVelocity(p.walls.x_max, "x_max", 0);
  checkWallVelocity(p.walls.y_min, "y_min", 1);
  checkWallVelocity(p.walls.y_max, "y_max", 1);
  checkWallVelocity(p.walls.z_min, "z_min", 2);
  checkWallVelocity(p.walls.z_max, "z_max", 2);
  checkOpenSidesApart(p.walls);
  checkInitialFlow(p);
  checkRollers(p);
}

double inletMeanFactor(const WallParams& w, bool threeD) {
  if (w.profile == InletProfile::uniform) return 1.0;
  return threeD ? 4.0 / 9.0 : 2.0 / 3.0;  // mean of 4 s (1 - s) over [0, 1] is 2/3
}

double referenceVelocity(const LbmParams& p) {
  double u = p.initial_speed;
  for (const WallParams* w : {&p.walls.x_min, &p.walls.x_max, &p.walls.y_min, &p.walls.y_max,
                              &p.walls.z_min, &p.walls.z_max})
    if (w->type == WallType::moving_wall || w->type == WallType::velocity_inlet)
      u = std::max(u, std::sqrt(w->velocity[0] * w->velocity[0] + w->velocity[1] * w->velocity[1] +
                                w->velocity_z * w->velocity_z) *
                          (w->type == WallType::velocity_inlet ? inletMeanFactor(*w, is3D(p)) : 1.0));
  for (const RollerParams& r : p.rollers) u = std::max(u, std::abs(r.angular_velocity) * r.radius);
  return u;
}

}  // namespace fluidviz::lbm
