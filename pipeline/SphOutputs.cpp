#include "pipeline/SphOutputs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <vtkPolyData.h>

#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/render/ParticleImage.h"
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "pipeline/PictureText.h"
#include "pipeline/SceneValidation.h"
#include "pipeline/SphDerivedArrays.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

std::string num(double x) { return formatNumber(x, 4); }

// Scene rules of the outputs SPH offers; ParamError keys are scene paths.
void validateSphOutputKinds(const SceneParams& scene) {
  if (!scene.output.lic.empty())
    throw ParamError("output.lic", "is not available for solver sph (LIC needs a grid); resample "
                                   "the particles with `fluidviz resample` and run `fluidviz "
                                   "lic` on the grid, or remove output.lic");
  if (!scene.output.streamlines.empty())
    throw ParamError("output.streamlines",
                     "is not available for solver sph (streamlines need a grid); resample the "
                     "particles with `fluidviz resample` first, or remove output.streamlines");
  // Particle pictures colour particles by a particle array; derived grid fields do not exist here.
  const std::vector<std::string> particleFields = {"speed", "density", "pressure", "velocity_x",
                                                   "velocity_y"};
  for (std::size_t i = 0; i < scene.output.images.size(); ++i) {
    const std::string field = choiceName(scene.output.images[i].field);
    if (std::find(particleFields.begin(), particleFields.end(), field) == particleFields.end())
      throw ParamError("output.images[" + std::to_string(i) + "].field",
                       "is \"" + field + "\", not available for solver sph; allowed one of "
                       "{speed, density, pressure, velocity_x, velocity_y}");
  }
}

// The solver stops on NaN before a state is kept; this guards the files all the same.
void requireFinite(const particles::ParticleSet& s, double time) {
  auto bad = [&](double x) {
    if (!std::isfinite(x))
      throw std::runtime_error("SPH state at t = " + num(time) +
                               " s has a non-finite value; no snapshot written");
  };
  for (const Vec3& x : s.positions)
    for (int a = 0; a < 3; ++a) bad(x[a]);
  for (const auto& sc : s.scalars)
    for (double x : sc.values) bad(x);
  for (const auto& v : s.vectors)
    for (const Vec3& x : v.values)
      for (int a = 0; a < 3; ++a) bad(x[a]);
}

std::array<double, 6> domainBox(const sph::SphParams& p) {
  const bool d3 = p.dimension == 3;
  return {p.domain_lower[0], p.domain_upper[0], p.domain_lower[1], p.domain_upper[1],
          d3 ? p.domain_lower[2] : 0.0, d3 ? p.domain_upper[2] : 0.0};
}

}  // namespace

void validateSphScene(const SceneParams& scene) {
  validateSphOutputKinds(scene);
  withKeyPrefix("sph.", [&] { sph::validateSphParams(scene.sph); });
}

std::unique_ptr<sph::SphSolver> createCheckedSphSolver(const SceneParams& scene) {
  std::unique_ptr<sph::SphSolver> solver;
  try {
    withKeyPrefix("sph.", [&] { solver = std::make_unique<sph::SphSolver>(scene.sph); });
  } catch (const std::invalid_argument& e) {  // layout problems the validation cannot see
    throw ParamError("sph", e.what());
  }
  checkSphGridOutputs(scene, *solver);  // output.grids, free_surface, views
  return solver;
}

SphOutputs::SphOutputs(const SceneParams& scene, const sph::SphSolver& solver, std::ostream& log)
    : scene_(scene), solver_(solver), log_(log) {}

SphOutputs::~SphOutputs() = default;

void SphOutputs::begin(const SnapshotSeries& series, bool resumed, std::vector<fs::path>& written) {
  const particles::ParticleSet boundary = solver_.boundary();  // at t = 0, also when resuming
  if (boundary.size() > 0) {
    const fs::path file = series.dir() / (scene_.name + "_boundary.vtp");
    writeVtp(resample::toPolyData(boundary), file);
    written.push_back(file);
  }
  // The grids' every_snapshot series follow the targets 1..n: the main series' t = 0 entry is
  // not theirs.
  const auto& entries = series.entries();
  const std::vector<PvdSeries::Entry> targets(entries.begin() + (entries.empty() ? 0 : 1),
                                              entries.end());
  grids_ = std::make_unique<SphGridOutputs>(scene_, series.dir(), log_, resumed, targets);
  written.insert(written.end(), grids_->earlierFiles().begin(), grids_->earlierFiles().end());
  if (resumed) continueEarlierFrames(scene_, series, written);
}

void SphOutputs::writeSnapshot(int index, SnapshotSeries& series, std::vector<fs::path>& written) {
  const particles::ParticleSet fluid =
      withSnapshotArrays(solver_.fluid(), solver_.particleMass(), solver_.smoothingLength());
  requireFinite(fluid, solver_.time());
  const fs::path relative = series.file(index, ".vtp");
  // The file first, then the index.
  writeVtp(resample::toPolyData(fluid), series.dir() / relative, series.snapshotInfo(solver_.time()));
  series.add(solver_.time(), relative, written);
  const PictureDestination frames = PictureDestination::frames(series, index);
  grids_->snapshot(solver_, index, frames, written);  // output.grids, views etc., every_snapshot
  if (anyPictureFrames(scene_)) writeImages(frames, written);
}

void SphOutputs::writeImages(const PictureDestination& to, std::vector<fs::path>& written) const {
  if (scene_.output.images.empty()) return;
  const sph::SphParams& p = scene_.sph;
  const particles::ParticleSet fluid = withDerived(solver_.fluid(), true);
  const auto fluidPoly = resample::toPolyData(fluid);
  const auto boundaryPoly = resample::toPolyData(solver_.boundary());
  for (std::size_t i = 0; i < scene_.output.images.size(); ++i) {
    const ImageOutput& img = scene_.output.images[i];
    const std::optional<fs::path> png = to.path(imageFileName(scene_, img), img);
    if (!png) continue;
    ParticlePictureParams pp;
    pp.picture = img;
    const std::string field = choiceName(img.field);
    pp.picture.title = pictureTitle(scene_, "output.images[" + std::to_string(i) + "].title",
                                    img.title, {field, solver_.time()});
    if (pp.picture.scalar_bar_title.empty()) pp.picture.scalar_bar_title = legendTitleOf(field);
    pp.color_by = field;
    pp.radius = 0.5 * p.particle_spacing;
    pp.dimension = p.dimension;
    pp.domain = domainBox(p);
    writePicture(renderParticlePicture(fluidPoly, boundaryPoly, pp), *png);
    written.push_back(*png);
  }
}

void SphOutputs::writeFinal(const SnapshotSeries& series, const scene::json& /*effectiveScene*/,
                            std::vector<fs::path>& written) {
  writeImages(PictureDestination::finalPictures(series.dir()), written);
  grids_->finalState(solver_, written);  // output.grids, free_surface, views
  if (!series.entries().empty()) written.push_back(series.path());
}

}  // namespace fluidviz
