#include "fieldviz/render/StreamlineOverlay.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <cmath>

#include "fieldviz/core/ParamRanges.h"
#include "fieldviz/render/FlatActors.h"
#include "fieldviz/render/OverlayDepth.h"

namespace fluidviz {

namespace {

vtkSmartPointer<vtkPolyData> polylines(const std::vector<std::vector<Vec3>>& lines, double z) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (const auto& line : lines) {
    if (line.size() < 2) continue;
    cells->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (const Vec3& p : line) cells->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), z));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(cells);
  return data;
}

vtkSmartPointer<vtkPolyData> triangles(const std::vector<std::array<Vec3, 3>>& tris) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (const auto& t : tris) {
    cells->InsertNextCell(3);
    for (const Vec3& p : t) cells->InsertCellPoint(points->InsertNextPoint(p.data()));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(cells);
  return data;
}

}  // namespace

std::vector<std::array<Vec3, 3>> arrowheads(const std::vector<std::vector<Vec3>>& lines,
                                            double spacing, double size, double z) {
  std::vector<std::array<Vec3, 3>> out;
  for (const auto& line : lines) {
    double next = 0.5 * spacing, walked = 0.0;
    for (std::size_t k = 1; k < line.size(); ++k) {
      Vec3 a = line[k - 1], b = line[k];
      a.z() = b.z() = 0.0;
      const double len = (b - a).norm();
      if (len == 0.0) continue;
      const Vec3 d = (b - a) / len, n(-d.y(), d.x(), 0.0);
      // The arrow's centre sits on the line at arc length `next`.
      for (; next <= walked + len; next += spacing) {
        Vec3 c = a + (next - walked) * d;
        c.z() = z;
        out.push_back({c + 0.5 * size * d, c - 0.5 * size * d + 0.35 * size * n,
                       c - 0.5 * size * d - 0.35 * size * n});
      }
      walked += len;
    }
  }
  return out;
}

namespace {

// Black around light lines, white around dark ones (Rec. 709 luma).
std::array<double, 3> outlineColour(const std::array<double, 3>& c) {
  const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  return luma > 0.5 ? std::array<double, 3>{0, 0, 0} : std::array<double, 3>{1, 1, 1};
}

// The triangle grown by `by` world units on every side (about its centroid).
std::array<Vec3, 3> grown(const std::array<Vec3, 3>& t, double by) {
  const Vec3 c = (t[0] + t[1] + t[2]) / 3.0;
  // The inradius r of the arrowhead: growing by `by` scales it by (r + by) / r.
  const double a = (t[1] - t[2]).norm(), b = (t[0] - t[2]).norm(), d = (t[0] - t[1]).norm();
  const Vec3 u = t[1] - t[0], w = t[2] - t[0];
  const double area = 0.5 * std::abs(u.x() * w.y() - u.y() * w.x());  // triangles lie in xy
  const double r = 2.0 * area / (a + b + d);
  const double scale = (r + by) / r;
  return {c + scale * (t[0] - c), c + scale * (t[1] - c), c + scale * (t[2] - c)};
}

}  // namespace

void addStreamlineOverlay(FieldImageScene& scene, const std::vector<std::vector<Vec3>>& lines,
                          const StreamlineStyle& style, double pixelsPerUnit) {
  params::checkRanges(style);
  const bool outlined = style.outline_width > 0;
  const auto outline = outlineColour(style.line_color);
  // Outline first (wider, below), then the line over it; arrowheads above both.
  if (outlined) {
    vtkSmartPointer<vtkActor> under = flatActor(polylines(lines, overlayDepth(scene, 2)), outline);
    under->GetProperty()->SetLineWidth(static_cast<float>(style.line_width + 2 * style.outline_width));
    scene.renderer().addProp(under);
  }
  vtkSmartPointer<vtkActor> line =
      flatActor(polylines(lines, overlayDepth(scene, 3)), style.line_color);
  line->GetProperty()->SetLineWidth(static_cast<float>(style.line_width));
  scene.renderer().addProp(line);
  if (!style.arrows) return;
  const auto tris = arrowheads(lines, style.arrow_spacing / pixelsPerUnit,
                               style.arrow_size / pixelsPerUnit, overlayDepth(scene, 5));
  if (outlined) {
    std::vector<std::array<Vec3, 3>> bigger;
    for (const auto& t : tris) bigger.push_back(grown(t, style.outline_width / pixelsPerUnit));
    for (auto& t : bigger)
      for (Vec3& p : t) p.z() = overlayDepth(scene, 4);
    scene.renderer().addProp(flatActor(triangles(bigger), outline));
  }
  scene.renderer().addProp(flatActor(triangles(tris), style.line_color));
}

}  // namespace fluidviz
