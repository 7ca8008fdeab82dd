#include "solvers/fhp/FhpSolver.h"

#include <bit>
#include <algorithm>
#include <cmath>

#include "fieldviz/core/StateBytes.h"
#include "solvers/fhp/lattice/Initialisation.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {

FhpSolver::FhpSolver(const FhpParams& params)
    : params_(params),
      units_(computeFhpUnits(params)),
      lattice_(units_.nx, units_.ny),
      table_(buildCollisionTable(params.model)),
      averager_(units_.nx, units_.ny, units_.blockX, units_.blockY) {
  rules_.model = params.model;
  rules_.seed = static_cast<std::uint64_t>(params.seed);
  rules_.forceProbability = units_.forceProbability;
  rules_.forceDirection = units_.forceDirection;
  buildGeometry();
  for (int y = 0; y < units_.ny; ++y)
    for (int x = 0; x < units_.nx; ++x) fluidNodes_ += lattice_.isSolid(x, y) ? 0.0 : 1.0;
  flipEfficiency_ = params.channel_density * (1.0 - params.channel_density);
  const auto u = units_.flowSpeed;
  fillEquilibrium(lattice_, params.model, params.channel_density,
                  [u](int, int) { return u; }, rules_.seed);
}

// Wall sides are layers of solid nodes (rows 0 and ny - 1, columns 0 and nx - 1); a slip side's
// nodes reflect specularly. Obstacles and rollers: the nodes whose position lies inside the disc.
void FhpSolver::buildGeometry() {
  const int nx = units_.nx, ny = units_.ny;
  const FhpSidesParams& w = params_.walls;
  auto row = [&](int y, SideType side) {
    if (side == SideType::periodic) return;
    for (int x = 0; x < nx; ++x) {
      lattice_.setSolid(x, y, true);
      lattice_.setSlip(x, y, side == SideType::slip);
    }
  };
  auto column = [&](int x, SideType side) {
    if (side == SideType::periodic) return;
    for (int y = 0; y < ny; ++y) lattice_.setSolid(x, y, true);
  };
  column(0, w.x_min.type);
  column(nx - 1, w.x_max.type);
  row(0, w.y_min.type);
  row(ny - 1, w.y_max.type);
  auto disc = [&](const std::array<double, 2>& centre, double radius) {
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        if (std::hypot(nodeX(x, y) - centre[0], nodeY(y) - centre[1]) < radius) {
          lattice_.setSolid(x, y, true);
          lattice_.setSlip(x, y, false);
        }
  };
  for (const FhpObstacleParams& o : params_.obstacles) disc(o.center, o.radius);
  for (const lbm::RollerParams& r : params_.rollers) disc(r.center, r.radius);
  lattice_.setWallMotion(movingWallNodes());
}

double FhpSolver::nodeX(int x, int y) const { return (x + (y % 2 == 1 ? 0.5 : 0.0)) * units_.dx; }
double FhpSolver::nodeY(int y) const { return y * kRowSpacing * units_.dx; }

// The solid nodes next to the fluid on a moving_wall side or a turning roller, each with its wall
// velocity in lattice units: the side's velocity, or omega x (r - centre) at the node's position.
// Where sides meet, a corner node takes the first moving side's velocity (x_min, x_max, y_min,
// y_max); a roller node takes its roller's.
std::vector<WallNodeMotion> FhpSolver::movingWallNodes() const {
  const int nx = units_.nx, ny = units_.ny;
  const WallEquilibrium equilibrium = wallEquilibrium(params_.model, params_.channel_density);
  std::vector<std::array<double, 2>> velocity(static_cast<std::size_t>(nx) * ny);
  std::vector<std::uint8_t> moving(velocity.size(), 0);
  auto set = [&](int x, int y, std::array<double, 2> v) {
    const std::size_t n = static_cast<std::size_t>(y) * nx + x;
    if (moving[n]) return;
    moving[n] = 1;
    velocity[n] = {units_.toLatticeVelocity(v[0]), units_.toLatticeVelocity(v[1])};
  };
  const FhpSidesParams& w = params_.walls;
  const std::array<std::pair<const FhpWallParams*, int>, 4> sides{
      {{&w.x_min, 0}, {&w.x_max, 1}, {&w.y_min, 2}, {&w.y_max, 3}}};
  for (const auto& [side, which] : sides) {
    if (side->type != SideType::moving_wall) continue;
    if (which < 2)
      for (int y = 0; y < ny; ++y) set(which == 0 ? 0 : nx - 1, y, side->velocity);
    else
      for (int x = 0; x < nx; ++x) set(x, which == 2 ? 0 : ny - 1, side->velocity);
  }
  for (const lbm::RollerParams& r : params_.rollers) {
    if (r.angular_velocity == 0.0) continue;
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const double rx = nodeX(x, y) - r.center[0], ry = nodeY(y) - r.center[1];
        if (std::hypot(rx, ry) < r.radius)
          set(x, y, {-r.angular_velocity * ry, r.angular_velocity * rx});
      }
  }
  std::vector<WallNodeMotion> nodes;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const std::size_t n = static_cast<std::size_t>(y) * nx + x;
      if (!moving[n]) continue;
      unsigned fluid = 0;
      for (int c = 0; c < kMovingChannels; ++c) {
        const int tx = (x + neighbourDx(c, y % 2 == 1) + nx) % nx, ty = (y + kDy[c] + ny) % ny;
        if (!lattice_.isSolid(tx, ty)) fluid |= 1u << c;
      }
      if (fluid != 0) nodes.push_back(wallNodeMotion(x, y, velocity[n], fluid, equilibrium));
    }
  return nodes;
}

