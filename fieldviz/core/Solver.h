#pragma once
// The one interface the scene run loop (pipeline/RunLoop.h) drives, whatever the solver: LBM
// (solvers/lbm/LbmSolverAdapter.h), SPH (solvers/sph/SphSolverAdapter.h), or a third one. It
// knows nothing of files, VTK or the scene: the loop decides where the run stops for snapshots
// (RunTarget), polls stop requests and writes checkpoints between calls to advance(); the solver
// decides how much work one call does and when its own stop conditions hold (end time,
// max_steps, steady state, ...).
//
//   while (!solver.reached(target)) { solver.advance(target); poll stop requests, checkpoints }
//   snapshot target.k; next target, unless solver.stoppedEarly()
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/StateBytes.h"

namespace fluidviz {

/// Where the loop wants the run to stop next: output point k of n, evenly spread over the run
/// (k = n: its end). Each solver maps it onto its own clock, so that outputs fall on the same
/// steps however the run is chunked, stopped or resumed (LBM: step ceil(k N / n) of its N steps;
/// SPH: time k T / n of its end time T, reached exactly by a shortened last step).
struct RunTarget {
  int k = 1;
  int n = 1;
  /// A time (s) the next chunk should end at (or at the first step past it, never earlier):
  /// the next time-series sample. A solver whose chunks are single steps may ignore it.
  double sampleTime = std::numeric_limits<double>::infinity();
};

/// How far a run is: the fraction done (the solver's progress quantity: steps, simulated time)
/// and a one-line detail for the progress bar ("t = 0.5 s, step 120, dt = 0.0004 s").
struct SolverProgress {
  double fraction = 0.0;  ///< in [0, 1]
  std::string detail;
};

class Solver {
 public:
  virtual ~Solver() = default;

  /// "lbm", "sph": the solver a checkpoint was written by.
  virtual std::string name() const = 0;
  /// What the run uses (lattice units, particle counts, time-step limits): the log's first
  /// line(s) of a run and the answer of `fluidviz check`.
  virtual std::string description() const = 0;

  virtual double time() const = 0;  ///< s
  virtual long long stepCount() const = 0;
  /// Where the run stands, for the log ("t = 0.05 s, step 25").
  virtual std::string position() const = 0;

  /// The solver stands at `target`, or its run has ended before it (stoppedEarly()).
  virtual bool reached(const RunTarget& target) = 0;
  /// The run ended before its end time (steady state, max_steps): no later target is run.
  virtual bool stoppedEarly() const = 0;
  /// It stopped early because the flow became steady (RunSummary::steady).
  virtual bool steady() const { return false; }
  /// One chunk of work towards `target`, never past it: at most a fraction of a second, so that
  /// the loop can poll stop requests between chunks. Runs the stability and stop-condition
  /// checks that fall due in it (throws InstabilityError). Returns the progress to report if
  /// the chunk ended where the solver reports progress between targets.
  virtual std::optional<SolverProgress> advance(const RunTarget& target) = 0;
  /// The progress the loop reports after each target.
  virtual SolverProgress progress() const = 0;
  /// Messages for the log that appeared since the last call (e.g. a fixed time step past the
  /// stable limit), each printed as "<scene>: warning: <message>".
  virtual std::vector<std::string> takeWarnings() = 0;
  /// Throws InstabilityError if the current state is unusable (the loop calls it before every
  /// snapshot; advance() calls it whenever a check falls due).
  virtual void checkStability() const = 0;

  /// The closing line of a completed run ("steady state reached at t = 2.3 s after 1200 steps").
  virtual std::string summary() const = 0;
  /// Warnings about the whole run, printed before the summary.
  virtual std::vector<std::string> closingWarnings() const { return {}; }

  /// Everything advance() evolves, including the solver's own stop-condition bookkeeping, for a
  /// checkpoint; restoreState on a solver built from the same scene continues bit-identically.
  /// restoreState throws StateFormatError on a state that does not fit.
  virtual void saveState(StateWriter& out) const = 0;
  virtual void restoreState(StateReader& in) = 0;
};

}  // namespace fluidviz
