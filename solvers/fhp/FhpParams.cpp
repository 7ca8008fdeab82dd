#include "solvers/fhp/FhpParams.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <utility>

#include "fieldviz/core/ParamRanges.h"
#include "solvers/fhp/kernel/MovingWall.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {

double latticeViscosity(Model model, double d) {
  const double e = 1.0 - d;
  switch (model) {
    case Model::fhp1: return 1.0 / (12.0 * d * e * e * e) - 0.125;
    case Model::fhp2: return 1.0 / (28.0 * d * e * e * e * (1.0 - 4.0 * d / 7.0)) - 0.125;
    case Model::fhp3: return 1.0 / (28.0 * d * e * (1.0 - 8.0 * d * e / 7.0)) - 0.125;
  }
  return 0.0;
}

double galileanFactor(Model model, double d) {
  return model == Model::fhp1 ? (1.0 - 2.0 * d) / (2.0 * (1.0 - d))
                              : 7.0 * (1.0 - 2.0 * d) / (12.0 * (1.0 - d));
}

double soundSpeed(Model model) {
  return model == Model::fhp1 ? std::sqrt(0.5) : std::sqrt(3.0 / 7.0);
}

namespace {

std::string modelName(Model m) {
  return m == Model::fhp1 ? "FHP-I" : m == Model::fhp2 ? "FHP-II" : "FHP-III";
}

int blockRows(int blockSize) {
  return std::max(1, static_cast<int>(std::lround(blockSize / kRowSpacing)));
}

int rowCount(const FhpParams& p, int blockY) {
  const double dx = p.domain_size[0] / p.resolution;
  const int step = std::lcm(2, blockY);
  const long rows = std::lround(p.domain_size[1] / (kRowSpacing * dx) / step) * step;
  return static_cast<int>(std::max<long>(step, rows));
}

void checkSides(const FhpSidesParams& w) {
  auto pair = [](SideType lo, SideType hi, const std::string& loKey, const std::string& hiKey) {
    const bool a = lo == SideType::periodic, b = hi == SideType::periodic;
    if (a != b)
      throw ParamError("walls." + (a ? hiKey : loKey) + ".type",
                       "is \"" + choiceName(a ? hi : lo) + "\" but walls." + (a ? loKey : hiKey) +
                           " is periodic; periodic sides come in pairs: make both walls." + loKey +
                           " and walls." + hiKey + " periodic, or neither");
  };
  pair(w.x_min.type, w.x_max.type, "x_min", "x_max");
  pair(w.y_min.type, w.y_max.type, "y_min", "y_max");
  for (auto [side, key] : {std::pair{w.x_min.type, "x_min"}, std::pair{w.x_max.type, "x_max"}})
    if (side == SideType::slip)
      throw ParamError(std::string("walls.") + key + ".type",
                       "is \"slip\"; specular walls are offered on the y sides (rows) only: "
                       "allowed here wall, moving_wall or periodic");
  const std::array<std::pair<const FhpWallParams*, const char*>, 4> sides{
      {{&w.x_min, "x_min"}, {&w.x_max, "x_max"}, {&w.y_min, "y_min"}, {&w.y_max, "y_max"}}};
  for (int i = 0; i < 4; ++i) {
    const FhpWallParams& side = *sides[i].first;
    const std::string key = std::string("walls.") + sides[i].second + ".velocity";
    const int normal = i < 2 ? 0 : 1;  // x sides: the x component is normal to the wall
    if (side.type != SideType::moving_wall && (side.velocity[0] != 0.0 || side.velocity[1] != 0.0))
      throw ParamError(key, "is set but the side's type is \"" + choiceName(side.type) +
                                "\"; only a moving_wall has a velocity");
    if (side.type == SideType::moving_wall && side.velocity[normal] != 0.0)
      throw ParamError(key, "has a component " + formatNumber(side.velocity[normal]) +
                                " m/s normal to the wall; a moving_wall slides along itself: "
                                "only the " + (normal == 0 ? "y" : "x") +
                                " component may be non-zero");
  }
}

/// A disc (obstacle or roller, `what` in the message) at least 2 links wide and inside the box.
void checkDisc(const FhpParams& p, const std::string& key, const std::array<double, 2>& center,
               double radius, const std::string& what) {
  const double dx = p.domain_size[0] / p.resolution;
  if (radius < 2.0 * dx)
    throw ParamError(key + ".radius", "is " + formatNumber(radius) + " m, below 2 links (" +
                                          formatNumber(2.0 * dx) +
                                          " m at this resolution): raise it or the resolution");
  if (center[0] - radius < 0.0 || center[0] + radius > p.domain_size[0] ||
      center[1] - radius < 0.0 || center[1] + radius > p.domain_size[1])
    throw ParamError(key + ".center", "puts the " + what + " outside the box [0, " +
                                          formatNumber(p.domain_size[0]) + "] x [0, " +
                                          formatNumber(p.domain_size[1]) + "] m");
}

void checkObstacles(const FhpParams& p) {
  for (std::size_t i = 0; i < p.obstacles.size(); ++i)
    checkDisc(p, "obstacles[" + std::to_string(i) + "]", p.obstacles[i].center,
              p.obstacles[i].radius, "disc");
}

/// U_ref: reference_velocity, else |flow_velocity|, else the fastest moving wall or roller rim.
double referenceSpeed(const FhpParams& p) {
  if (p.reference_velocity > 0.0) return p.reference_velocity;
  double speed = std::hypot(p.flow_velocity[0], p.flow_velocity[1]);
  if (speed > 0.0) return speed;
  for (const FhpWallParams* w : {&p.walls.x_min, &p.walls.x_max, &p.walls.y_min, &p.walls.y_max})
    if (w->type == SideType::moving_wall) speed = std::max(speed, std::hypot(w->velocity[0], w->velocity[1]));
  for (const lbm::RollerParams& r : p.rollers)
    speed = std::max(speed, std::abs(r.angular_velocity) * r.radius);
  return speed;
}

void checkRollers(const FhpParams& p) {
  for (std::size_t i = 0; i < p.rollers.size(); ++i) {
    const lbm::RollerParams& r = p.rollers[i];
    const std::string key = "rollers[" + std::to_string(i) + "]";
    if (r.boundary != lbm::RollerBoundary::staircase)
      throw ParamError(key + ".boundary",
                       "is \"" + choiceName(r.boundary) +
                           "\"; the lattice gas reflects particles at the solid nodes of the "
                           "roller only: allowed staircase");
    checkDisc(p, key, r.center, r.radius, "roller");
  }
}

/// A moving wall or roller rim of physical speed `speed`: its lattice speed within
/// max_lattice_velocity and its largest turn probability (kernel/MovingWall.h) at most 1.
void checkWallSpeed(const FhpParams& p, const FhpUnits& u, double speed, const std::string& key,
                    const std::string& what) {
  const double lattice = std::abs(u.toLatticeVelocity(speed));
  const double turn =
      flatWallTurnProbability(wallEquilibrium(p.model, p.channel_density), lattice);
  if (lattice > p.max_lattice_velocity || turn > 1.0)
    throw ParamError(key, "gives " + what + " a lattice speed of " + formatNumber(lattice, 4) +
                              " links per step (turn probability " + formatNumber(turn, 4) +
                              "); allowed at most max_lattice_velocity " +
                              formatNumber(p.max_lattice_velocity) +
                              " and a turn probability of 1: lower it, or lower reynolds or "
                              "raise resolution");
}

void checkWallSpeeds(const FhpParams& p, const FhpUnits& u) {
  const std::array<std::pair<const FhpWallParams*, const char*>, 4> sides{
      {{&p.walls.x_min, "x_min"}, {&p.walls.x_max, "x_max"}, {&p.walls.y_min, "y_min"},
       {&p.walls.y_max, "y_max"}}};
  for (const auto& [side, name] : sides)
    if (side->type == SideType::moving_wall)
      checkWallSpeed(p, u, std::hypot(side->velocity[0], side->velocity[1]),
                     std::string("walls.") + name + ".velocity", "the wall");
  for (std::size_t i = 0; i < p.rollers.size(); ++i)
    checkWallSpeed(p, u, p.rollers[i].angular_velocity * p.rollers[i].radius,
                   "rollers[" + std::to_string(i) + "].angular_velocity", "the rim");
}

}  // namespace

