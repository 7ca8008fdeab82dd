#include "pipeline/RunScene.h"

#include <iostream>

#include "pipeline/RunLoop.h"
#include "pipeline/SceneValidation.h"
#include "pipeline/SolverFactory.h"

namespace fluidviz {

std::string checkScene(const SceneParams& scene, const std::string& sceneFile) {
  validateScene(scene, sceneFile);
  return withSceneErrors(sceneFile, [&] { return solverEntry(scene.solver).describe(scene); });
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
