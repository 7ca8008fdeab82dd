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
// nodes reflect specularly. Obstacles: the nodes whose position lies inside the disc.
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
  column(0, w.x_min);
  column(nx - 1, w.x_max);
  row(0, w.y_min);
  row(ny - 1, w.y_max);
  for (const FhpObstacleParams& o : params_.obstacles)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const double px = (x + (y % 2 == 1 ? 0.5 : 0.0)) * units_.dx;
        const double py = y * kRowSpacing * units_.dx;
        if (std::hypot(px - o.center[0], py - o.center[1]) < o.radius) {
          lattice_.setSolid(x, y, true);
          lattice_.setSlip(x, y, false);
        }
      }
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
