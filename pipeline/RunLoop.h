#pragma once
// The one run loop of scene runs, for every solver (docs/design.md, "Solvers and the run loop"): it drives a
// Solver (fieldviz/core/Solver.h) to output.snapshots evenly spread targets and hands each
// snapshot and the final state to the solver's SolverOutputs (pipeline/LbmOutputs.h,
// pipeline/SphOutputs.h); it owns the main .pvd series, progress, checkpoints
// (pipeline/Checkpoint.h), resume and stop signals (pipeline/StopSignals.h).
//
//   for each target k = 1..n (n = max(snapshots, 1)), unless the solver stopped early:
//     until solver.reached(target): solver.advance(target) (one chunk); its progress and
//       warnings; a checkpoint if the interval is due; a stop request: checkpoint, RunInterrupted
//     snapshot k (if snapshots > 0) and its checkpoint (checkpoint.at_snapshots); progress;
//     a stop request
//   closing line, outputs.writeFinal, checkpoint removed unless checkpoint.keep
//
// Checkpoints hold, after the header, i32 snapshots written, then Solver::saveState.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/Solver.h"
#include "fieldviz/io/PvdSeries.h"
#include "fieldviz/scene/SceneFile.h"
#include "pipeline/RunScene.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

/// The run's main series: <dir>/<name>.pvd listing <name>/<name>_NNNN.<ext>, only complete files.
class SnapshotSeries {
 public:
  /// `earlier`: the entries of a resumed run's snapshots.
  SnapshotSeries(std::filesystem::path dir, std::string name,
                 std::vector<PvdSeries::Entry> earlier = {});

  const std::filesystem::path& dir() const { return dir_; }
  /// <name>/<name>_NNNN<extension> (relative to dir()) for snapshot `index`; creates its folder.
  std::filesystem::path file(int index, const std::string& extension) const;
  /// Lists a written snapshot file (relative to dir()) at `time` and appends it to `written`.
  void add(double time, const std::filesystem::path& relative,
           std::vector<std::filesystem::path>& written);
  const std::vector<PvdSeries::Entry>& entries() const { return series_.entries(); }
  const std::filesystem::path& path() const { return series_.path(); }

 private:
  std::filesystem::path dir_;
  std::string name_;
  PvdSeries series_;
};

/// What one solver writes: its snapshot files, the pictures and grids of the final state.
class SolverOutputs {
 public:
  virtual ~SolverOutputs() = default;
  /// Before the first step and before a resumed state is restored (the solver is at t = 0):
  /// files of the whole run (e.g. the SPH boundary at t = 0) and, when resuming, those of the
  /// earlier snapshots besides the main series', appended to `written`. Throws FileError for an
  /// earlier file that is missing.
  virtual void begin(const SnapshotSeries& series, bool resumed,
                     std::vector<std::filesystem::path>& written) = 0;
  /// Snapshot `index` (1, 2, ...) of the solver's current state: its file, listed in `series`
  /// (the file first, then the index), and any per-snapshot outputs.
  virtual void writeSnapshot(int index, SnapshotSeries& series,
                             std::vector<std::filesystem::path>& written) = 0;
  /// The final state: pictures, grids, and the effective scene (writeEffectiveScene).
  virtual void writeFinal(const SnapshotSeries& series, const scene::json& effectiveScene,
                          std::vector<std::filesystem::path>& written) = 0;
  /// The grid fields of the current state ("velocity", "density") that output.probes sample;
  /// empty for a solver without a grid (validateProbes refuses probes there).
  virtual FieldSet probeFields() const { return {}; }
  /// The values of output.time_series quantities in the current state, in order; NaN for one
  /// the solver does not offer (validateTimeSeries refuses those).
  virtual std::vector<double> seriesValues(const std::vector<SeriesQuantity>& quantities) const {
    return std::vector<double>(quantities.size(), std::numeric_limits<double>::quiet_NaN());
  }
};

/// <dir>/<name>_scene.json: the scene as the run used it, every default spelled out.
void writeEffectiveScene(const std::filesystem::path& dir, const std::string& name,
                         const scene::json& effectiveScene,
                         std::vector<std::filesystem::path>& written);

/// Runs `solver` to its end (see above), writing through `outputs` into options.outputDir.
/// `effectiveScene`: the scene with only this solver's section (a checkpoint records it, a
/// resume requires the same). Lets the solver's InstabilityError through after saying how many
/// snapshots were kept; throws RunInterrupted after the checkpoint of a stop request.
RunSummary runLoop(Solver& solver, SolverOutputs& outputs, const SceneParams& scene,
                   const scene::json& effectiveScene, const RunOptions& options);

}  // namespace fluidviz
