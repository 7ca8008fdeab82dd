#include "solvers/fhp/FhpSolverAdapter.h"

#include <algorithm>
#include <sstream>

namespace fluidviz::fhp {

FhpSolverAdapter::FhpSolverAdapter(std::unique_ptr<FhpSolver> solver)
    : solver_(std::move(solver)),
      // About 3e7 node updates (64 per word operation): well under a second.
      sliceSteps_(std::max<long long>(1, 30'000'000 / (static_cast<long long>(solver_->units().nx) *
                                                        solver_->units().ny))) {}

long long FhpSolverAdapter::targetStep(const RunTarget& target) const {
  return (solver_->units().steps * target.k + target.n - 1) / target.n;  // ceil(k N / n)
}

bool FhpSolverAdapter::reached(const RunTarget& target) {
  return solver_->stepCount() >= targetStep(target);
}

std::optional<SolverProgress> FhpSolverAdapter::advance(const RunTarget& target) {
  if (windowTarget_ != target.k) {
    solver_->clearAverage();
    windowTarget_ = target.k;
  }
  const long long step = solver_->stepCount(), end = targetStep(target);
  const long long windowStart = end - solver_->params().average_steps;  // first sampled: +1
  if (step < windowStart) {
    solver_->step(std::min(sliceSteps_, windowStart - step));
  } else {
    const long long n = std::min(sliceSteps_, end - step);
    for (long long i = 0; i < n; ++i) {
      solver_->step(1);
      solver_->sampleAverage();
    }
  }
  if (reached(target)) return std::nullopt;  // the loop reports it after the snapshot
  return progress();
}

std::string FhpSolverAdapter::position() const {
  std::ostringstream s;
  s << "t = " << solver_->time() << " s, step " << solver_->stepCount();
  return s.str();
}

SolverProgress FhpSolverAdapter::progress() const {
  std::ostringstream detail;
  detail.precision(4);
  detail << "t = " << solver_->time() << " s, step " << solver_->stepCount();
  return {static_cast<double>(solver_->stepCount()) /
              static_cast<double>(std::max<long long>(1, solver_->units().steps)),
          detail.str()};
}

std::string FhpSolverAdapter::summary() const {
  std::ostringstream end;
  end.precision(5);
  end << "reached t = " << solver_->time() << " s after " << solver_->stepCount() << " steps";
  return end.str();
}

void FhpSolverAdapter::saveState(StateWriter& w) const {
  w.put<std::int32_t>(windowTarget_);
  solver_->saveState(w);
}

void FhpSolverAdapter::restoreState(StateReader& r) {
  windowTarget_ = r.get<std::int32_t>();
  solver_->restoreState(r);
}

}  // namespace fluidviz::fhp
