#include "pipeline/LbmOutputs.h"

#include <vtkImageData.h>

#include "pipeline/SceneTopology.h"

#include "fieldviz/core/RestingWalls.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/FlowFields.h"
#include "pipeline/FlowOutputs.h"
#include "pipeline/LbmSketchStart.h"
#include "pipeline/PictureText.h"
#include "pipeline/SceneValidation.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

// A picture of a 3D LBM scene is one z layer: output.images[].slice_index in [0, nz - 1].
void checkLbmImageSlices(const SceneParams& scene, const lbm::LatticeUnits& units) {
  const int nz = lbm::is3D(scene.lbm) ? units.nz : 1;
  for (std::size_t i = 0; i < scene.output.images.size(); ++i) {
    const int k = scene.output.images[i].slice_index;
    if (nz > 1 && (k < 0 || k >= nz))
      throw ParamError("output.images[" + std::to_string(i) + "].slice_index",
                       "is " + std::to_string(k) + "; a 3D scene (lattice D3Q19, " +
                           std::to_string(nz) + " nodes along z) draws one z layer: give slice_index "
                           "in [0, " + std::to_string(nz - 1) + "]");
  }
}

// Gauge pressure p = c_s^2 (rho - rho0) (dx/dt)^2, c_s^2 = 1/3 (lattice units), in Pa for density
// in kg/m^3: the pressure of the LBM equation of state (docs/units.md). Solid nodes carry rho0:
// p = 0 there.
ScalarField lbmPressure(const ScalarField& density, const lbm::LatticeUnits& units) {
  const double c = units.dx / units.dt;
  ScalarField p{"pressure", density.grid, std::vector<double>(density.values.size())};
  for (std::size_t n = 0; n < p.values.size(); ++n)
    p.values[n] = (density.values[n] - units.density) * c * c / 3.0;
  return p;
}

// 1 on the solver's solid nodes (walls inside the box, rollers, obstacles).
PointMask solidMask(const lbm::LbmSolver& solver) {
  const Grid& g = solver.grid();
  PointMask solid(g.nodeCount(), 0);
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) solid[g.index(i, j, k)] = solver.isSolid(i, j, k);
  return solid;
}

// The sides that hold the fluid at rest (a wall, or a moving_wall that does not move): the
// topology commands read their attachment and separation points from them (RestingWalls.h).
std::string restingSides(const lbm::WallsParams& w) {
  const auto resting = [](const lbm::WallParams& p) {
    return p.type == lbm::WallType::wall ||
           (p.type == lbm::WallType::moving_wall && p.velocity[0] == 0.0 &&
            p.velocity[1] == 0.0 && p.velocity_z == 0.0);
  };
  return restingSidesText({resting(w.x_min), resting(w.x_max), resting(w.y_min), resting(w.y_max)});
}

}  // namespace

FieldSet lbmSnapshotFields(const lbm::LbmSolver& solver) {
  FieldSet set = solver.fields();
  const VectorField velocity = *set.findVector("velocity");
  set.add(lbmPressure(*set.findScalar("density"), solver.units()));
  if (velocity.grid.is2D()) {
    set.add(vorticity(velocity));
  } else {
    set.add(vorticityVector(velocity));
    set.add(qCriterion(velocity));
  }
  return set;
}

void validateLbmScene(const SceneParams& scene) {
  lbm::LatticeUnits units;
  // A sketched start counts with its largest speed (LbmSketchStart.h).
  withKeyPrefix("lbm.", [&] { units = lbm::computeLatticeUnits(lbmStartOf(scene).params); });
  checkLbmImageSlices(scene, units);  // 3D scenes draw z slices
}

LbmOutputs::LbmOutputs(const SceneParams& scene, const lbm::LbmSolver& solver)
    : scene_(scene), solver_(solver) {}

void LbmOutputs::begin(const SnapshotSeries& series, bool resumed, std::vector<fs::path>& written) {
  if (resumed) continueEarlierFrames(scene_, series, written);
}

void LbmOutputs::writeSnapshot(int index, SnapshotSeries& series, std::vector<fs::path>& written) {
  const fs::path relative = series.file(index, ".vti");
  const FieldSet fields = lbmSnapshotFields(solver_);
  // The file first, then the index.
  FileInfo info = series.snapshotInfo(solver_.time());
  info.strings.emplace_back(kRestingSidesFieldData, restingSides(scene_.lbm.walls));
  writeVti(fields, solidMask(solver_), series.dir() / relative, info);
  series.add(solver_.time(), relative, written);
  if (anyPictureFrames(scene_))
    writePictures(fields, sceneStreamlineOverlays(scene_, *fields.findVector("velocity")),
                  PictureDestination::frames(series, index), written);
}

void LbmOutputs::writeFinal(const SnapshotSeries& series, const scene::json& /*effectiveScene*/,
                            std::vector<fs::path>& written) {
  const FieldSet final = lbmSnapshotFields(solver_);
  // Streamlines first: pictures may show them.
  const SceneLineOverlays lines =
      writeSceneStreamlines(scene_, *final.findVector("velocity"), series.dir(), written);
  if (!scene_.output.topology.empty()) {
    FileInfo info = series.snapshotInfo(solver_.time());
    info.strings.emplace_back(kRestingSidesFieldData, restingSides(scene_.lbm.walls));
    writeSceneTopology(scene_, snapshotImage(final, solidMask(solver_), info), solver_.time(),
                       series.dir(), written);
  }
  writePictures(final, lines, PictureDestination::finalPictures(series.dir()), written);
}

void LbmOutputs::writePictures(const FieldSet& fields, const SceneLineOverlays& lines,
                               const PictureDestination& to, std::vector<fs::path>& written) const {
  writeSceneGridPictures(scene_, fields, solver_.time(), lines, to, written);
}

}  // namespace fluidviz
