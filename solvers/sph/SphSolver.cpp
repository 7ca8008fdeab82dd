#include "solvers/sph/SphSolver.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "solvers/sph/EquationOfStateTait.h"
#include "fieldviz/particles/KernelsMuller2003.h"
#include "fieldviz/particles/Parallel.h"

namespace fluidviz::sph {

namespace {

std::string num(double x, int digits = 4) { return formatNumber(x, digits); }

const char* sideName(int side) {
  static const char* names[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  return names[side];
}

const SphParams& validated(const SphParams& p) {
  validateSphParams(p);
  return p;
}

// Model A: the mass for which the poly6 summation (with self) on the initial lattice gives
// rest_density exactly (the discrete sum differs from the kernel's integral by several percent
// at h / dx ~ 1.3, which would start the fluid compressed).
double latticeCalibratedMass(const SphParams& p) {
  const particles::KernelPoly6 poly6(p.smoothing_length_ratio * p.particle_spacing, p.dimension);
  const double dx = p.particle_spacing;
  const int n = static_cast<int>(std::ceil(poly6.support() / dx));
  double sum = 0.0;
  for (int k = (p.dimension == 3 ? -n : 0); k <= (p.dimension == 3 ? n : 0); ++k)
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) sum += poly6.W(dx * std::sqrt(double(i * i + j * j + k * k)));
  return p.rest_density / sum;
}

ModelConstants modelConstants(const SphParams& p) {
  ModelConstants c;
  c.dimension = p.dimension;
  c.h = p.smoothing_length_ratio * p.particle_spacing;
  c.spacing = p.particle_spacing;
  c.mass = p.model == SphModel::muller2003 ? latticeCalibratedMass(p)
                          : p.rest_density * std::pow(p.particle_spacing, p.dimension);
  c.rho0 = p.rest_density;
  c.c0 = p.speed_of_sound;
  c.gamma = p.eos_exponent;
  c.nu = p.viscosity;
  c.alpha = p.alpha;
  c.beta = p.beta;
  c.xsphEpsilon = p.xsph_epsilon;
  c.cohesion = p.cohesion;
  c.densityDiffusion = p.model == SphModel::weakly_compressible ? p.density_diffusion : 0.0;
  c.surfaceTension = p.surface_tension;
  c.surfaceThreshold = p.surface_threshold;
  c.gravity = sceneVector(p.gravity, p.dimension);
  c.hydrostaticGravity = c.gravity;
  for (int a = 0; a < p.dimension; ++a)
    if (sideType(p.walls, 2 * a) == SphSide::periodic) c.hydrostaticGravity[a] = 0.0;
  c.wallPressure = p.model == SphModel::weakly_compressible && p.wall_pressure == WallPressure::adami2012;
  c.repulsion = {boundaryStrength(p), boundaryRange(p), p.boundary_exponents[0],
                 p.boundary_exponents[1]};
  return c;
}

// Boundary layers covering the kernel support 2h.
int boundaryLayers(const SphParams& p) {
  return static_cast<int>(std::ceil(2.0 * p.smoothing_length_ratio - 1e-9));
}

// Search box: the domain plus the wall layers on non-periodic axes.
particles::UniformGridNeighborSearch makeSearch(const SphParams& p) {
  const int dim = p.dimension;
  const double h = p.smoothing_length_ratio * p.particle_spacing;
  const double margin = (boundaryLayers(p) + 1) * p.particle_spacing;
  Vec3 lo = sceneVector(p.domain_lower, dim), hi = sceneVector(p.domain_upper, dim);
  std::array<bool, 3> periodic{false, false, false};
  for (int a = 0; a < dim; ++a) {
    periodic[a] = sideType(p.walls, 2 * a) == SphSide::periodic;
    if (!periodic[a]) lo[a] -= margin, hi[a] += margin;
  }
  return particles::UniformGridNeighborSearch(dim, lo, hi, 2.0 * h, periodic);
}

}  // namespace

SphSolver::SphSolver(const SphParams& params)
    : params_(validated(params)),
      constants_(modelConstants(params_)),
      boundary_(makeBoundaryParticles(params_, boundaryLayers(params_))),
      search_(makeSearch(params_)) {
  const std::vector<Vec3> x = makeFluidParticles(params_, boundary_);
  if (x.empty())
    throw ParamError("fluid_blocks", "hold no fluid particle outside the obstacles and rollers; "
                                     "enlarge the blocks or reduce particle_spacing");
  state_.resize(x.size());
  state_.x = x;
  std::fill(state_.v.begin(), state_.v.end(), Vec3::Zero());
  initialDensity();
}

// Model B: each block's own hydrostatic column p = rho0 |g| depth (Tait inverted), or rho0.
// Gravity along periodic axes is not balanced by pressure and is left out.
void SphSolver::initialDensity() {
  std::fill(state_.rho.begin(), state_.rho.end(), params_.rest_density);
  const double g = constants_.hydrostaticGravity.norm();
  if (params_.model != SphModel::weakly_compressible || params_.initial_pressure != InitialPressure::hydrostatic || g == 0.0) return;
  const EquationOfStateTait eos(constants_.rho0, constants_.c0, constants_.gamma);
  const Vec3 down = constants_.hydrostaticGravity / g;
  for (std::size_t i = 0; i < state_.size(); ++i) {
    double depth = 0.0;  // below the top of the deepest block containing the particle
    for (const SphBoxParams& b : params_.fluid_blocks) {
      const Vec3 lo = sceneVector(b.lower, params_.dimension), hi = sceneVector(b.upper, params_.dimension);
      if (((state_.x[i] - lo).array() < 0).any() || ((hi - state_.x[i]).array() < 0).any())
        continue;
      double top = down.dot(state_.x[i]);  // smallest 'down' coordinate over the corners
      for (int c = 0; c < 8; ++c) {
        const Vec3 corner((c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]);
        top = std::min(top, down.dot(corner));
      }
      depth = std::max(depth, down.dot(state_.x[i]) - top);
    }
    state_.rho[i] = eos.density(constants_.rho0 * g * depth);
  }
}

void SphSolver::setFluidParticles(std::vector<Vec3> positions, std::vector<Vec3> velocities) {
  if (steps_ > 0)
    throw std::invalid_argument("SphSolver::setFluidParticles: only before the first step");
  if (!velocities.empty() && velocities.size() != positions.size())
    throw std::invalid_argument("SphSolver::setFluidParticles: " +
                                std::to_string(velocities.size()) + " velocities for " +
                                std::to_string(positions.size()) + " positions");
  if (positions.empty())
    throw std::invalid_argument("SphSolver::setFluidParticles: no particles");
  state_.resize(positions.size());
  state_.x = std::move(positions);
  if (velocities.empty())
    std::fill(state_.v.begin(), state_.v.end(), Vec3::Zero());
  else
    state_.v = std::move(velocities);
  std::fill(state_.rho.begin(), state_.rho.end(), params_.rest_density);
  ratesValid_ = false;
}

void SphSolver::rebuildNeighbors() {
  const std::size_t nf = state_.size();
  allPoints_.resize(nf + boundary_.size());
  std::copy(state_.x.begin(), state_.x.end(), allPoints_.begin());
  std::copy(boundary_.positions.begin(), boundary_.positions.end(), allPoints_.begin() + nf);
  search_.build(allPoints_);
  search_.neighborLists(nf, 2.0 * constants_.h, lists_);
  if (constants_.wallPressure)
    search_.neighborLists(nf, allPoints_.size(), 2.0 * constants_.h, boundaryLists_, nf);
}

void SphSolver::evaluateRates() {
  rebuildNeighbors();
  computeForces();
}

void SphSolver::computeForces() {
  const Interactions in{lists_, search_, boundary_, state_.size(),
                        constants_.wallPressure ? &boundaryLists_ : nullptr};
  if (params_.model == SphModel::muller2003)
    computeRatesMuller2003(constants_, in, state_);
  else
    computeRatesWeaklyCompressible(params_.kernel, constants_, in, state_);
  ratesValid_ = true;
}

// Model B: d rho/dt at the current positions and neighbour lists, with velocities v.
void SphSolver::densityRate(const std::vector<Vec3>& v, std::vector<double>& drho) const {
  const Interactions in{lists_, search_, boundary_, state_.size(), nullptr};
  drho.resize(state_.size());
  computeDensityRateWeaklyCompressible(params_.kernel, constants_, in, state_.x, v, state_.rho,
                                       drho);
}

TimeStepLimits SphSolver::timeStepLimits() {
  if (!ratesValid_) evaluateRates();
  double v2 = 0.0, a2 = 0.0, rhoMax = constants_.rho0;
  for (std::size_t i = 0; i < state_.size(); ++i) {
    v2 = std::max(v2, state_.v[i].squaredNorm());
    a2 = std::max(a2, state_.a[i].squaredNorm());
    rhoMax = std::max(rhoMax, state_.rho[i]);
  }
  for (const Vec3& vb : boundary_.velocities) v2 = std::max(v2, vb.squaredNorm());
  const double cMax = params_.model == SphModel::weakly_compressible
                          ? EquationOfStateTait(constants_.rho0, constants_.c0, constants_.gamma)
                                .soundSpeed(rhoMax)
                          : constants_.c0;
  const TimeStepFactors f{params_.cfl_factor, params_.viscous_factor, params_.force_factor};
  return sph::timeStepLimits(f, constants_.h, cMax, std::sqrt(v2), constants_.nu, std::sqrt(a2));
}

double SphSolver::chooseTimeStep(double maxDt) {
  const TimeStepLimits limits = timeStepLimits();
  const double stable = limits.stable();
  if (params_.time_step) {
    if (*params_.time_step > stable * (1.0 + 1e-12)) {
      if (stepsPastLimit_++ == 0)
        warnings_.push_back("time_step " + num(*params_.time_step) + " s exceeds the stable "
                            "limit " + num(stable) + " s (" + limits.binding() + " condition) "
                            "at step " + std::to_string(steps_) + ", t = " + num(time_) +
                            " s; lower time_step or leave it unset for the automatic step");
    }
    return std::min(*params_.time_step, maxDt);
  }
  const double floor =
      params_.min_step_fraction * params_.cfl_factor * constants_.h / constants_.c0;
  if (stable < floor) {
    std::size_t worst = 0;
    for (std::size_t i = 1; i < state_.size(); ++i)
      if (state_.a[i].squaredNorm() > state_.a[worst].squaredNorm()) worst = i;
    fail(steps_, time_, worst, "time step collapsed",
         "the automatic time step " + num(stable) + " s (" + limits.binding() +
             " condition) fell below min_step_fraction * cfl_factor h / c0 = " + num(floor) +
             " s; |a| = " + num(state_.a[worst].norm()) +
             " m/s^2 there (a particle overlapping a wall or another particle?): start particles "
             "at least one particle_spacing from walls, or lower boundary_strength");
  }
  return std::min(stable, maxDt);
}

// First half kick: v+ = v + dt/2 a(n).
void SphSolver::halfKick(double dt) {
  const std::int64_t n = static_cast<std::int64_t>(state_.size());
  vHalf_.resize(n);
#pragma omp parallel for schedule(static) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) vHalf_[i] = state_.v[i] + 0.5 * dt * state_.a[i];
}

// Drift: x(n+1) = x + dt (v+ + xsph). state_.v becomes the predicted v(n+1) = v+ + dt/2 a(n),
// used only by the velocity-dependent forces of the next evaluation.
void SphSolver::drift(double dt) {
  const std::int64_t n = static_cast<std::int64_t>(state_.size());
#pragma omp parallel for schedule(static) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    state_.x[i] += dt * (vHalf_[i] + state_.xsph[i]);
    state_.v[i] = vHalf_[i] + 0.5 * dt * state_.a[i];
  }
}

