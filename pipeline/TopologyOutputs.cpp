#include "pipeline/TopologyOutputs.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "pipeline/FlowFields.h"
#include "fieldviz/render/CriticalPointGlyphs.h"
#include "fieldviz/render/ImageOverlay.h"
#include "fieldviz/render/LicPicture.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "fieldviz/core/ParamRanges.h"

namespace fluidviz {

namespace topo = fluidviz::topology;

std::string criticalPointCsvRow(const topo::CriticalPoint& p) {
  char row[512];
  std::snprintf(row, sizeof row, "%.10g,%.10g,%.10g,%s,%d,%d,%.10g,%.10g,%d,%d,%d\n",
                p.position.x(), p.position.y(), p.position.z(), p.typeName().c_str(), p.index,
                p.morse ? 1 : 0, p.det, p.trace, p.sectors.hyperbolic, p.sectors.elliptic,
                p.sectors.parabolic);
  return row;
}

std::string criticalPointsCsv(const std::vector<topo::CriticalPoint>& points) {
  std::string csv = std::string(kCriticalPointsCsvHeader) + "\n";
  for (const topo::CriticalPoint& p : points) csv += criticalPointCsvRow(p);
  return csv;
}

std::string criticalPoint3DCsvRow(const topo::CriticalPoint3D& p) {
  char row[768];
  std::snprintf(row, sizeof row,
                "%.10g,%.10g,%.10g,%s,%d,%d,%.10g,%.10g,%d,%d,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n",
                p.position.x(), p.position.y(), p.position.z(), p.typeName().c_str(), p.index,
                p.morse ? 1 : 0, p.det, p.trace, p.index_measured ? 1 : 0, p.cluster_size,
                p.eigenvalues[0].real(), p.eigenvalues[0].imag(), p.eigenvalues[1].real(),
                p.eigenvalues[1].imag(), p.eigenvalues[2].real(), p.eigenvalues[2].imag());
  return row;
}

std::string criticalPoints3DCsv(const std::vector<topo::CriticalPoint3D>& points) {
  std::string csv = std::string(kCriticalPoints3DCsvHeader) + "\n";
  for (const topo::CriticalPoint3D& p : points) csv += criticalPoint3DCsvRow(p);
  return csv;
}

std::vector<std::pair<std::string, int>> countTypes3D(
    const std::vector<topo::CriticalPoint3D>& points) {
  std::map<int, int> counts;
  for (const topo::CriticalPoint3D& p : points) ++counts[static_cast<int>(p.type)];
  std::vector<std::pair<std::string, int>> ordered;
  for (const auto& [code, count] : counts)
    ordered.emplace_back(topo::toString(static_cast<topo::CriticalPointType3D>(code)), count);
  return ordered;
}

void validateTopologyPictureParams(const TopologyPictureParams& p) { params::checkRanges(p); }

std::vector<std::pair<std::string, int>> countTypes(const std::vector<topo::CriticalPoint>& points) {
  std::map<std::string, int> counts;
  for (const topo::CriticalPoint& p : points) ++counts[p.typeName()];
  std::vector<std::pair<std::string, int>> ordered;
  for (const std::string& name : criticalPointTypeOrder())
    if (counts.count(name)) ordered.emplace_back(name, counts[name]);
  return ordered;
}

namespace {

double pixelsPerUnit(FieldImageScene& scene, const Grid& g) {
  const PixelRect r = scene.fieldPixels();
  return (r.right - r.left) / ((g.dims[0] - 1) * g.spacing[0]);
}

// Separatrix points run from the critical point outwards; incoming ones are reversed so that the
// arrowheads point downstream.
std::vector<std::vector<Vec3>> downstreamLines(const std::vector<topo::Separatrix>& separatrices) {
  std::vector<std::vector<Vec3>> lines;
  for (const topo::Separatrix& s : separatrices) {
    lines.push_back(s.points);
    if (!s.start.outflow) std::reverse(lines.back().begin(), lines.back().end());
  }
  return lines;
}

std::vector<GlyphPoint> glyphPoints(const std::vector<topo::CriticalPoint>& points) {
  std::vector<GlyphPoint> glyphs;
  for (const topo::CriticalPoint& p : points) glyphs.push_back({p.position, p.typeName()});
  return glyphs;
}

std::string spaced(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

std::vector<LegendEntry> legendEntries(const std::vector<topo::CriticalPoint>& points,
                                       bool withSeparatrices, const StreamlineStyle& style) {
  std::vector<LegendEntry> entries;
  for (const auto& [name, count] : countTypes(points))
    entries.push_back({spaced(name) + " (" + std::to_string(count) + ")", name});
  if (withSeparatrices)
    entries.push_back({"separatrix", "", true,
                       {style.line_color[0], style.line_color[1], style.line_color[2]}});
  return entries;
}

// The LIC texture of the flow blended with the colour scalar, solid pixels masked.
std::unique_ptr<FieldImageScene> licScene(const VectorField& velocity, const ScalarField& colour,
                                          const TopologyPictureParams& p,
                                          const SolidTest& solid) {
  lic::LicImage texture = lic::computeLic(velocity, p.lic);
  if (solid)
    for (int j = 0; j < texture.height(); ++j)
      for (int i = 0; i < texture.width(); ++i)
        if (solid(texture.texture.grid.position(i, j)))
          texture.mask[static_cast<std::size_t>(j) * texture.width() + i] = 1;
  return makeLicScene(texture.texture, texture.mask, colour, p.picture, p.blend).scene;
}

}  // namespace

SolidTest maskedCells(const Grid& grid, const PointMask& mask) {
  if (mask.empty()) return {};
  return [&grid, &mask](const Vec3& p) { return maskFraction(grid, mask, p) >= 0.5; };
}

RgbaImage renderTopologyPicture(const VectorField& velocity,
                                const std::vector<topo::CriticalPoint>& points,
                                const std::vector<topo::Separatrix>& separatrices,
                                const TopologyPictureParams& params, const SolidTest& solid) {
  validateTopologyPictureParams(params);
  if (!velocity.grid.is2D())
    throw std::invalid_argument("topology picture: field '" + velocity.name +
                                "' must be 2D; take a z layer first");
  const std::optional<ScalarField> derived = derivedScalar(velocity, params.blend.color_by);
  if (!derived)
    throw ParamError("blend.color_by", "is \"" + params.blend.color_by +
                                           "\"; allowed for topology pictures: speed, vorticity");
  FieldImageParams picture = params.picture;
  if (params.blend.color_by == "vorticity") useSymmetricRange(*derived, picture);
  TopologyPictureParams p = params;
  p.picture = picture;
  std::unique_ptr<FieldImageScene> scene =
      params.underlay == TopologyUnderlay::lic
          ? licScene(velocity, *derived, p, solid)
          : std::make_unique<FieldImageScene>(*derived, picture);
  const double scale = pixelsPerUnit(*scene, velocity.grid);
  if (params.separatrices)
    addStreamlineOverlay(*scene, downstreamLines(separatrices), params.separatrix_style, scale);
  addCriticalPointGlyphs(*scene, glyphPoints(points), params.glyph_size, scale);
  const RgbaImage image = scene->render();
  const auto entries = legendEntries(points, params.separatrices && !separatrices.empty(),
                                     params.separatrix_style);
  if (entries.empty()) return image;
  const bool dark = picture.background == Background::dark;
  const std::uint8_t bg = dark ? 20 : 255;
  return stackImages(image,
                     renderGlyphLegend(entries, image.width, picture.background, params.glyph_size),
                     {bg, bg, bg});
}

}  // namespace fluidviz