// The flips need a particle against the force and an empty channel along it: in equilibrium at
// velocity u that happens with N_-(1 - N_+) = d (1 - d) - (rho / 3) c_d . u (Frisch et al. 1987,
// section 4, to first order), so a fixed flip probability gives a force that fades as the flow
// grows (by a fifth at u = 0.07 for d = 1/4). The probability is therefore scaled by d (1 - d)
// over the measured efficiency (flips per node and unit probability, averaged over about 20
// steps), which keeps the momentum input at the scene's body force.
void FhpSolver::adaptForcing(std::uint64_t flips) {
  if (units_.forceProbability <= 0.0) return;
  const double d = params_.channel_density;
  const double efficiency = static_cast<double>(flips) / (rules_.forceProbability * fluidNodes_);
  flipEfficiency_ += 0.05 * (efficiency - flipEfficiency_);
  rules_.forceProbability =
      std::min(1.0, units_.forceProbability * d * (1.0 - d) / std::max(flipEfficiency_, 1e-3));
}

void FhpSolver::step(long long n) {
  for (long long i = 0; i < n; ++i) {
    adaptForcing(lattice_.step(table_, rules_));
    if (params_.inflow_width > 0)
      refillEquilibrium(lattice_, params_.model, params_.channel_density, units_.flowSpeed,
                        rules_.seed, params_.inflow_width);
  }
}

Grid FhpSolver::grid() const { return averager_.fields(units_.dx).grid; }

FieldSet FhpSolver::averagedFields() const {
  BlockAverager now(units_.nx, units_.ny, units_.blockX, units_.blockY);
  const BlockAverager* source = &averager_;
  if (averager_.samples() == 0) {
    now.add(lattice_);
    source = &now;
  }
  FieldSet lattice = source->fields(units_.dx);
  const double perNode = channelCount(params_.model) * params_.channel_density;
  const double c = units_.dx / units_.dt;
  const double cs = soundSpeed(params_.model);
  ScalarField density = *lattice.findScalar("density");
  ScalarField pressure{"pressure", lattice.grid, std::vector<double>(density.values.size(), 0.0)};
  const std::vector<double> fluid = source->fluidFraction();
  for (std::size_t k = 0; k < density.values.size(); ++k) {
    // Solid blocks carry the reference density (p = 0), as the LBM's solid nodes do.
    const double n = fluid[k] > 0.0 ? density.values[k] : perNode;
    density.values[k] = params_.density * n / perNode;
    pressure.values[k] = units_.g * cs * cs * (density.values[k] - params_.density) * c * c;
  }
  VectorField velocity = *lattice.findVector("velocity");
  for (Vec3& v : velocity.values) v *= units_.g * c;
  FieldSet set;
  set.grid = lattice.grid;
  set.add(std::move(density));
  set.add(magnitude(velocity));
  set.add(std::move(velocity));
  set.add(std::move(pressure));
  return set;
}

std::vector<std::uint8_t> FhpSolver::solidBlocks() const {
  BlockAverager geometry(units_.nx, units_.ny, units_.blockX, units_.blockY);
  geometry.add(lattice_);
  std::vector<std::uint8_t> solid;
  for (double f : geometry.fluidFraction()) solid.push_back(f < 0.5 ? 1 : 0);
  return solid;
}

long long FhpSolver::momentumX2() const {
  long long m = 0;
  for (int c = 0; c < kMovingChannels; ++c)
    for (int y = 0; y < units_.ny; ++y)
      for (int w = 0; w < lattice_.wordsPerRow(); ++w)
        m += kCx2[c] * std::popcount(lattice_.word(c, y, w));
  return m;
}

long long FhpSolver::momentumYInt() const {
  long long m = 0;
  for (int c = 0; c < kMovingChannels; ++c)
    for (int y = 0; y < units_.ny; ++y)
      for (int w = 0; w < lattice_.wordsPerRow(); ++w)
        m += kCyInt[c] * std::popcount(lattice_.word(c, y, w));
  return m;
}

// Layout: f64 flip efficiency and probability, u64 step count, the channel planes, i32 samples,
// the averager's sums.
void FhpSolver::saveState(StateWriter& out) const {
  out.put<double>(flipEfficiency_);
  out.put<double>(rules_.forceProbability);
  out.put<std::uint64_t>(lattice_.time());
  out.putVector(lattice_.planes());
  out.put<std::int32_t>(averager_.samples());
  out.putVector(averager_.sums());
}

void FhpSolver::restoreState(StateReader& in) {
  flipEfficiency_ = in.get<double>();
  rules_.forceProbability = in.get<double>();
  const auto time = in.get<std::uint64_t>();
  std::vector<std::uint64_t> planes;
  in.getVector(planes, static_cast<std::int64_t>(lattice_.planes().size()));
  const auto samples = in.get<std::int32_t>();
  std::vector<double> sums;
  in.getVector(sums, static_cast<std::int64_t>(averager_.sums().size()));
  lattice_.restore(std::move(planes), time);
  averager_.restoreSums(sums, samples);
}

}  // namespace fluidviz::fhp
