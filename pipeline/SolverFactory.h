#pragma once
// The solvers a scene can name, in one table: for each, its scene rules, the description
// `fluidviz check` prints, and how to build its Solver (fieldviz/core/Solver.h) and
// SolverOutputs (pipeline/RunLoop.h). A third solver is one more entry (SolverFactory.cpp),
// next to its Solver implementation and its outputs; runScene, checkScene, validateScene and
// the run loop need no change.
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "fieldviz/core/Solver.h"
#include "fieldviz/scene/SceneFile.h"
#include "pipeline/RunLoop.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

/// A solver and its outputs, ready for runLoop. The outputs refer to the solver.
struct SolverRun {
  std::unique_ptr<Solver> solver;
  std::unique_ptr<SolverOutputs> outputs;
};

struct SolverEntry {
  SolverKind kind;  ///< the scene's `solver`; choiceName(kind) names its parameter section
  /// The solver's rules of a scene, after the common ones (validateScene): its parameters and
  /// the outputs it offers. Throws ParamError with the key from the scene's root.
  void (*validate)(const SceneParams& scene);
  /// What `fluidviz check` prints about a valid scene (units, particle counts, time steps).
  /// Throws ParamError for what only a built solver can check.
  std::string (*describe)(const SceneParams& scene);
  /// The solver and outputs of a valid scene; `log` takes warnings of the outputs. Throws
  /// ParamError for what only a built solver can check.
  SolverRun (*create)(const SceneParams& scene, std::ostream& log);
};

/// The entry for scene.solver. Every SolverKind has one (a missing one is a ParamError on key
/// "solver", naming those there are).
const SolverEntry& solverEntry(SolverKind kind);

/// The effective scene of a run: every key with its value or default, without the parameter
/// sections of the other solvers (their defaults would not read back).
scene::json effectiveScene(const SceneParams& scene);

}  // namespace fluidviz