// Model B: rho(n+1) = rho(n) + dt/2 (D(x(n), v+) + D(x(n+1), v+)), D the continuity rate.
void SphSolver::driftDensity(double dt, const std::vector<double>& rateAtStart) {
  std::vector<double>& rateAtEnd = state_.drho;
  densityRate(vHalf_, rateAtEnd);
  const std::int64_t n = static_cast<std::int64_t>(state_.size());
#pragma omp parallel for schedule(static) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i)
    state_.rho[i] += 0.5 * dt * (rateAtStart[i] + rateAtEnd[i]);
}

// Second half kick with the new accelerations: v(n+1) = v+ + dt/2 a(n+1).
void SphSolver::finishKick(double dt, const std::vector<Vec3>& vHalf) {
  const std::int64_t n = static_cast<std::int64_t>(state_.size());
#pragma omp parallel for schedule(static) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) state_.v[i] = vHalf[i] + 0.5 * dt * state_.a[i];
}

// Periodic sides wrap; model A walls reflect (Mueller 2003: collision with the container),
// keeping `restitution` of the normal speed.
void SphSolver::applyDomainSides(std::vector<Vec3>& vHalf) {
  const int dim = params_.dimension;
  const bool reflect = params_.model == SphModel::muller2003;
  const std::int64_t n = static_cast<std::int64_t>(state_.size());
#pragma omp parallel for schedule(static) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    Vec3& x = state_.x[i];
    Vec3& v = state_.v[i];
    Vec3& vh = vHalf[i];
    for (int a = 0; a < dim; ++a) {
      const double lo = params_.domain_lower[a], hi = params_.domain_upper[a];
      const SphSide tlo = sideType(params_.walls, 2 * a);
      if (tlo == SphSide::periodic) {
        x[a] -= (hi - lo) * std::floor((x[a] - lo) / (hi - lo));
        continue;
      }
      if (!reflect) continue;
      if (tlo == SphSide::wall && x[a] < lo) {
        x[a] = std::min(lo + (lo - x[a]), hi);
        if (v[a] < 0) v[a] = -params_.restitution * v[a];
        if (vh[a] < 0) vh[a] = -params_.restitution * vh[a];
      }
      if (sideType(params_.walls, 2 * a + 1) == SphSide::wall && x[a] > hi) {
        x[a] = std::max(hi - (x[a] - hi), lo);
        if (v[a] > 0) v[a] = -params_.restitution * v[a];
        if (vh[a] > 0) vh[a] = -params_.restitution * vh[a];
      }
    }
  }
}

