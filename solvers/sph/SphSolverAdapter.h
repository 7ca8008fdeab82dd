#pragma once
// The SPH solver behind the run loop's Solver interface (fieldviz/core/Solver.h): a scene's run
// to end_time, at most max_steps steps; target k of n is the time k end_time / n, reached
// exactly (the last step before it is shortened). A chunk of advance() is one time step
// (automatic or fixed; SphSolver checks the state after each). Progress is reported every 20
// steps; a fixed time step past the stable limit is a warning.
#include <memory>
#include <string>
#include <vector>

#include "fieldviz/core/Solver.h"
#include "solvers/sph/SphSolver.h"

namespace fluidviz::sph {

/// "SPH 2D model B (wendland_c2), 400 fluid + 300 boundary particles, dx = ... m, h = ...\n
/// c0 = ... m/s, stable dt at t = 0: ... s (CFL), automatic, end_time = ... s". Evaluates the
/// time-step limits of the current state.
std::string describeSolver(SphSolver& solver);

class SphSolverAdapter final : public Solver {
 public:
  explicit SphSolverAdapter(std::unique_ptr<SphSolver> solver);

  const SphSolver& solver() const { return *solver_; }

  std::string name() const override { return "sph"; }
  std::string description() const override { return description_; }
  double time() const override { return solver_->time(); }
  long long stepCount() const override { return solver_->stepCount(); }
  std::string position() const override;
  bool reached(const RunTarget& target) override;
  bool stoppedEarly() const override { return stopReason_ != kEndTimeReached; }
  std::optional<SolverProgress> advance(const RunTarget& target) override;
  SolverProgress progress() const override;
  std::vector<std::string> takeWarnings() override;
  void checkStability() const override {}  // SphSolver::step checks every step it takes
  std::string summary() const override;
  std::vector<std::string> closingWarnings() const override;
  /// Why the run stopped ("end_time reached" until max_steps stops it), then
  /// SphSolver::saveState.
  void saveState(StateWriter& out) const override;
  void restoreState(StateReader& in) override;

 private:
  static constexpr const char* kEndTimeReached = "end_time reached";
  double targetTime(const RunTarget& target) const;

  std::unique_ptr<SphSolver> solver_;
  std::string description_;  ///< of the initial state
  std::string stopReason_ = kEndTimeReached;
  std::size_t warningsShown_ = 0;
};

}  // namespace fluidviz::sph
