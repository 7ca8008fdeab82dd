#include "solvers/lbm/LbmSolverAdapter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fluidviz::lbm {

double relativeVelocityChange(const std::vector<Vec3>& before, const std::vector<Vec3>& after) {
  double change = 0.0, scale = 0.0;
  for (std::size_t n = 0; n < after.size(); ++n) {
    change = std::max(change, (after[n] - before[n]).norm());
    scale = std::max(scale, after[n].norm());
  }
  return scale > 0 ? change / scale : change;
}

std::string describeUnits(const LatticeUnits& u, const LbmParams& p) {
  std::ostringstream s;
  s.precision(4);
  s << "lattice " << u.nx << " x " << u.ny << (u.nz > 1 ? " x " + std::to_string(u.nz) : "")
    << " nodes, dx = " << u.dx << " m, dt = " << u.dt << " s\n"
    << "tau = " << u.tau;
  if (u.tauMinus != u.tau) s << " (TRT tau- = " << u.tauMinus << ")";
  if (u.latticeVelocity > 0.0) {
    s << ", lattice velocity = " << u.latticeVelocity << ", Mach = " << u.mach
      << ", lattice viscosity = " << u.latticeViscosity << ", Reynolds = " << u.reynolds;
  } else {
    s << ", lattice viscosity = " << u.latticeViscosity
      << "; no wall, roller or inlet sets a speed (the flow is driven)";
    const double peak = drivenChannelPeakSpeed(p, u);
    if (peak > 0.0 && !p.rollers.empty()) {
      s << "\nthe flow's speed follows from the drag on the rollers/cylinders (the unobstructed "
           "channel would reach " << peak << " m/s): watch the run's maximum speed";
    } else if (peak > 0.0) {
      const double lattice = u.toLatticeVelocity(peak);
      s << "\nplane-Poiseuille estimate of the peak speed a H^2 / (8 nu) = " << peak
        << " m/s: lattice velocity " << lattice << ", Mach "
        << lattice * std::sqrt(3.0) << ", Reynolds U_mean H / nu = "
        << (2.0 / 3.0) * peak * p.domain_size[1] / u.viscosity;
    }
  }
  // The lattice's sound speed dx / (sqrt(3) dt) is an artefact of dt: what matters is how long
  // a pressure wave from a sudden start takes to cross the box (WallParams::ramp_time).
  const double soundSpeed = u.dx / (std::sqrt(3.0) * u.dt);
  s << "\nlattice sound speed c_s = dx / (sqrt(3) dt) = " << soundSpeed
    << " m/s: a pressure wave crosses Lx in " << p.domain_size[0] / soundSpeed << " s";
  const long long steps = plannedSteps(p, u);
  s << "\nsteps: " << steps << (steps == p.max_steps ? " (max_steps)" : " (end_time / dt)")
    << ", " << static_cast<double>(steps) * static_cast<double>(u.nodeCount())
    << " node updates" << (p.steady_tolerance > 0 ? "; steady_tolerance may stop it earlier" : "");
  return s.str();
}

LbmSolverAdapter::LbmSolverAdapter(std::unique_ptr<LbmSolver> solver)
    : solver_(std::move(solver)),
      totalSteps_(plannedSteps(solver_->params(), solver_->units())),
      // A few million node updates: well under a second.
      sliceSteps_(std::max<long long>(
          1, 4'000'000 / std::max<long long>(1, solver_->fluidNodeCount()))),
      steadyCheck_(solver_->params().steady_tolerance > 0) {
  if (steadyCheck_) lastVelocity_ = solver_->fields().findVector("velocity")->values;
}

long long LbmSolverAdapter::targetStep(const RunTarget& target) const {
  return (totalSteps_ * target.k + target.n - 1) / target.n;  // ceil(k N / n)
}

long long LbmSolverAdapter::stepsToSample(const RunTarget& target) const {
  const double steps = target.sampleTime / solver_->units().dt;
  if (!(steps < 1e18)) return std::numeric_limits<long long>::max();
  // The first step at or after the sample time (1e-9: a time k dt computed as k * interval).
  const long long sampleStep = static_cast<long long>(std::ceil(steps - 1e-9));
  return std::max(1LL, sampleStep - solver_->stepCount());
}

bool LbmSolverAdapter::reached(const RunTarget& target) {
  return steady_ || solver_->stepCount() >= targetStep(target);
}

std::optional<SolverProgress> LbmSolverAdapter::advance(const RunTarget& target) {
  const long long step = solver_->stepCount();
  const long long chunkEnd = std::min(step + solver_->params().check_interval - sinceCheck_,
                                      targetStep(target));
  const long long n = std::min({sliceSteps_, chunkEnd - step, stepsToSample(target)});
  if (n <= 0) return std::nullopt;
  solver_->step(static_cast<int>(n));
  sinceCheck_ += n;
  if (step + n < chunkEnd) return std::nullopt;
  runChecks();
  if (reached(target)) return std::nullopt;  // the loop reports it after the snapshot
  return progress();
}

// At every check_interval steps and every target: stability, then the steady-state criterion.
void LbmSolverAdapter::runChecks() {
  solver_->checkStability();
  if (sinceCheck_ >= solver_->params().check_interval) sinceCheck_ = 0;
  if (!steadyCheck_ || sinceCheck_ != 0) return;
  const FieldSet now = solver_->fields();
  const std::vector<Vec3>& velocity = now.findVector("velocity")->values;
  change_ = relativeVelocityChange(lastVelocity_, velocity);
  lastVelocity_ = velocity;
  steady_ = change_ < solver_->params().steady_tolerance;
}

std::string LbmSolverAdapter::position() const {
  std::ostringstream s;
  s << "t = " << solver_->time() << " s, step " << solver_->stepCount();
  return s.str();
}

SolverProgress LbmSolverAdapter::progress() const {
  std::ostringstream detail;
  detail.precision(4);
  detail << "t = " << solver_->time() << " s, step " << solver_->stepCount();
  if (std::isfinite(change_)) detail << ", change " << change_;
  return {static_cast<double>(solver_->stepCount()) / static_cast<double>(totalSteps_),
          detail.str()};
}

std::string LbmSolverAdapter::summary() const {
  std::ostringstream end;
  end.precision(5);
  end << (steady_ ? "steady state reached at t = " : "reached t = ") << solver_->time()
      << " s after " << solver_->stepCount() << " steps";
  return end.str();
}

// Layout of checkpoint format version 1 (pipeline/Checkpoint.h): after the loop's snapshot
// count, i64 steps since the check, f64 change, u8 steady, the reference velocity, the solver.
void LbmSolverAdapter::saveState(StateWriter& w) const {
  w.put<std::int64_t>(sinceCheck_);
  w.put<double>(change_);
  w.put<std::uint8_t>(steady_ ? 1 : 0);
  w.putVec3s(lastVelocity_);
  solver_->saveState(w);
}

void LbmSolverAdapter::restoreState(StateReader& r) {
  sinceCheck_ = r.get<std::int64_t>();
  change_ = r.get<double>();
  steady_ = r.get<std::uint8_t>() != 0;
  r.getVec3s(lastVelocity_);
  const std::size_t nodes = steadyCheck_ ? solver_->grid().nodeCount() : 0;
  if (lastVelocity_.size() != nodes)
    throw StateFormatError("the steady-state reference holds " +
                           std::to_string(lastVelocity_.size()) + " nodes");
  solver_->restoreState(r);
}

}  // namespace fluidviz::lbm
