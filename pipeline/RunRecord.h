#pragma once
// What made a run's files and how the run ended (issue 16, "provenance"), and the rule that a
// fresh run never mixes its files with an earlier run's (ParaView groups <name>_NNNN files into
// one series, so two runs in one folder silently become one).
//
//   <dir>/<name>_run.json    machine-readable: fluidviz version and commit, date, threads, the
//                            scene file, the solver's derived units, outcome, steps, time, the
//                            files written, and the effective scene
//   <dir>/<name>_scene.json  the effective scene (re-runnable), its provenance and outcome in
//                            // comment lines at the top (scene files allow them)
#include <filesystem>
#include <string>
#include <vector>

#include "fieldviz/scene/SceneFile.h"

namespace fluidviz {

/// How a run ended, as written in its record.
enum class RunOutcome {
  completed,     ///< reached end_time (or max_steps)
  steady_state,  ///< stopped early: the steady-state tolerance was met
  unstable,      ///< stopped by the solver's stability limits; the snapshots before it are kept
  interrupted,   ///< stopped by SIGINT/SIGTERM after writing its checkpoint (--resume continues)
};
const char* outcomeName(RunOutcome outcome);

/// Who made the files: version, commit, date (UTC, ISO 8601), OpenMP threads.
struct Provenance {
  std::string version;
  std::string commit;
  bool modified = false;  ///< built from sources that differ from `commit`
  std::string date;       ///< e.g. 2026-12-02T06:41:07Z
  int threads = 1;

  static Provenance now();  ///< this build, the current time and thread count
  /// One line: "fluidviz 0.1.0 (commit 008bf10c1a2b), 2026-12-02T06:41:07Z, 2 threads".
  std::string line() const;
  scene::json toJson() const;
};

/// Everything <name>_run.json records.
struct RunRecord {
  Provenance provenance;
  std::string sceneFile;          ///< the file the scene came from
  std::string solverDescription;  ///< Solver::description(): lattice units / particle counts
  RunOutcome outcome = RunOutcome::completed;
  std::string message;            ///< why it stopped, for unstable and interrupted runs
  long long steps = 0;
  double time = 0.0;              ///< s, the physical time reached
  std::vector<std::filesystem::path> files;  ///< written by the run (the record itself excluded)
};

std::filesystem::path runRecordPath(const std::filesystem::path& dir, const std::string& name);

/// Writes <dir>/<name>_scene.json (comment header + effective scene) and <dir>/<name>_run.json
/// (atomically, each); appends the scene copy to record.files first so the record lists it.
void writeRunRecord(const std::filesystem::path& dir, const std::string& name,
                    const scene::json& effectiveScene, RunRecord record);

/// Files of an earlier run of scene `name` in `dir`: those its run record lists (if it has one)
/// and, always, its series (<name>.pvd, the <name>/ folder's files), scene copy, run record and
/// checkpoint. Only existing files, sorted.
std::vector<std::filesystem::path> earlierRunFiles(const std::filesystem::path& dir,
                                                   const std::string& name);

/// Makes `dir` ready for a fresh run of `name`: no earlier run's files, or with `replace` those
/// files removed first (the <name>/ folder too once empty). Without `replace`, throws FileError
/// naming the folder, how many files and the first few, and the two ways out (--replace, or
/// another -o folder).
void claimOutputFolder(const std::filesystem::path& dir, const std::string& name, bool replace);

}  // namespace fluidviz
