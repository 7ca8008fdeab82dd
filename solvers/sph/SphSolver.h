#pragma once
// SPH solver in 2D and 3D: model A (Mueller et al. 2003) or model B (weakly compressible,
// Monaghan 1994 / Morris et al. 1997); see SphParams.h, SphModels.h and the one-method headers.
//
//   construction: validate SphParams (ParamError), lay fluid and boundary particles on the
//                 lattice, model B: initial density hydrostatic or rho0
//   step():       kick-drift-kick leapfrog (Stoermer-Verlet) in which the density of model B
//                 drifts like a position, time-symmetrically, so that the acoustic pair
//                 (rho, v) neither gains nor loses energy (a predictor-corrector on rho pumps
//                 energy into sound waves at CFL 0.25; a one-sided drift loses 8% per 1000
//                 steps):
//                   v+ = v + dt/2 a(n)
//                   x(n+1) = x + dt (v+ + xsph)
//                   rho(n+1) = rho + dt/2 (D(x(n), v+) + D(x(n+1), v+))   (model B, D = continuity)
//                   a(n+1) from x(n+1), rho(n+1) and, for the viscous terms, the predicted
//                   v+ + dt/2 a(n)
//                   v(n+1) = v+ + dt/2 a(n+1)
//                 Model B costs three neighbour passes per step (two continuity, one force),
//                 model A two (density, force); one neighbour rebuild each.
//                 periodic sides wrap; model A walls reflect; rollers turn rigidly.
//   time step:    automatic min(CFL, viscous, force) (TimeStepControl.h) or fixed; a fixed step
//                 past the stable limit is reported in warnings() / stableLimitExceeded().
//   checks:       after every step: NaN, a particle outside the domain, density error past
//                 max_density_error; before it: an automatic step collapsing. Each throws
//                 InstabilityError and leaves the particles at the last good state.
// Nothing is printed.
#include <limits>
#include <string>
#include <vector>

#include "fieldviz/core/StateBytes.h"
#include "solvers/sph/BoundaryParticles.h"
#include "solvers/sph/InstabilityError.h"
#include "fieldviz/particles/ParticleSet.h"
#include "solvers/sph/SphModels.h"
#include "solvers/sph/SphParams.h"
#include "solvers/sph/TimeStepControl.h"
#include "fieldviz/particles/UniformGridNeighborSearch.h"

namespace fluidviz::sph {

/// Why advance() returned.
enum class SphStopReason {
  ReachedTime,  ///< the requested time was reached
  EndTime,      ///< params.end_time reached
  MaxSteps,     ///< params.max_steps reached
};

class SphSolver {
 public:
  /// Validates params (ParamError with the key relative to SphParams) and lays out particles.
  explicit SphSolver(const SphParams& params);

  /// Replaces the fluid particles (before the first step): positions (m), optional velocities
  /// (m/s; empty = at rest). Density starts at rho0. Throws std::invalid_argument on size
  /// mismatch or if called after stepping.
  void setFluidParticles(std::vector<Vec3> positions, std::vector<Vec3> velocities = {});

  /// One time step (automatic, or the fixed params.time_step), never longer than maxDt.
  /// Returns the step taken (s). Throws InstabilityError.
  double step(double maxDt = std::numeric_limits<double>::infinity());
  /// Steps until time() reaches targetTime exactly (at most end_time, max_steps).
  SphStopReason advance(double targetTime);
  SphStopReason run() { return advance(params_.end_time); }

  double time() const { return time_; }         ///< s
  long long stepCount() const { return steps_; }
  double lastTimeStep() const { return lastDt_; }  ///< s
  /// Stability limits at the current state (evaluates the rates if needed).
  TimeStepLimits timeStepLimits();

  /// true once a fixed time step exceeded the stable limit; warnings() says when and by how
  /// much (one message, at the first occurrence).
  bool stableLimitExceeded() const { return stepsPastLimit_ > 0; }
  long long stepsPastStableLimit() const { return stepsPastLimit_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// Fluid particles: positions; scalars "density" (kg/m^3), "pressure" (Pa); vectors
  /// "velocity" (m/s). Before the first step: the initial density (model A: rest_density) and
  /// its pressure.
  particles::ParticleSet fluid() const;
  /// Boundary particles: positions; vectors "velocity" (m/s).
  particles::ParticleSet boundary() const;

  /// Everything step() evolves (particles with the rates of the last evaluation, boundary
  /// positions, time, step counts, warnings) for a checkpoint; restoreState on a solver built
  /// from the same params continues bit-identically. restoreState throws StateFormatError on a
  /// state of another dimension or particle count (SphSolverState.cpp).
  void saveState(StateWriter& out) const;
  void restoreState(StateReader& in);

  const SphParams& params() const { return params_; }
  const FluidState& state() const { return state_; }
  const BoundaryParticles& boundaryParticles() const { return boundary_; }
  std::size_t fluidCount() const { return state_.size(); }
  double particleMass() const { return constants_.mass; }  ///< kg
  double smoothingLength() const { return constants_.h; }  ///< m
  /// Fluid volume sum_i m / rho_i (m^3 in 3D, m^2 in 2D).
  double fluidVolume() const;

 private:
  void evaluateRates();
  void computeForces();
  void densityRate(const std::vector<Vec3>& v, std::vector<double>& drho) const;
  void driftDensity(double dt, const std::vector<double>& rateAtStart);
  void rebuildNeighbors();
  double chooseTimeStep(double maxDt);
  void halfKick(double dt);
  void drift(double dt);
  void finishKick(double dt, const std::vector<Vec3>& vHalf);
  void applyDomainSides(std::vector<Vec3>& vHalf);
  void checkState(long long step, double time) const;
  void checkStartInsideDomain() const;
  [[noreturn]] void fail(long long step, double time, std::size_t i, const std::string& reason,
                         const std::string& detail) const;
  void initialDensity();

  SphParams params_;
  ModelConstants constants_;
  BoundaryParticles boundary_;
  FluidState state_;
  particles::UniformGridNeighborSearch search_;
  particles::NeighborLists lists_;          ///< neighbours of each fluid particle (fluid and boundary)
  particles::NeighborLists boundaryLists_;  ///< fluid neighbours of each boundary particle (wall pressure)
  std::vector<Vec3> allPoints_;  ///< fluid then boundary positions (the searched set)
  std::vector<Vec3> vHalf_;          ///< v(n+1/2) during a step
  std::vector<double> rateAtStart_;  ///< model B: continuity rate at x(n) during a step
  bool ratesValid_ = false;
  double time_ = 0.0;
  long long steps_ = 0;
  double lastDt_ = 0.0;
  long long stepsPastLimit_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace fluidviz::sph
