#pragma once
// The LBM solver behind the run loop's Solver interface (fieldviz/core/Solver.h): a scene's run
// of N = min(max_steps, ceil(end_time / dt)) steps, with the stability check every
// check_interval steps and at every target, and the steady-state stop (steady_tolerance > 0):
// the largest velocity change between two checks relative to the largest speed
// (relativeVelocityChange) below steady_tolerance.
//
// A chunk of advance() is a slice of at most a few million node updates (well under a second),
// ending early at the next check or target; results do not depend on the slicing.
#include <memory>
#include <string>
#include <vector>

#include "fieldviz/core/Solver.h"
#include "solvers/lbm/LbmSolver.h"

namespace fluidviz::lbm {

/// Largest change of the velocity between two checks, relative to the largest speed (0 speed:
/// the change itself).
double relativeVelocityChange(const std::vector<Vec3>& before, const std::vector<Vec3>& after);

/// "lattice 64 x 64 nodes, dx = ... m, dt = ... s\ntau = ..., Mach = ..., Reynolds = ...\nsteps:
/// ..." (for a driven flow that nothing moves: the plane-Poiseuille estimate of its speed).
std::string describeUnits(const LatticeUnits& units, const LbmParams& params);

class LbmSolverAdapter final : public Solver {
 public:
  explicit LbmSolverAdapter(std::unique_ptr<LbmSolver> solver);

  const LbmSolver& solver() const { return *solver_; }

  std::string name() const override { return "lbm"; }
  std::string description() const override { return describeUnits(solver_->units(), solver_->params()); }
  double time() const override { return solver_->time(); }
  long long stepCount() const override { return solver_->stepCount(); }
  std::string position() const override;
  bool reached(const RunTarget& target) override;
  bool stoppedEarly() const override { return steady_; }
  bool steady() const override { return steady_; }
  std::optional<SolverProgress> advance(const RunTarget& target) override;
  SolverProgress progress() const override;
  std::vector<std::string> takeWarnings() override { return {}; }
  void checkStability() const override { solver_->checkStability(); }
  std::string summary() const override;
  /// The loop's checks (steps since the last, last change, steady flag, reference velocity),
  /// then LbmSolver::saveState.
  void saveState(StateWriter& out) const override;
  void restoreState(StateReader& in) override;

 private:
  long long targetStep(const RunTarget& target) const;
  /// Steps to the first step at or after target.sampleTime (at least 1).
  long long stepsToSample(const RunTarget& target) const;
  void runChecks();

  std::unique_ptr<LbmSolver> solver_;
  long long totalSteps_;
  long long sliceSteps_;  ///< steps between polls of a stop request
  bool steadyCheck_;
  long long sinceCheck_ = 0;       ///< steps since the last stability/steady check
  double change_ = NAN;            ///< last relative velocity change (progress lines)
  bool steady_ = false;
  std::vector<Vec3> lastVelocity_;  ///< velocity at the last check (steady_tolerance > 0)
};

}  // namespace fluidviz::lbm
