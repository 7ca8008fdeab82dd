#include "fieldviz/render/CriticalPointGlyphs.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <stdexcept>

#include "fieldviz/render/FlatActors.h"
#include "fieldviz/render/OverlayDepth.h"

namespace fluidviz {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr Rgb kOutline{0.05, 0.05, 0.05};
// Glyphs go above the streamline overlay's levels (texture 1, lines 2-3, arrowheads 4-5).
constexpr int kOutlineLevel = 6, kFillLevel = 7;
constexpr double kOutlinePx = 1.5;

struct NamedStyle {
  const char* name;
  GlyphStyle style;
};

// Saturated fills with a dark outline: visible on grey LIC, on viridis and on white.
const std::vector<NamedStyle>& styleTable() {
  static const std::vector<NamedStyle> table = {
      {"saddle", {GlyphShape::Cross, {0.90, 0.10, 0.10}, 1.25}},
      {"monkey_saddle", {GlyphShape::Star6, {0.95, 0.25, 0.90}, 1.4}},
      {"centre", {GlyphShape::Circle, {1.00, 1.00, 1.00}, 1.0}},
      {"spiral_sink", {GlyphShape::TriangleDown, {0.25, 0.85, 0.95}, 1.15}},
      {"spiral_source", {GlyphShape::TriangleUp, {1.00, 0.55, 0.10}, 1.15}},
      {"sink", {GlyphShape::Square, {0.25, 0.45, 1.00}, 0.95}},
      {"source", {GlyphShape::Diamond, {1.00, 0.90, 0.10}, 1.1}},
      {"saddle_node", {GlyphShape::Pentagon, {0.80, 0.60, 0.35}, 1.05}},
      {"cusp", {GlyphShape::Star3, {1.00, 0.60, 0.75}, 1.3}},
      {"dipole", {GlyphShape::Hexagon, {0.30, 0.80, 0.30}, 1.05}},
      {"degenerate", {GlyphShape::Octagon, {0.65, 0.65, 0.65}, 1.0}},
      {"unknown", {GlyphShape::Star5, {0.40, 0.40, 0.40}, 1.3}},
      {"attachment", {GlyphShape::Star4, {0.15, 0.70, 0.35}, 1.25}},
      {"separation", {GlyphShape::Star8, {0.85, 0.15, 0.50}, 1.25}},
  };
  return table;
}

std::vector<std::array<double, 2>> regularPolygon(int corners, double firstAngle) {
  std::vector<std::array<double, 2>> out;
  for (int k = 0; k < corners; ++k) {
    const double a = firstAngle + 2 * kPi * k / corners;
    out.push_back({std::cos(a), std::sin(a)});
  }
  return out;
}

// Points alternate between the unit circle and `inner`, starting with a point at `firstAngle`.
std::vector<std::array<double, 2>> star(int points, double inner, double firstAngle) {
  std::vector<std::array<double, 2>> out;
  for (int k = 0; k < 2 * points; ++k) {
    const double a = firstAngle + kPi * k / points, r = k % 2 == 0 ? 1.0 : inner;
    out.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return out;
}

// Every shape is star-shaped about its centre, so a fan of triangles from the centre fills it
// (concave stars included; VTK's polygon fill assumes convex polygons).
vtkSmartPointer<vtkPolyData> filledGlyphs(const std::vector<Vec3>& centres,
                                          const std::vector<std::array<double, 2>>& outline,
                                          double radius, double z) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  const auto n = static_cast<vtkIdType>(outline.size());
  for (const Vec3& c : centres) {
    const vtkIdType centre = points->InsertNextPoint(c.x(), c.y(), z);
    for (const auto& p : outline)
      points->InsertNextPoint(c.x() + radius * p[0], c.y() + radius * p[1], z);
    for (vtkIdType k = 0; k < n; ++k) {
      const vtkIdType tri[3] = {centre, centre + 1 + k, centre + 1 + (k + 1) % n};
      cells->InsertNextCell(3, tri);
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(cells);
  return data;
}

// The band between the outline scaled to `inner` and to `outer`: the glyph's border, drawn
// without overlapping the fill (2D overlay actors of equal depth are drawn in no fixed order).
vtkSmartPointer<vtkPolyData> glyphRings(const std::vector<Vec3>& centres,
                                        const std::vector<std::array<double, 2>>& outline,
                                        double inner, double outer, double z) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  const auto n = static_cast<vtkIdType>(outline.size());
  for (const Vec3& c : centres) {
    const vtkIdType first = points->GetNumberOfPoints();
    for (const auto& p : outline) {
      points->InsertNextPoint(c.x() + inner * p[0], c.y() + inner * p[1], z);
      points->InsertNextPoint(c.x() + outer * p[0], c.y() + outer * p[1], z);
    }
    for (vtkIdType k = 0; k < n; ++k) {
      const vtkIdType i0 = first + 2 * k, o0 = i0 + 1;
      const vtkIdType i1 = first + 2 * ((k + 1) % n), o1 = i1 + 1;
      const vtkIdType a[3] = {i0, o0, o1}, b[3] = {i0, o1, i1};
      cells->InsertNextCell(3, a);
      cells->InsertNextCell(3, b);
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(cells);
  return data;
}

}  // namespace

GlyphStyle criticalPointGlyph(const std::string& typeName) {
  for (const NamedStyle& s : styleTable())
    if (typeName == s.name) return s.style;
  return styleTable().back().style;
}

const std::vector<std::string>& criticalPointTypeOrder() {
  static const std::vector<std::string> order = [] {
    std::vector<std::string> names;
    for (const NamedStyle& s : styleTable()) names.emplace_back(s.name);
    return names;
  }();
  return order;
}

std::vector<std::array<double, 2>> glyphOutline(GlyphShape shape) {
  switch (shape) {
    case GlyphShape::Circle: return regularPolygon(32, 0.0);
    case GlyphShape::Square: return regularPolygon(4, 0.25 * kPi);
    case GlyphShape::Diamond: return regularPolygon(4, 0.0);
    case GlyphShape::TriangleUp: return regularPolygon(3, 0.5 * kPi);
    case GlyphShape::TriangleDown: return regularPolygon(3, -0.5 * kPi);
    case GlyphShape::Pentagon: return regularPolygon(5, 0.5 * kPi);
    case GlyphShape::Hexagon: return regularPolygon(6, 0.0);
    case GlyphShape::Octagon: return regularPolygon(8, kPi / 8);
    case GlyphShape::Star3: return star(3, 0.35, 0.5 * kPi);
    case GlyphShape::Cross: return star(4, 0.32, 0.25 * kPi);
    case GlyphShape::Star5: return star(5, 0.45, 0.5 * kPi);
    case GlyphShape::Star6: return star(6, 0.5, 0.5 * kPi);
    case GlyphShape::Star4: return star(4, 0.42, 0.5 * kPi);
    case GlyphShape::Star8: return star(8, 0.55, 0.5 * kPi);
  }
  return regularPolygon(32, 0.0);
}

void addCriticalPointGlyphs(FieldImageScene& scene, const std::vector<GlyphPoint>& points,
                            double sizePx, double pixelsPerUnit) {
  if (!(sizePx >= 2.0 && sizePx <= 200.0))
    throw std::invalid_argument("glyph size " + std::to_string(sizePx) +
                                " px is outside [2, 200]");
  // One actor pair (outline below, fill above) per type present.
  std::map<std::string, std::vector<Vec3>> byType;
  for (const GlyphPoint& p : points) byType[p.type].push_back(p.position);
  for (const auto& [type, centres] : byType) {
    const GlyphStyle style = criticalPointGlyph(type);
    const auto outline = glyphOutline(style.shape);
    const double radiusPx = 0.5 * sizePx * style.scale;
    scene.renderer().addProp(flatActor(
        glyphRings(centres, outline, radiusPx / pixelsPerUnit,
                   (radiusPx + kOutlinePx) / pixelsPerUnit, overlayDepth(scene, kOutlineLevel)),
        kOutline));
    scene.renderer().addProp(flatActor(
        filledGlyphs(centres, outline, radiusPx / pixelsPerUnit, overlayDepth(scene, kFillLevel)),
        style.fill));
  }
}

// ---------------------------------------------------------------------------------------------
// Legend strip

namespace {

struct LegendStyle {
  Rgb background, text;
  int fontPx;
};

LegendStyle legendStyle(Background background, int width) {
  const bool dark = background == Background::dark;
  // The label size of field pictures (FieldImage.cpp): 2.1 % of the picture, at least 10 px.
  return {dark ? Rgb{0.08, 0.08, 0.10} : Rgb{1.0, 1.0, 1.0},
          dark ? Rgb{0.95, 0.95, 0.95} : Rgb{0.0, 0.0, 0.0},
          std::clamp(static_cast<int>(std::lround(0.021 * width)), 10, 64)};
}

void applyTextStyle(vtkTextProperty* t, const LegendStyle& s) {
  t->SetFontFamilyToArial();
  t->SetFontSize(s.fontPx);
  t->SetColor(s.text[0], s.text[1], s.text[2]);
  t->SetBold(false);
  t->SetItalic(false);
  t->SetShadow(false);
  t->SetJustificationToLeft();
  t->SetVerticalJustificationToCentered();
}

int textWidth(const LegendStyle& style, const std::string& text) {
  vtkNew<vtkTextProperty> p;
  applyTextStyle(p, style);
  int box[4] = {0, 0, 0, 0};
  vtkTextRenderer* r = vtkTextRenderer::GetInstance();
  if (text.empty() || r == nullptr || !r->GetBoundingBox(p, text, box, 72)) return 0;
  return box[1] - box[0] + 1;
}

// A 2D actor (display coordinates: x right, y up from the bottom-left pixel). 2D actors of one
// layer are not drawn in a defined order, so what must cover goes to a higher layer.
vtkSmartPointer<vtkActor2D> actor2D(vtkPolyData* data, const Rgb& colour, int layer,
                                    double lineWidth = 1) {
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(lineWidth));
  actor->SetLayerNumber(layer);
  return actor;
}

vtkSmartPointer<vtkPolyData> lineSample(double x0, double x1, double y) {
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(x0, y, 0);
  points->InsertNextPoint(x1, y, 0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[2] = {0, 1};
  cells->InsertNextCell(2, ids);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(cells);
  return data;
}

struct PlacedEntry {
  const LegendEntry* entry;
  double x, row;  // left edge of the symbol (px), row number from the top
};

}  // namespace

void addGlyphs2D(OffscreenRenderer& renderer, const std::vector<std::array<double, 2>>& centres,
                 const std::string& type, double sizePx) {
  addGlyphs2D(renderer, centres, criticalPointGlyph(type), sizePx);
}

void addGlyphs2D(OffscreenRenderer& renderer, const std::vector<std::array<double, 2>>& centres,
                 const GlyphStyle& g, double sizePx) {
  if (centres.empty()) return;
  const auto outline = glyphOutline(g.shape);
  const double r = 0.5 * sizePx * g.scale;
  std::vector<Vec3> at;
  for (const auto& c : centres) at.emplace_back(c[0], c[1], 0.0);
  renderer.addProp(actor2D(glyphRings(at, outline, r, r + kOutlinePx, 0), kOutline, 1));
  renderer.addProp(actor2D(filledGlyphs(at, outline, r, 0), g.fill, 2));
}

RgbaImage renderGlyphLegend(const std::vector<LegendEntry>& entries, int width,
                            Background background, double glyphPx) {
  if (entries.empty() || width < 16) return RgbaImage{};
  const LegendStyle style = legendStyle(background, width);
  const double symbol = std::max(glyphPx * 1.4, 2.0 * style.fontPx);  // symbol column width
  const double gap = style.fontPx * 0.4, spacing = style.fontPx * 1.6;
  const double rowHeight = std::max(glyphPx * 1.5, style.fontPx * 1.7);
  const double margin = style.fontPx;
  // Flow layout: entries left to right, a new row when the next would not fit.
  std::vector<PlacedEntry> placed;
  double x = margin, row = 0;
  for (const LegendEntry& e : entries) {
    const double w = symbol + gap + textWidth(style, e.label);
    if (x > margin && x + w > width - margin) x = margin, row += 1;
    placed.push_back({&e, x, row});
    x += w + spacing;
  }
  const int height = static_cast<int>(std::ceil((row + 1) * rowHeight + margin));
  OffscreenRenderer renderer(width, height, style.background);
  for (const PlacedEntry& p : placed) {
    const double cy = height - (0.5 * margin + (p.row + 0.5) * rowHeight);
    const double cx = p.x + 0.5 * symbol;
    if (p.entry->line) {
      // The line as drawn over pictures: a dark outline under a light line (and vice versa).
      const Rgb& c = p.entry->line_color;
      const bool light = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2] > 0.5;
      const Rgb edge = light ? Rgb{0, 0, 0} : Rgb{1, 1, 1};
      renderer.addProp(actor2D(lineSample(p.x, p.x + symbol, cy + 2), edge, 1, 1.0));
      renderer.addProp(actor2D(lineSample(p.x, p.x + symbol, cy - 2), edge, 1, 1.0));
      renderer.addProp(actor2D(lineSample(p.x, p.x + symbol, cy), c, 2, 3.0));
    } else {
      if (p.entry->dot_color)
        addGlyphs2D(renderer, {{cx, cy}}, GlyphStyle{GlyphShape::Circle, *p.entry->dot_color, 1.0},
                    glyphPx);
      else
        addGlyphs2D(renderer, {{cx, cy}}, p.entry->type, glyphPx);
    }
    auto label = vtkSmartPointer<vtkTextActor>::New();
    label->SetInput(p.entry->label.c_str());
    label->SetTextScaleModeToNone();
    applyTextStyle(label->GetTextProperty(), style);
    label->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    label->SetPosition(p.x + symbol + gap, cy);
    renderer.addProp(label);
  }
  return renderer.render();
}

RgbaImage stackImages(const RgbaImage& top, const RgbaImage& bottom,
                      const std::array<std::uint8_t, 3>& fill) {
  RgbaImage out;
  out.width = std::max(top.width, bottom.width);
  out.height = top.height + bottom.height;
  out.pixels.resize(4 * static_cast<std::size_t>(out.width) * out.height);
  for (std::size_t i = 0; i < out.pixels.size(); i += 4) {
    std::memcpy(&out.pixels[i], fill.data(), 3);
    out.pixels[i + 3] = 255;
  }
  auto copy = [&](const RgbaImage& img, int firstRow) {
    for (int y = 0; y < img.height; ++y)
      std::memcpy(&out.pixels[4 * (static_cast<std::size_t>(firstRow + y) * out.width)],
                  &img.pixels[4 * static_cast<std::size_t>(y) * img.width],
                  4 * static_cast<std::size_t>(img.width));
  };
  copy(top, 0);
  copy(bottom, top.height);
  return out;
}

}  // namespace fluidviz
