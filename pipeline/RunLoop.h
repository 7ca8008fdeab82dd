#pragma once
// The one run loop of scene runs, for every solver (docs/design.md, "Solvers and the run loop"): it drives a
// Solver (fieldviz/core/Solver.h) to output.snapshots evenly spread targets and hands each
// snapshot and the final state to the solver's SolverOutputs (pipeline/LbmOutputs.h,
// pipeline/SphOutputs.h); it owns the main .pvd series, progress, checkpoints
// (pipeline/Checkpoint.h), resume and stop signals (pipeline/StopSignals.h).
//
//   snapshot 0 of the initial state (t = 0) when snapshots > 0, unless resumed
//   for each target k = 1..n (n = max(snapshots, 1)), unless the solver stopped early:
//     until solver.reached(target): solver.advance(target) (one chunk); its progress and
//       warnings; a checkpoint if the interval is due; a stop request: checkpoint, RunInterrupted
//     snapshot k (if snapshots > 0) and its checkpoint (checkpoint.at_snapshots); progress;
//     a stop request
//   closing line, and one saying so when the run ended early (steady state, max_steps) with
//     fewer than n + 1 snapshots; outputs.writeFinal, the pictures' movies (PictureSeries.h),
//     checkpoint removed unless checkpoint.keep, the run record (<name>_scene.json, <name>_run.json; also when the run stops unstable or
//     on a signal)
// A fresh run first claims its folder (claimOutputFolder): an earlier run's files of the same
// scene are refused, or removed with RunOptions::replace.
// So the .pvd lists n + 1 snapshots (t = 0 and the n targets, the last being the final state),
// fewer for a run that ended early (its last is then the state it stopped at), and does not
// exist when snapshots = 0.
//
// Checkpoints hold, after the header, i32 snapshots written (t = 0 included), then
// Solver::saveState.
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/Solver.h"
#include "fieldviz/io/PvdSeries.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/scene/SceneFile.h"
#include "pipeline/RunScene.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

/// The run's main series: <dir>/<name>.pvd listing <name>/<name>_NNNN.<ext>, only complete files.
/// The .pvd is written with the first snapshot (none without snapshots).
class SnapshotSeries {
 public:
  /// `earlier`: the entries of a resumed run's snapshots.
  SnapshotSeries(std::filesystem::path dir, std::string name,
                 std::vector<PvdSeries::Entry> earlier = {});

  const std::filesystem::path& dir() const { return dir_; }
  /// <name>/<name>_NNNN<extension> (relative to dir()) for snapshot `index`; creates its folder.
  std::filesystem::path file(int index, const std::string& extension) const;
  /// <name>/<stem>_NNNN.png (relative to dir()): the frame of a picture `pictureFile`
  /// (<stem>.png) at snapshot `index`, numbered as the snapshot's file; creates its folder.
  std::filesystem::path frameFile(int index, const std::string& pictureFile) const;
  /// Lists a written snapshot file (relative to dir()) at `time` and appends it to `written`.
  void add(double time, const std::filesystem::path& relative,
           std::vector<std::filesystem::path>& written);
  const std::vector<PvdSeries::Entry>& entries() const;
  /// What a snapshot file of this run says about itself (VTK field data, VtkXmlWriters.h): the
  /// run's provenance strings (set by runLoop) and `time`.
  FileInfo snapshotInfo(double time) const { return FileInfo{provenance_, time}; }
  void setProvenance(std::vector<std::pair<std::string, std::string>> strings) {
    provenance_ = std::move(strings);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path dir_;
  std::string name_;
  std::filesystem::path path_;
  std::optional<PvdSeries> series_;  ///< from the first snapshot on
  std::vector<std::pair<std::string, std::string>> provenance_;
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
  /// Snapshot `index` (0 = the initial state, 1, 2, ...) of the solver's current state: its file, listed in `series`
  /// (the file first, then the index), and any per-snapshot outputs.
  virtual void writeSnapshot(int index, SnapshotSeries& series,
                             std::vector<std::filesystem::path>& written) = 0;
  /// The final state: pictures and grids (the loop then writes the scene copy and the run
  /// record, pipeline/RunRecord.h).
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

/// Runs `solver` to its end (see above), writing through `outputs` into options.outputDir.
/// `effectiveScene`: the scene with only this solver's section (a checkpoint records it, a
/// resume requires the same). Lets the solver's InstabilityError through after saying how many
/// snapshots were kept; throws RunInterrupted after the checkpoint of a stop request.
RunSummary runLoop(Solver& solver, SolverOutputs& outputs, const SceneParams& scene,
                   const scene::json& effectiveScene, const RunOptions& options);

}  // namespace fluidviz
