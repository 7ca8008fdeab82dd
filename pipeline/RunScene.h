#pragma once
// Runs a scene: validation (SceneValidation.h), the solver and outputs the scene names
// (SolverFactory.h), the run loop (RunLoop.h): snapshots, pictures, checkpoints, progress.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "pipeline/SceneParams.h"

namespace fluidviz {

struct RunOptions {
  std::filesystem::path outputDir = "out";  ///< created if missing
  std::string sceneFile = "scene";          ///< for messages: the file the scene came from
  std::ostream* log = nullptr;              ///< progress and summary; nullptr: std::cerr
  bool interactive = false;                 ///< progress bar instead of lines
  /// Continue from outputDir/<name>.checkpoint (pipeline/Checkpoint.h) instead of
  /// starting over.
  bool resume = false;
  /// A fresh run into a folder that holds an earlier run of the same scene removes that run's
  /// files first (RunRecord.h, claimOutputFolder); false: such a run is refused.
  bool replace = false;
  /// Tests: behave as if SIGTERM arrived once the run reaches this step (-1: never).
  long long stopAtStep = -1;
};

struct RunSummary {
  long steps = 0;
  double time = 0.0;        ///< physical time reached (s)
  bool steady = false;      ///< stopped because the steady-state tolerance was met
  std::vector<std::filesystem::path> files;  ///< everything written
};

/// Checks everything that can be checked before a run (rules spanning several keys, the solver's
/// physical limits); throws scene::SceneError naming the file and key. Returns what the run
/// would use, as text (LBM: the lattice units; SPH: particle counts and time-step limits).
std::string checkScene(const SceneParams& scene, const std::string& sceneFile);

/// Wall-clock estimate of the whole run of a valid scene, measured: builds the solver, advances
/// it for about `seconds` and extrapolates by its progress fraction (steady_tolerance may stop a
/// run earlier; the outputs' time is not counted). E.g. "estimated run time: 42 s (measured over
/// 0.31 s, 2 threads; without the outputs)".
std::string estimateRunTime(const SceneParams& scene, double seconds);

/// Throws scene::SceneError for bad parameters (before writing anything), and lets the solver's
/// instability error through (files written before it stay complete and listed). On SIGINT or
/// SIGTERM (pipeline/StopSignals.h) it writes the checkpoint and throws RunInterrupted.
RunSummary runScene(const SceneParams& scene, const RunOptions& options);

}  // namespace fluidviz