void validateFhpParams(const FhpParams& p) {
  params::checkRanges(p);
  if (p.resolution % 64 != 0)
    throw ParamError("resolution", "is " + std::to_string(p.resolution) +
                                       "; it must be a multiple of 64 (64 nodes per machine word)");
  if (p.resolution % p.block_size != 0)
    throw ParamError("block_size", "is " + std::to_string(p.block_size) +
                                       "; it must divide resolution " +
                                       std::to_string(p.resolution));
  checkSides(p.walls);
  if (p.inflow_width > 0 && p.walls.x_min.type != SideType::periodic)
    throw ParamError("inflow_width",
                     "is " + std::to_string(p.inflow_width) +
                         "; an inflow zone needs periodic x sides (walls.x_min and walls.x_max), "
                         "whose outflow it replaces");
  if (p.inflow_width >= p.resolution / 2)
    throw ParamError("inflow_width", "is " + std::to_string(p.inflow_width) +
                                         "; allowed below half the resolution (" +
                                         std::to_string(p.resolution / 2) + ")");
  checkObstacles(p);
  checkRollers(p);
  if (referenceSpeed(p) == 0.0)
    throw ParamError("reference_velocity",
                     "is 0 and flow_velocity, the moving walls and the rollers are at rest: give "
                     "the speed U_ref of the Reynolds number (e.g. the expected mean speed of a "
                     "forced flow), in m/s");
}

