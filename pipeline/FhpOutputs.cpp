#include "pipeline/FhpOutputs.h"

#include <vtkImageData.h>

#include "pipeline/SceneTopology.h"

#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/FlowFields.h"
#include "pipeline/FlowOutputs.h"
#include "pipeline/PictureText.h"
#include "pipeline/SceneValidation.h"

namespace fluidviz {

namespace fs = std::filesystem;

FieldSet fhpSnapshotFields(const fhp::FhpSolver& solver) {
  FieldSet set = solver.averagedFields();
  // A solid block of an obstacle is at rest (bounce-back): it carries the wall's velocity, 0, as
  // an LBM snapshot's solids carry theirs, so that the topology commands read its wall as a wall
  // at rest (RestingWalls.h) instead of the average of the few fluid nodes the block holds. A
  // roller's blocks carry its own velocity omega x r, as the LBM's roller nodes do.
  const PointMask solid = solver.solidBlocks();
  VectorField velocity = withMaskedValue(*set.findVector("velocity"), solid, Vec3::Zero());
  for (const lbm::RollerParams& r : solver.params().rollers)
    for (std::size_t n = 0; n < solid.size(); ++n) {
      const int nx = velocity.grid.dims[0];
      const Vec3 p = velocity.grid.position(static_cast<int>(n) % nx, static_cast<int>(n) / nx) -
                     Vec3(r.center[0], r.center[1], 0.0);
      if (solid[n] && p.head<2>().norm() < r.radius)
        velocity.values[n] = r.angular_velocity * Vec3(-p.y(), p.x(), 0.0);
    }
  for (VectorField& v : set.vectors)
    if (v.name == "velocity") v = velocity;
  for (ScalarField& s : set.scalars)
    if (s.name == "speed")
      for (std::size_t n = 0; n < solid.size(); ++n)
        if (solid[n]) s.values[n] = velocity.values[n].norm();
  set.add(vorticity(*set.findVector("velocity")));
  return set;
}

void validateFhpScene(const SceneParams& scene) {
  withKeyPrefix("fhp.", [&] { fhp::computeFhpUnits(scene.fhp); });
  if (!scene.output.time_series.quantities.empty())
    throw ParamError("output.time_series.quantities",
                     "is \"" + scene.output.time_series.quantities +
                         "\"; solver fhp offers no time series: leave it empty");
}

FhpOutputs::FhpOutputs(const SceneParams& scene, const fhp::FhpSolver& solver)
    : scene_(scene), solver_(solver) {}

void FhpOutputs::begin(const SnapshotSeries& series, bool resumed, std::vector<fs::path>& written) {
  if (resumed) continueEarlierFrames(scene_, series, written);
}

void FhpOutputs::writeSnapshot(int index, SnapshotSeries& series, std::vector<fs::path>& written) {
  const fs::path relative = series.file(index, ".vti");
  const FieldSet fields = fhpSnapshotFields(solver_);
  writeVti(fields, solver_.solidBlocks(), series.dir() / relative,
           series.snapshotInfo(solver_.time()));
  series.add(solver_.time(), relative, written);
  if (anyPictureFrames(scene_))
    writePictures(fields, sceneStreamlineOverlays(scene_, *fields.findVector("velocity")),
                  PictureDestination::frames(series, index), written);
}

void FhpOutputs::writeFinal(const SnapshotSeries& series, const scene::json& /*effectiveScene*/,
                            std::vector<fs::path>& written) {
  const FieldSet final = fhpSnapshotFields(solver_);
  const SceneLineOverlays lines =
      writeSceneStreamlines(scene_, *final.findVector("velocity"), series.dir(), written);
  if (!scene_.output.topology.empty())
    writeSceneTopology(scene_,
                       snapshotImage(final, solver_.solidBlocks(),
                                     series.snapshotInfo(solver_.time())),
                       solver_.time(), series.dir(), written);
  writePictures(final, lines, PictureDestination::finalPictures(series.dir()), written);
}

void FhpOutputs::writePictures(const FieldSet& fields, const SceneLineOverlays& lines,
                               const PictureDestination& to, std::vector<fs::path>& written) const {
  writeSceneGridPictures(scene_, fields, solver_.time(), lines, to, written);
}

}  // namespace fluidviz
