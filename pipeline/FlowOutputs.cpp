#include "pipeline/FlowOutputs.h"
#include "pipeline/SceneTopology.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/FlowFields.h"
#include "pipeline/PictureText.h"
#include "pipeline/SceneValidation.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "filters/topology/StreamFunction.h"
#include "fieldviz/core/ParamRanges.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"

namespace fluidviz {

namespace fs = std::filesystem;
namespace sl = fluidviz::streamlines;

namespace {

// The scene's fields a LIC picture can be coloured by.
const std::vector<std::string> kColorBy = {"speed", "vorticity", "density", "velocity_x",
                                           "velocity_y"};

struct Disc {
  double x, y, radius;
  bool contains(const Vec3& p) const {
    return (p.x() - x) * (p.x() - x) + (p.y() - y) * (p.y() - y) < radius * radius;
  }
};

// Solid bodies of the scene: the rollers (fixed or turning discs), FHP's obstacles and rollers.
std::vector<Disc> solidDiscs(const SceneParams& scene) {
  std::vector<Disc> discs;
  if (scene.solver == SolverKind::fhp) {
    for (const auto& o : scene.fhp.obstacles) discs.push_back({o.center[0], o.center[1], o.radius});
    for (const auto& r : scene.fhp.rollers) discs.push_back({r.center[0], r.center[1], r.radius});
    return discs;
  }
  for (const auto& r : scene.lbm.rollers) discs.push_back({r.center[0], r.center[1], r.radius});
  return discs;
}

ScalarField fieldForImage(const FieldSet& fields, const std::string& name) {
  if (const ScalarField* s = fields.findScalar(name)) return *s;
  const VectorField* velocity = fields.findVector("velocity");
  const int component = name == "velocity_x" ? 0 : (name == "velocity_z" ? 2 : 1);
  ScalarField s{name, velocity->grid, std::vector<double>(velocity->values.size())};
  for (std::size_t n = 0; n < s.values.size(); ++n) s.values[n] = velocity->values[n][component];
  return s;
}

bool insideSolid(const std::vector<Disc>& solids, const Vec3& p) {
  return std::any_of(solids.begin(), solids.end(), [&](const Disc& d) { return d.contains(p); });
}

void validateLic(const SceneParams& scene, std::size_t i, std::vector<std::string>& files) {
  const LicOutput& o = scene.output.lic[i];
  const std::string key = "output.lic[" + std::to_string(i) + "].";
  requireOutputFileName(key + "file", licFileName(scene, o), ".png", files);
  if (std::find(kColorBy.begin(), kColorBy.end(), o.color_by) == kColorBy.end())
    throw ParamError(key + "color_by", "is \"" + o.color_by +
                                           "\", allowed one of {speed, vorticity, density, "
                                           "velocity_x, velocity_y}");
  withKeyPrefix(key, [&] {
    lic::validateLicParams(o);
    params::checkRanges(static_cast<const LicBlendParams&>(o));
    validateFieldImageParams(o);
  });
}

void validateStreamlines(const SceneParams& scene, std::size_t i, std::vector<std::string>& files) {
  const StreamlinesOutput& o = scene.output.streamlines[i];
  const std::string key = "output.streamlines[" + std::to_string(i) + "].";
  requireOutputFileName(key + "file", streamlinesFileName(scene, o), ".vtp", files);
  withKeyPrefix(key + "integration.", [&] { sl::validateStreamlineParams(o.integration); });
  withKeyPrefix(key + "seeding.", [&] {
    params::checkRanges(o.seeding);
    if (o.seeding.strategy == streamlines::SeedStrategy::points && o.seeding.points.empty())
      throw ParamError("points", "strategy points needs at least one seed");
  });
  withKeyPrefix(key, [&] { params::checkRanges(static_cast<const StreamlineStyle&>(o)); });
  const bool wantsLic = o.draw_on == DrawOn::lic || o.draw_on == DrawOn::all;
  const bool wantsImages = o.draw_on == DrawOn::images || o.draw_on == DrawOn::all;
  if ((wantsLic && scene.output.lic.empty()) || (wantsImages && scene.output.images.empty()))
    throw ParamError(key + "draw_on", "is \"" + choiceName(o.draw_on) + "\", but output." +
                                          (wantsLic && scene.output.lic.empty() ? "lic" : "images") +
                                          " lists no picture; allowed here: " +
                                          (scene.output.lic.empty() ? "images or none" : "lic or none"));
}

// The z layer nearest `z` (mid-height when unset); 0 for a 2D grid.
int nearestLayer(const Grid& g, const std::optional<double>& z) {
  if (g.is2D()) return 0;
  const double at = z ? *z : 0.5 * (g.origin[2] + g.upperCorner().z());
  const long k = std::lround((at - g.origin[2]) / g.spacing[2]);
  return static_cast<int>(std::clamp<long>(k, 0, g.dims[2] - 1));
}

std::vector<sl::Streamline> traceOutsideSolids(const VectorField& velocity,
                                               const StreamlinesOutput& o,
                                               const std::vector<Disc>& solids) {
  if (o.seeding.strategy == streamlines::SeedStrategy::evenly_spaced) {
    std::vector<sl::Streamline> lines = sl::traceSeeded(velocity, o.seeding, o.integration);
    std::erase_if(lines, [&](const sl::Streamline& l) {
      return !l.points.empty() && insideSolid(solids, l.points[l.seed_index]);
    });
    return lines;
  }
  std::vector<Vec3> seeds = sl::generateSeeds(velocity.grid, o.seeding);
  std::erase_if(seeds, [&](const Vec3& p) { return insideSolid(solids, p); });
  return sl::traceStreamlines(velocity, seeds, o.integration);
}

LineOverlay overlayOf(const std::vector<sl::Streamline>& lines, const StreamlineStyle& style) {
  LineOverlay overlay{{}, style};
  for (const auto& l : lines) overlay.lines.push_back(l.points);
  return overlay;
}

ScalarField sceneScalar(const FieldSet& fields, const VectorField& velocity,
                        const std::string& name) {
  if (auto derived = derivedScalar(velocity, name)) return *derived;
  if (const ScalarField* s = fields.findScalar(name)) return *s;
  ScalarField component{name, velocity.grid, std::vector<double>(velocity.values.size())};
  const int c = name == "velocity_x" ? 0 : 1;
  for (std::size_t n = 0; n < component.values.size(); ++n)
    component.values[n] = velocity.values[n][c];
  return component;
}

}  // namespace

std::string licFileName(const SceneParams& scene, const LicOutput& o) {
  return o.file.empty() ? scene.name + "_lic_" + o.color_by + ".png" : o.file;
}

std::string streamlinesFileName(const SceneParams& scene, const StreamlinesOutput& o) {
  return o.file.empty() ? scene.name + "_streamlines.vtp" : o.file;
}

void validateFlowOutputs(const SceneParams& scene) {
  std::vector<std::string> files = imageFileNames(scene);
  for (std::size_t i = 0; i < scene.output.lic.size(); ++i) validateLic(scene, i, files);
  for (std::size_t i = 0; i < scene.output.streamlines.size(); ++i)
    validateStreamlines(scene, i, files);
  validateSceneTopology(scene, files);
}

namespace {

void addOverlays(SceneLineOverlays& overlays, const StreamlinesOutput& o,
                 const std::vector<sl::Streamline>& lines) {
  if (o.draw_on == DrawOn::lic || o.draw_on == DrawOn::all) overlays.lic.push_back(overlayOf(lines, o));
  if (o.draw_on == DrawOn::images || o.draw_on == DrawOn::all) overlays.images.push_back(overlayOf(lines, o));
}

}  // namespace

SceneLineOverlays writeSceneStreamlines(const SceneParams& scene, const VectorField& velocity,
                                        const fs::path& dir, std::vector<fs::path>& written) {
  SceneLineOverlays overlays;
  const std::vector<Disc> solids = solidDiscs(scene);
  for (const StreamlinesOutput& o : scene.output.streamlines) {
    const std::vector<sl::Streamline> lines = traceOutsideSolids(velocity, o, solids);
    const fs::path vtp = dir / streamlinesFileName(scene, o);
    writeVtp(sl::streamlinesToPolyData(lines), vtp);
    written.push_back(vtp);
    addOverlays(overlays, o, lines);
  }
  return overlays;
}

SceneLineOverlays sceneStreamlineOverlays(const SceneParams& scene, const VectorField& velocity) {
  SceneLineOverlays overlays;
  const std::vector<Disc> solids = solidDiscs(scene);
  for (const StreamlinesOutput& o : scene.output.streamlines)
    if (o.draw_on != DrawOn::none) addOverlays(overlays, o, traceOutsideSolids(velocity, o, solids));
  return overlays;
}

ScalarField outsideSceneSolids(const SceneParams& scene, ScalarField field) {
  const std::vector<Disc> solids = solidDiscs(scene);
  if (solids.empty()) return field;
  const Grid& g = field.grid;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        if (insideSolid(solids, g.position(i, j, k)))
          field.values[g.index(i, j, k)] = std::numeric_limits<double>::quiet_NaN();
  return field;
}

void writeSceneLicPictures(const SceneParams& scene, const FieldSet& fields, double time,
                           const std::vector<LineOverlay>& lines, const PictureDestination& to,
                           std::vector<fs::path>& written) {
  const VectorField& velocity3 = *fields.findVector("velocity");
  const std::vector<Disc> solids = solidDiscs(scene);
  for (std::size_t n = 0; n < scene.output.lic.size(); ++n) {
    const LicOutput& o = scene.output.lic[n];
    const std::optional<fs::path> png = to.path(licFileName(scene, o), o);
    if (!png) continue;
    // A 3D flow is shown in the xy layer nearest slice_height: texture and colour from that layer.
    const int layer = nearestLayer(velocity3.grid, o.lic::LicParams::slice_height);
    const VectorField velocity = velocity3.grid.is2D() ? velocity3 : sliceZ(velocity3, layer);
    lic::LicImage texture = lic::computeLic(velocity, o);
    for (int j = 0; j < texture.height(); ++j)
      for (int i = 0; i < texture.width(); ++i)
        if (insideSolid(solids, texture.texture.grid.position(i, j)))
          texture.mask[static_cast<std::size_t>(j) * texture.width() + i] = 1;
    ScalarField colour = sceneScalar(fields, velocity, o.color_by);
    if (!colour.grid.is2D()) colour = sliceZ(colour, layer);
    colour = outsideSceneSolids(scene, std::move(colour));
    FieldImageParams picture = o;
    picture.title = pictureTitle(scene, "output.lic[" + std::to_string(n) + "].title", o.title,
                                 {o.color_by, time});
    if (picture.scalar_bar_title.empty()) picture.scalar_bar_title = legendTitleOf(o.color_by);
    if (o.color_by == "vorticity") useSymmetricRange(colour, picture);
    writePicture(renderLicPicture(texture.texture, texture.mask, colour, picture, o, lines).image, *png);
    written.push_back(*png);
  }
}

// Fields a picture may ask for, computed only then: vorticity and stream function (of the
// 2D field, or of the picture's z layer of a 3D field; the result is 2D, so the picture's
// slice_index is cleared), else fieldForImage. NaN inside the solid bodies, whose rigid motion
// would otherwise set the colour range.
ScalarField sceneImageField(const SceneParams& scene, const FieldSet& fields, const std::string& name,
                          FieldImageParams& picture) {
  if (name != "vorticity" && name != "stream_function")
    return outsideSceneSolids(scene, fieldForImage(fields, name));
  const VectorField& velocity = *fields.findVector("velocity");
  const int k = velocity.grid.is2D() ? 0 : picture.slice_index;
  picture.slice_index = -1;
  if (name == "vorticity") {
    ScalarField w =
        outsideSceneSolids(scene, vorticity(velocity.grid.is2D() ? velocity : sliceZ(velocity, k)));
    useSymmetricRange(w, picture);
    return w;
  }
  topology::TopologyParams params;
  params.slice_index = k;
  ScalarField psi = topology::computeStreamFunction(velocity, params).psi;
  psi.name = "stream_function";
  return outsideSceneSolids(scene, std::move(psi));
}

void writeSceneGridPictures(const SceneParams& scene, const FieldSet& fields, double time,
                            const SceneLineOverlays& lines, const PictureDestination& to,
                            std::vector<std::filesystem::path>& written) {
  for (std::size_t i = 0; i < scene.output.images.size(); ++i) {
    const ImageOutput& img = scene.output.images[i];
    const std::optional<std::filesystem::path> png = to.path(imageFileName(scene, img), img);
    if (!png) continue;
    FieldImageParams params = img;
    const std::string field = choiceName(img.field);
    params.title = pictureTitle(scene, "output.images[" + std::to_string(i) + "].title",
                                img.title, {field, time});
    if (params.scalar_bar_title.empty()) params.scalar_bar_title = legendTitleOf(field);
    writePicture(
        renderFieldPicture(sceneImageField(scene, fields, field, params), params, lines.images).image,
        *png);
    written.push_back(*png);
  }
  writeSceneLicPictures(scene, fields, time, lines.lic, to, written);
}

}  // namespace fluidviz