double SphSolver::step(double maxDt) {
  if (steps_ == 0) checkStartInsideDomain();
  const double dt = chooseTimeStep(maxDt);  // evaluates the rates if needed
  const FluidState backup = state_;
  const double t0 = time_;
  const bool continuity = params_.model == SphModel::weakly_compressible;
  halfKick(dt);
  if (continuity) densityRate(vHalf_, rateAtStart_);  // D(x(n), v+), lists of x(n)
  drift(dt);
  applyDomainSides(vHalf_);
  boundary_.moveTo(t0 + dt);
  try {
    rebuildNeighbors();
    if (continuity) driftDensity(dt, rateAtStart_);
    computeForces();
    finishKick(dt, vHalf_);
    checkState(steps_, t0);
  } catch (const InstabilityError&) {
    state_ = backup;
    boundary_.moveTo(t0);
    ratesValid_ = false;
    throw;
  }
  time_ = t0 + dt;
  lastDt_ = dt;
  ++steps_;
  return dt;
}

SphStopReason SphSolver::advance(double targetTime) {
  const double target = std::min(targetTime, params_.end_time);
  while (time_ < target * (1.0 - 1e-12)) {
    if (steps_ >= params_.max_steps) return SphStopReason::MaxSteps;
    const double remaining = target - time_;
    step(remaining);
    if (target - time_ < 1e-12 * std::max(1.0, target)) time_ = target;
  }
  return targetTime >= params_.end_time ? SphStopReason::EndTime : SphStopReason::ReachedTime;
}

