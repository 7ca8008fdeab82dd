#include "pipeline/TopologyPicture3D.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "fieldviz/render/CriticalPointGlyphs.h"
#include "fieldviz/render/LicBlend.h"
#include "fieldviz/render/SurfaceRendering.h"
#include "filters/topology/vtk/TopologyPolyData.h"

namespace fluidviz {

namespace {

using topology::CriticalPoint3D;
using topology::SeparatingSurface;
using topology::Separatrix3D;

constexpr Rgb kUnstableLine{0.85, 0.20, 0.10}, kStableLine{0.10, 0.30, 0.85};
constexpr Rgb kUnstableSheet{0.95, 0.50, 0.45}, kStableSheet{0.45, 0.60, 0.95};

/// Legend order: the 3D types as CriticalPoint3D.h lists them.
const std::vector<std::string>& typeOrder3D() {
  static const std::vector<std::string> order = {
      "source", "sink", "saddle_1", "saddle_2", "spiral_source", "spiral_sink",
      "spiral_saddle_1", "spiral_saddle_2", "centre", "degenerate", "unknown"};
  return order;
}

vtkSmartPointer<vtkActor> sphereActor(const Vec3& centre, double radius, const Rgb& color) {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre.data());
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetSpecular(0.3);
  return actor;
}

vtkSmartPointer<vtkActor> linesActor(const std::vector<Separatrix3D>& lines, const Rgb& color) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(topology::separatrices3DToPolyData(lines));
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetLineWidth(2.5);
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkActor> sheetActor(const std::vector<SeparatingSurface>& sheets, const Rgb& color,
                                     double opacity) {
  SurfaceStyle style;
  style.color = {color[0], color[1], color[2]};
  style.opacity = opacity;
  style.specular = 0.1;
  vtkSmartPointer<vtkActor> actor =
      makeSurfaceActor(topology::separatingSurfacesToPolyData(sheets), style).actor;
  actor->GetProperty()->BackfaceCullingOff();
  return actor;
}

template <class T>
std::pair<std::vector<T>, std::vector<T>> splitByOutgoing(const std::vector<T>& all) {
  std::pair<std::vector<T>, std::vector<T>> out;
  for (const T& x : all) (x.outgoing ? out.first : out.second).push_back(x);
  return out;
}

std::vector<LegendEntry> legendEntries(const std::vector<CriticalPoint3D>& points,
                                       bool unstableLines, bool stableLines, bool unstableSheets,
                                       bool stableSheets) {
  std::map<std::string, int> present;
  for (const CriticalPoint3D& p : points) ++present[p.typeName()];
  std::vector<LegendEntry> entries;
  for (const std::string& t : typeOrder3D())
    if (present.count(t))
      entries.push_back({t + " (" + std::to_string(present[t]) + ")", t, false, {},
                         criticalPoint3DColor(t)});
  const auto line = [&](bool shown, const std::string& label, const Rgb& c) {
    if (shown) entries.push_back({label, "", true, c, std::nullopt});
  };
  line(unstableLines, "unstable separatrix", kUnstableLine);
  line(stableLines, "stable separatrix", kStableLine);
  line(unstableSheets, "unstable surface", kUnstableSheet);
  line(stableSheets, "stable surface", kStableSheet);
  return entries;
}

}  // namespace

Rgb criticalPoint3DColor(const std::string& typeName) {
  static const std::map<std::string, Rgb> saddles = {
      {"saddle_1", {0.90, 0.10, 0.10}},
      {"saddle_2", {0.60, 0.20, 0.85}},
      {"spiral_saddle_1", {1.00, 0.50, 0.60}},
      {"spiral_saddle_2", {0.75, 0.60, 1.00}}};
  const auto it = saddles.find(typeName);
  return it != saddles.end() ? it->second : criticalPointGlyph(typeName).fill;
}

RgbaImage renderTopology3DPicture(const Grid& grid, const std::vector<CriticalPoint3D>& points,
                                  const std::vector<Separatrix3D>& separatrices,
                                  const std::vector<SeparatingSurface>& surfaces,
                                  const Topology3DPictureParams& params) {
  Scene3D scene(params.view);
  const Vec3 lo = grid.position(0, 0, 0), hi = grid.upperCorner();
  scene.setBounds({lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()});
  const double diameter = (hi - lo).norm();
  const double radius = 0.5 * params.glyph_size * diameter /
                        (params.view.height * params.view.camera.zoom);
  for (const CriticalPoint3D& p : points)
    scene.add(sphereActor(p.position, radius, criticalPoint3DColor(p.typeName())));
  const auto [unstableLines, stableLines] = splitByOutgoing(separatrices);
  if (!unstableLines.empty()) scene.add(linesActor(unstableLines, kUnstableLine));
  if (!stableLines.empty()) scene.add(linesActor(stableLines, kStableLine));
  const auto [unstableSheets, stableSheets] = splitByOutgoing(surfaces);
  if (!unstableSheets.empty())
    scene.add(sheetActor(unstableSheets, kUnstableSheet, params.surface_opacity));
  if (!stableSheets.empty())
    scene.add(sheetActor(stableSheets, kStableSheet, params.surface_opacity));
  if (!params.title.empty()) scene.setTitle(params.title);
  const RgbaImage image = scene.render();
  const auto entries = legendEntries(points, !unstableLines.empty(), !stableLines.empty(),
                                     !unstableSheets.empty(), !stableSheets.empty());
  const RgbaImage legend =
      renderGlyphLegend(entries, image.width, params.view.background, params.glyph_size);
  const Rgb bg = backgroundColor(params.view.background);
  return stackImages(image, legend, {toByte(bg[0]), toByte(bg[1]), toByte(bg[2])});
}

}  // namespace fluidviz
