#include "pipeline/RunScene.h"

#include <omp.h>

#include <chrono>
#include <iostream>
#include <sstream>

#include "fieldviz/core/Params.h"

#include "pipeline/RunLoop.h"
#include "pipeline/SceneValidation.h"
#include "pipeline/SolverFactory.h"

namespace fluidviz {

std::string checkScene(const SceneParams& scene, const std::string& sceneFile) {
  validateScene(scene, sceneFile);
  return withSceneErrors(sceneFile, [&] { return solverEntry(scene.solver).describe(scene); });
}

namespace {

std::string durationText(double seconds) {
  if (seconds < 120) return formatNumber(seconds, 2) + " s";
  if (seconds < 7200) return formatNumber(seconds / 60, 2) + " min";
  return formatNumber(seconds / 3600, 3) + " h";
}

}  // namespace

std::string estimateRunTime(const SceneParams& scene, double seconds) {
  std::ostringstream quiet;
  const SolverRun run = solverEntry(scene.solver).create(scene, quiet);
  Solver& solver = *run.solver;
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const RunTarget whole{1, 1};
  double elapsed = 0;
  while (elapsed < seconds && !solver.reached(whole)) {
    solver.advance(whole);
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  const double fraction = solver.progress().fraction;
  const std::string how = "measured over " + formatNumber(elapsed, 2) + " s, " +
                          std::to_string(omp_get_max_threads()) + " threads; without the outputs";
  if (solver.reached(whole) || fraction >= 1)
    return "estimated run time: " + durationText(elapsed) + " (the whole run, " + how + ")";
  if (!(fraction > 0)) return "estimated run time: unknown (no progress within " + how + ")";
  return "estimated run time: " + durationText(elapsed / fraction) + " (" + how + ")";
}

RunSummary runScene(const SceneParams& scene, const RunOptions& options) {
  std::ostream& log = options.log ? *options.log : std::cerr;
  // Everything that can be checked is checked before the first file is written.
  validateScene(scene, options.sceneFile);
  const SolverRun run =
      withSceneErrors(options.sceneFile, [&] { return solverEntry(scene.solver).create(scene, log); });
  return runLoop(*run.solver, *run.outputs, scene, effectiveScene(scene), options);
}

}  // namespace fluidviz
