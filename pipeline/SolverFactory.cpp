#include "pipeline/SolverFactory.h"

#include "pipeline/FhpOutputs.h"
#include "pipeline/LbmOutputs.h"
#include "pipeline/LbmSketchStart.h"
#include "pipeline/SceneReading.h"
#include "pipeline/SceneValidation.h"
#include "pipeline/SphOutputs.h"
#include "solvers/fhp/FhpSolverAdapter.h"
#include "solvers/lbm/LbmSolverAdapter.h"
#include "solvers/sph/SphSolverAdapter.h"

namespace fluidviz {

namespace {

SolverRun createLbmRun(const SceneParams& scene, std::ostream&) {
  LbmStart start;
  withKeyPrefix("lbm.", [&] { start = lbmStartOf(scene); });
  std::unique_ptr<lbm::LbmSolver> lbmSolver = lbm::createLbmSolver(start.params);
  if (!start.velocity.empty())  // a sketch (LbmSketchStart.h); a resumed run restores over it
    lbmSolver->initialise(std::vector<double>(start.velocity.size(), start.params.density),
                          start.velocity);
  auto solver = std::make_unique<lbm::LbmSolverAdapter>(std::move(lbmSolver));
  auto outputs = std::make_unique<LbmOutputs>(scene, solver->solver());
  return {std::move(solver), std::move(outputs)};
}

std::string describeLbm(const SceneParams& scene) {
  LbmStart start;
  withKeyPrefix("lbm.", [&] { start = lbmStartOf(scene); });
  const std::string sketched = describeSketchStart(start, scene);
  return lbm::describeUnits(lbm::computeLatticeUnits(start.params), start.params) +  // no lattice
         (sketched.empty() ? "" : "\n" + sketched);
}

SolverRun createSphRun(const SceneParams& scene, std::ostream& log) {
  auto solver = std::make_unique<sph::SphSolverAdapter>(createCheckedSphSolver(scene));
  auto outputs = std::make_unique<SphOutputs>(scene, solver->solver(), log);
  return {std::move(solver), std::move(outputs)};
}

std::string describeSph(const SceneParams& scene) {
  return sph::describeSolver(*createCheckedSphSolver(scene));
}

SolverRun createFhpRun(const SceneParams& scene, std::ostream&) {
  std::unique_ptr<fhp::FhpSolver> fhpSolver;
  withKeyPrefix("fhp.", [&] { fhpSolver = std::make_unique<fhp::FhpSolver>(scene.fhp); });
  auto solver = std::make_unique<fhp::FhpSolverAdapter>(std::move(fhpSolver));
  auto outputs = std::make_unique<FhpOutputs>(scene, solver->solver());
  return {std::move(solver), std::move(outputs)};
}

std::string describeFhp(const SceneParams& scene) {
  return fhp::describeFhpUnits(fhp::computeFhpUnits(scene.fhp), scene.fhp);  // no lattice allocated
}

const std::vector<SolverEntry>& solverTable() {
  static const std::vector<SolverEntry> table = {
      {SolverKind::lbm, validateLbmScene, describeLbm, createLbmRun},
      {SolverKind::sph, validateSphScene, describeSph, createSphRun},
      {SolverKind::fhp, validateFhpScene, describeFhp, createFhpRun},
  };
  return table;
}

}  // namespace

const SolverEntry& solverEntry(SolverKind kind) {
  std::string names;
  for (const SolverEntry& e : solverTable()) {
    if (e.kind == kind) return e;
    names += (names.empty() ? "" : ", ") + choiceName(e.kind);
  }
  throw ParamError("solver", "is \"" + choiceName(kind) + "\", which has no run entry; allowed one of {" +
                                 names + "}");
}

scene::json effectiveScene(const SceneParams& scene) {
  scene::json j = writeSceneParams(scene);
  for (const SolverEntry& e : solverTable())
    if (e.kind != scene.solver) j.erase(choiceName(e.kind));
  return j;
}

}  // namespace fluidviz