FhpUnits computeFhpUnits(const FhpParams& p) {
  validateFhpParams(p);
  FhpUnits u;
  u.nx = p.resolution;
  u.blockX = p.block_size;
  u.blockY = blockRows(p.block_size);
  u.ny = rowCount(p, u.blockY);
  u.dx = p.domain_size[0] / p.resolution;
  u.nu = latticeViscosity(p.model, p.channel_density);
  u.g = galileanFactor(p.model, p.channel_density);
  const double lRef = (p.reference_length > 0.0 ? p.reference_length : p.domain_size[0]) / u.dx;
  const double uRef = referenceSpeed(p);
  // Re = g u L / nu (Frisch et al. 1987, eq. 6.7): the lattice speed the scene's Re needs.
  u.referenceSpeed = p.reynolds * u.nu / (u.g * lRef);
  if (u.referenceSpeed > p.max_lattice_velocity) {
    const double reachable = u.g * p.max_lattice_velocity * lRef / u.nu;
    const int needed = static_cast<int>(std::ceil(p.resolution * u.referenceSpeed /
                                                  p.max_lattice_velocity / 64.0)) * 64;
    std::ostringstream m;
    m.precision(4);
    m << "is " << p.reynolds << ", which " << modelName(p.model) << " at channel_density "
      << p.channel_density << " (nu = " << u.nu << ", g = " << u.g << ") cannot reach on L_ref = "
      << lRef << " links: the lattice speed would be " << u.referenceSpeed
      << " > max_lattice_velocity " << p.max_lattice_velocity
      << "; the largest reachable Re at resolution " << p.resolution << " is " << reachable
      << " (Re = g u_max L / nu); lower reynolds or raise resolution to " << needed;
    throw ParamError("reynolds", m.str());
  }
  u.dt = u.g * u.referenceSpeed * u.dx / uRef;
  u.viscosity = u.nu * u.dx * u.dx / u.dt;
  for (int a = 0; a < 2; ++a) u.flowSpeed[a] = p.flow_velocity[a] / uRef * u.referenceSpeed;
  const double flow = std::hypot(u.flowSpeed[0], u.flowSpeed[1]);
  if (flow > p.max_lattice_velocity)
    throw ParamError("flow_velocity",
                     "has lattice speed " + formatNumber(flow, 4) + " > max_lattice_velocity " +
                         formatNumber(p.max_lattice_velocity) +
                         ": lower it or raise reference_velocity (at the same reynolds)");
  // Flips turning -c_d into +c_d happen at nodes with that channel full and c_d empty
  // (probability d (1 - d)), each adding momentum 2: d_t u = 2 p (1 - d) / b for b channels,
  // and v = g u gains g times that (Wolf-Gladrow 2000, section 3.2).
  const double aLattice = std::abs(p.body_force) * u.dt * u.dt / u.dx;
  const int b = channelCount(p.model);
  u.forceProbability = aLattice * b / (2.0 * u.g * (1.0 - p.channel_density));
  u.forceDirection = p.body_force < 0.0 ? 3 : 0;
  if (u.forceProbability > 1.0)
    throw ParamError("body_force", "is " + formatNumber(p.body_force) +
                                       " m/s^2, which needs a flip probability of " +
                                       formatNumber(u.forceProbability, 4) +
                                       " per node and step (at most 1): lower it, or lower "
                                       "reynolds or raise resolution (longer steps)");
  checkWallSpeeds(p, u);
  const double steps = std::ceil(p.end_time / u.dt - 1e-9);
  u.steps = static_cast<long long>(std::min<double>(steps, p.max_steps));
  return u;
}

std::string describeFhpUnits(const FhpUnits& u, const FhpParams& p) {
  std::ostringstream s;
  s.precision(4);
  s << modelName(p.model) << " lattice gas " << u.nx << " x " << u.ny << " nodes, dx = " << u.dx
    << " m, dt = " << u.dt << " s, channel density " << p.channel_density << "\n"
    << "lattice viscosity nu = " << u.nu << ", Galilean factor g = " << u.g
    << ", lattice speed of U_ref = " << u.referenceSpeed << " (Mach "
    << u.referenceSpeed / soundSpeed(p.model) << "), Reynolds = " << p.reynolds
    << ", viscosity = " << u.viscosity << " m^2/s\n"
    << "averaging: blocks of " << u.blockX << " x " << u.blockY << " nodes ("
    << u.nx / u.blockX << " x " << u.ny / u.blockY << " snapshot nodes), " << p.average_steps
    << " steps per snapshot\n"
    << "steps: " << u.steps << (u.steps == p.max_steps ? " (max_steps)" : " (end_time / dt)");
  if (u.forceProbability > 0.0) s << "; body force: flip probability " << u.forceProbability;
  return s.str();
}

}  // namespace fluidviz::fhp
