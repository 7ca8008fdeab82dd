#pragma once
// The FHP lattice gas behind the run loop's Solver interface (fieldviz/core/Solver.h): a scene's
// run of N = min(max_steps, ceil(end_time / dt)) steps, snapshot k of n on step ceil(k N / n)
// as for the LBM. The averaging window of snapshot k is its last min(average_steps, steps since
// snapshot k - 1) steps: the averager is cleared when the run first advances towards target k and
// samples every step from the window's start on. A lattice gas cannot go unstable and has no
// steady-state stop.
#include <memory>

#include "fieldviz/core/Solver.h"
#include "solvers/fhp/FhpSolver.h"

namespace fluidviz::fhp {

class FhpSolverAdapter final : public Solver {
 public:
  explicit FhpSolverAdapter(std::unique_ptr<FhpSolver> solver);

  const FhpSolver& solver() const { return *solver_; }

  std::string name() const override { return "fhp"; }
  std::string description() const override {
    return describeFhpUnits(solver_->units(), solver_->params());
  }
  double time() const override { return solver_->time(); }
  long long stepCount() const override { return solver_->stepCount(); }
  std::string position() const override;
  bool reached(const RunTarget& target) override;
  bool stoppedEarly() const override { return false; }
  std::optional<SolverProgress> advance(const RunTarget& target) override;
  SolverProgress progress() const override;
  std::vector<std::string> takeWarnings() override { return {}; }
  void checkStability() const override {}
  std::string summary() const override;
  /// i32 window target, then FhpSolver::saveState.
  void saveState(StateWriter& out) const override;
  void restoreState(StateReader& in) override;

 private:
  long long targetStep(const RunTarget& target) const;

  std::unique_ptr<FhpSolver> solver_;
  long long sliceSteps_;  ///< steps between polls of a stop request
  int windowTarget_ = 0;  ///< the target k the averager is collecting for (0: none yet)
};

}  // namespace fluidviz::fhp
