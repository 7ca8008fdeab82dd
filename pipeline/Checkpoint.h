#pragma once
// Checkpoints of scene runs: `fluidviz run SCENE --resume DIR` continues an interrupted LBM or
// SPH run from DIR/<name>.checkpoint and ends with outputs bit-identical to an uninterrupted run
// (same build, same thread count). See docs/checkpoints.md.
//
// File layout (format version 1; integers and doubles in the machine's byte order):
//   20 bytes  magic "fluidviz checkpoint\n"
//   u32       format version
//   u64       payload size in bytes
//   payload   string solver (Solver::name: "lbm" | "sph"), string effective scene (compact JSON,
//             without the keys a resume may change), i64 step, f64 time (s), u64 snapshot count
//             and per snapshot f64 time + string file (the .pvd entries so far), then the run
//             loop's state (i32 snapshots written, pipeline/RunLoop.h) and Solver::saveState
//             (LbmSolverAdapter: its checks, then LbmSolver::saveState; SphSolverAdapter: its
//             stop reason, then SphSolver::saveState)
//   u64       FNV-1a 64-bit hash of every byte before it
// (strings: u64 length + bytes). Written atomically (temporary file + rename), so a kill while
// writing leaves the previous checkpoint.
//
// When: with every snapshot (checkpoint.at_snapshots), every checkpoint.interval seconds of wall
// time, and on SIGINT/SIGTERM (StopSignals.h). Removed when the run completes unless
// checkpoint.keep.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "fieldviz/core/StateBytes.h"
#include "fieldviz/io/PvdSeries.h"
#include "fieldviz/scene/SceneFile.h"
#include "pipeline/RunScene.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

inline constexpr std::uint32_t kCheckpointFormatVersion = 1;

/// What a checkpoint says about the run before the loop's and the solver's state.
struct CheckpointHeader {
  std::string solver;     ///< Solver::name(): "lbm" | "sph"
  std::string sceneJson;  ///< checkpointSceneJson of the scene the run started with
  long long step = 0;
  double time = 0.0;                        ///< s
  std::vector<PvdSeries::Entry> snapshots;  ///< the .pvd entries written so far
};

struct LoadedCheckpoint {
  CheckpointHeader header;
  StateReader state;  ///< positioned at the run loop's state
};

/// DIR/<name>.checkpoint
std::filesystem::path checkpointPath(const std::filesystem::path& dir, const std::string& name);

/// The effective scene of a run (only its solver's section) as a checkpoint records it: every
/// key except those a resume may change (description, checkpoint.*, output.images, output.lic,
/// output.streamlines: the final pictures are made from the final state).
std::string checkpointSceneJson(scene::json effectiveScene);

/// Writes header, then whatever writeState appends, atomically. Throws FileError.
void writeCheckpoint(const std::filesystem::path& file, const CheckpointHeader& header,
                     const std::function<void(StateWriter&)>& writeState);

/// Reads and verifies a checkpoint. Throws FileError naming the file for a missing, foreign,
/// other-version, truncated, corrupt (checksum) or malformed file.
LoadedCheckpoint readCheckpoint(const std::filesystem::path& file);

/// For `--resume`: reads outputDir/<name>.checkpoint, requires that it was written for this
/// scene, i.e. that it records `sceneJson` (checkpointSceneJson; else scene::SceneError naming
/// the scene file, the first differing key and both values)
/// and that every snapshot it lists exists (else FileError), and removes snapshot files numbered
/// after them (<name>/<name>_NNNN.*) and temporary files of writers that died.
LoadedCheckpoint openCheckpointForResume(const SceneParams& scene, const std::string& sceneJson,
                                         const RunOptions& options);

/// Removes the files folder/<name>_NNNN.* numbered after `kept` (a resumed run writes them
/// again; left over, they would lie outside their .pvd).
void removeLaterSnapshots(const std::filesystem::path& folder, const std::string& name,
                          std::size_t kept);

/// For a fresh run: removes an earlier run's checkpoint and temporary files of writers that died.
void prepareFreshOutput(const SceneParams& scene, const RunOptions& options);

/// The checkpoint of one run: where it goes, when the next is due, and stop requests.
class RunCheckpointer {
 public:
  RunCheckpointer(const SceneParams& scene, const RunOptions& options);

  const std::filesystem::path& path() const { return path_; }
  bool atSnapshots() const { return atSnapshots_; }
  /// The wall-clock interval has passed since the run (re)started or the last checkpoint.
  bool intervalDue() const;
  /// SIGINT/SIGTERM received, or RunOptions::stopAtStep reached (reported as SIGTERM); else 0.
  int stopSignal(long long step) const;
  /// Writes the checkpoint (atomically) and restarts the interval.
  void write(const CheckpointHeader& header, const std::function<void(StateWriter&)>& state);
  /// Writes the checkpoint and throws RunInterrupted.
  [[noreturn]] void stop(int signal, const CheckpointHeader& header,
                         const std::function<void(StateWriter&)>& state);
  /// The run completed: removes the checkpoint unless checkpoint.keep.
  void finish() const;

 private:
  std::filesystem::path path_;
  double interval_;
  bool atSnapshots_, keep_;
  long long stopAtStep_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace fluidviz