void SphSolver::fail(long long step, double time, std::size_t i, const std::string& reason,
                     const std::string& detail) const {
  const Vec3 x = i < state_.size() ? state_.x[i] : Vec3::Zero();
  throw InstabilityError(step, time, static_cast<long long>(i), x, reason,
                         "SPH unstable at step " + std::to_string(step) + ", t = " + num(time) +
                             " s, particle " + std::to_string(i) + ": " + reason + ": " + detail);
}

// Fluid particles given outside the box (e.g. inside a wall) cannot be pushed back in.
void SphSolver::checkStartInsideDomain() const {
  for (std::size_t i = 0; i < state_.size(); ++i)
    for (int side = 0; side < 2 * params_.dimension; ++side) {
      const int a = side / 2;
      const double x = state_.x[i][a];
      const bool out = side % 2 == 0 ? x < params_.domain_lower[a] : x > params_.domain_upper[a];
      if (out && sideType(params_.walls, side) != SphSide::periodic)
        fail(0, 0.0, i, "left domain",
             std::string("starts outside the domain, beyond side ") + sideName(side) +
                 " (inside the wall or past an open side); place fluid particles inside the "
                 "domain box");
    }
}

void SphSolver::checkState(long long step, double time) const {
  const int dim = params_.dimension;
  const double rho0 = params_.rest_density, tol = 1e-9 * params_.particle_spacing;
  for (std::size_t i = 0; i < state_.size(); ++i) {
    const Vec3& x = state_.x[i];
    if (!x.allFinite() || !state_.v[i].allFinite() || !std::isfinite(state_.rho[i]) ||
        !state_.a[i].allFinite())
      fail(step, time, i, "NaN",
           "non-finite position, velocity, acceleration or density; lower time_step or "
           "cfl_factor, or raise speed_of_sound");
    for (int side = 0; side < 2 * dim; ++side) {
      const int a = side / 2;
      const bool out = side % 2 == 0 ? x[a] < params_.domain_lower[a] - tol
                                     : x[a] > params_.domain_upper[a] + tol;
      if (!out || sideType(params_.walls, side) == SphSide::periodic) continue;
      const bool open = sideType(params_.walls, side) == SphSide::open;
      fail(step, time, i, "left domain",
           std::string("crossed the ") + (open ? "open side " : "wall ") + sideName(side) +
               " at x = [" + num(x[0]) + ", " + num(x[1]) + ", " + num(x[2]) + "] m; " +
               (open ? "enlarge the domain or make the side a wall"
                     : "lower time_step or cfl_factor, or raise boundary_strength"));
    }
    const double err = state_.rho[i] / rho0 - 1.0;
    const bool tooDense = params_.model == SphModel::muller2003 ? err > params_.max_density_error
                                               : std::abs(err) > params_.max_density_error;
    if (tooDense || !(state_.rho[i] > 0))
      fail(step, time, i, "density error",
           "density " + num(state_.rho[i]) + " kg/m^3 is " + num(100 * err, 3) +
               "% off rest_density, past max_density_error " +
               num(100 * params_.max_density_error, 3) + "%: raise speed_of_sound (now " +
               num(params_.speed_of_sound) + " m/s; about 10x the fastest flow speed)");
  }
}

double SphSolver::fluidVolume() const {
  double v = 0.0;
  for (double rho : state_.rho) v += constants_.mass / rho;
  return v;
}

particles::ParticleSet SphSolver::fluid() const {
  particles::ParticleSet s;
  s.dimension = params_.dimension;
  s.positions = state_.x;
  s.vectors.push_back({"velocity", state_.v});
  s.scalars.push_back({"density", state_.rho});
  std::vector<double> p = state_.p;
  if (!ratesValid_ && params_.model == SphModel::weakly_compressible) {  // before the first evaluation
    const EquationOfStateTait eos(constants_.rho0, constants_.c0, constants_.gamma);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = eos.pressure(state_.rho[i]);
  }
  s.scalars.push_back({"pressure", std::move(p)});
  return s;
}

particles::ParticleSet SphSolver::boundary() const {
  particles::ParticleSet s;
  s.dimension = params_.dimension;
  s.positions = boundary_.positions;
  s.vectors.push_back({"velocity", boundary_.velocities});
  return s;
}

}  // namespace fluidviz::sph
