#include "solvers/sph/SphSolverAdapter.h"

#include <sstream>

#include "fieldviz/core/Params.h"

namespace fluidviz::sph {

namespace {

// Steps between progress reports.
constexpr long long kProgressSteps = 20;

}  // namespace

std::string describeSolver(SphSolver& s) {
  const SphParams& p = s.params();
  const TimeStepLimits limits = s.timeStepLimits();
  std::ostringstream d;
  d << "SPH " << p.dimension << "D model " << choiceName(p.model)
    << (p.model == SphModel::weakly_compressible ? " (" + choiceName(p.kernel) + ")"
                                                 : std::string())
    << ", " << s.fluidCount()
    << " fluid + " << s.boundaryParticles().size() << " boundary particles, dx = "
    << formatNumber(p.particle_spacing, 4) << " m, h = " << formatNumber(s.smoothingLength(), 4)
    << " m, mass = " << formatNumber(s.particleMass(), 4) << " kg\n"
    << "c0 = " << formatNumber(p.speed_of_sound, 4) << " m/s, stable dt at t = 0: " << formatNumber(limits.stable(), 4)
    << " s (" << limits.binding() << "), "
    << (p.time_step ? "fixed time_step = " + formatNumber(*p.time_step, 4) + " s" : std::string("automatic"))
    << ", end_time = " << formatNumber(p.end_time, 4) << " s";
  return d.str();
}

SphSolverAdapter::SphSolverAdapter(std::unique_ptr<SphSolver> solver)
    : solver_(std::move(solver)),
      description_(describeSolver(*solver_)),
      warningsShown_(solver_->warnings().size()) {}

double SphSolverAdapter::targetTime(const RunTarget& target) const {
  const double end = solver_->params().end_time;
  return target.k == target.n ? end : end * target.k / target.n;
}

bool SphSolverAdapter::reached(const RunTarget& target) {
  if (solver_->time() >= targetTime(target) * (1.0 - 1e-12)) return true;
  if (solver_->stepCount() < solver_->params().max_steps) return false;
  stopReason_ = "max_steps (" + std::to_string(solver_->params().max_steps) + ") reached";
  return true;
}

std::optional<SolverProgress> SphSolverAdapter::advance(const RunTarget& target) {
  solver_->step(targetTime(target) - solver_->time());
  if (solver_->stepCount() % kProgressSteps != 0) return std::nullopt;
  SolverProgress p = progress();
  p.detail += ", dt = " + formatNumber(solver_->lastTimeStep(), 4) + " s";
  return p;
}

std::string SphSolverAdapter::position() const {
  return "t = " + formatNumber(solver_->time(), 4) + " s, step " + std::to_string(solver_->stepCount());
}

SolverProgress SphSolverAdapter::progress() const {
  return {solver_->time() / solver_->params().end_time, position()};
}

std::vector<std::string> SphSolverAdapter::takeWarnings() {
  const std::vector<std::string>& all = solver_->warnings();
  std::vector<std::string> fresh(all.begin() + static_cast<long>(warningsShown_), all.end());
  warningsShown_ = all.size();
  return fresh;
}

std::string SphSolverAdapter::summary() const {
  return stopReason_ + ": t = " + formatNumber(solver_->time(), 4) + " s after " +
         std::to_string(solver_->stepCount()) + " steps";
}

std::vector<std::string> SphSolverAdapter::closingWarnings() const {
  if (!solver_->stableLimitExceeded()) return {};
  return {std::to_string(solver_->stepsPastStableLimit()) +
          " steps exceeded the stable time-step limit"};
}

// Layout of checkpoint format version 1 (pipeline/Checkpoint.h): after the loop's snapshot
// count, the stop reason, then the solver.
void SphSolverAdapter::saveState(StateWriter& w) const {
  w.putString(stopReason_);
  solver_->saveState(w);
}

void SphSolverAdapter::restoreState(StateReader& r) {
  stopReason_ = r.getString();
  solver_->restoreState(r);
  warningsShown_ = solver_->warnings().size();  // the run being resumed showed them
}

}  // namespace fluidviz::sph
