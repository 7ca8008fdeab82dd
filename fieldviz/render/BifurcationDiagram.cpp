#include "fieldviz/render/BifurcationDiagram.h"

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "fieldviz/core/RoundTicks.h"
#include "fieldviz/render/CriticalPointGlyphs.h"
#include "fieldviz/render/OffscreenRenderer.h"

namespace fluidviz {

namespace {

// Round ticks inside [lo, hi] (fieldviz/core/RoundTicks.h); none for an empty range.
std::vector<double> axisTicks(double lo, double hi) {
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) return {};
  return roundTicks(lo, hi).values;
}

struct DiagramStyle {
  Rgb background, text, frame, grid;
  int fontPx, titlePx;
};

DiagramStyle styleFor(const BifurcationDiagramParams& p) {
  const bool dark = p.background == Background::dark;
  const int shortSide = std::min(p.width, p.height);
  return {dark ? Rgb{0.08, 0.08, 0.10} : Rgb{1, 1, 1}, dark ? Rgb{0.95, 0.95, 0.95} : Rgb{0, 0, 0},
          dark ? Rgb{0.8, 0.8, 0.8} : Rgb{0.2, 0.2, 0.2},
          dark ? Rgb{0.3, 0.3, 0.33} : Rgb{0.85, 0.85, 0.85},
          std::clamp(static_cast<int>(std::lround(0.03 * shortSide)), 10, 48),
          std::clamp(static_cast<int>(std::lround(0.042 * shortSide)), 12, 72)};
}

// A rectangle in display pixels (origin bottom-left) and the value ranges it shows.
struct Panel {
  double left, bottom, right, top;
  std::array<double, 2> xRange, yRange;
  double px(double v) const {
    return left + (v - xRange[0]) / (xRange[1] - xRange[0]) * (right - left);
  }
  double py(double v) const {
    return bottom + (v - yRange[0]) / (yRange[1] - yRange[0]) * (top - bottom);
  }
};

std::string formatTick(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

void addLines(OffscreenRenderer& r, const std::vector<std::array<double, 4>>& segments,
              const Rgb& colour, double width) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (const auto& s : segments) {
    const vtkIdType a = points->InsertNextPoint(s[0], s[1], 0);
    const vtkIdType b = points->InsertNextPoint(s[2], s[3], 0);
    const vtkIdType ids[2] = {a, b};
    cells->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(cells);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(data);
  vtkNew<vtkActor2D> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  r.addProp(actor);
}

// Text centred on (x, y) in display pixels, optionally turned by 90 degrees.
void addText(OffscreenRenderer& r, const std::string& text, double x, double y, int fontPx,
             const Rgb& colour, bool bold = false, double angle = 0.0) {
  vtkNew<vtkTextActor> t;
  t->SetInput(text.c_str());
  t->SetTextScaleModeToNone();
  vtkTextProperty* p = t->GetTextProperty();
  p->SetFontFamilyToArial();
  p->SetFontSize(fontPx);
  p->SetColor(colour[0], colour[1], colour[2]);
  p->SetBold(bold);
  p->SetShadow(false);
  p->SetJustificationToCentered();
  p->SetVerticalJustificationToCentered();
  p->SetOrientation(angle);
  t->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
  t->SetPosition(x, y);
  r.addProp(t);
}

std::array<double, 2> padded(double lo, double hi, double fraction) {
  if (!(hi > lo)) {
    const double w = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    return {lo - w, hi + w};
  }
  const double pad = fraction * (hi - lo);
  return {lo - pad, hi + pad};
}

void drawAxes(OffscreenRenderer& r, const Panel& p, const DiagramStyle& s, const std::string& xLabel,
              const std::string& yLabel, const std::vector<double>& steps) {
  std::vector<std::array<double, 4>> grid, frame, ticks;
  for (double v : steps) grid.push_back({p.px(v), p.bottom, p.px(v), p.top});
  frame = {{p.left, p.bottom, p.right, p.bottom}, {p.right, p.bottom, p.right, p.top},
           {p.right, p.top, p.left, p.top}, {p.left, p.top, p.left, p.bottom}};
  const double tick = 0.4 * s.fontPx;
  for (double v : axisTicks(p.xRange[0], p.xRange[1])) {
    ticks.push_back({p.px(v), p.bottom, p.px(v), p.bottom + tick});
    addText(r, formatTick(v), p.px(v), p.bottom - 0.9 * s.fontPx, s.fontPx, s.text);
  }
  for (double v : axisTicks(p.yRange[0], p.yRange[1])) {
    ticks.push_back({p.left, p.py(v), p.left + tick, p.py(v)});
    addText(r, formatTick(v), p.left - 0.35 * s.fontPx - 0.3 * s.fontPx * formatTick(v).size(),
            p.py(v), s.fontPx, s.text);
  }
  addLines(r, grid, s.grid, 1.0);
  addLines(r, frame, s.frame, 1.5);
  addLines(r, ticks, s.frame, 1.5);
  addText(r, xLabel, 0.5 * (p.left + p.right), p.bottom - 2.3 * s.fontPx, s.fontPx, s.text);
  addText(r, yLabel, p.left - 3.6 * s.fontPx, 0.5 * (p.bottom + p.top), s.fontPx, s.text, false,
          90.0);
}

void drawPoints(OffscreenRenderer& r, const Panel& p, const std::vector<DiagramPoint>& points,
                bool useX, double glyphPx) {
  std::map<std::string, std::vector<std::array<double, 2>>> byType;
  for (const DiagramPoint& d : points)
    byType[d.type].push_back({p.px(d.parameter), p.py(useX ? d.x : d.y)});
  for (const auto& [type, centres] : byType) addGlyphs2D(r, centres, type, glyphPx);
}

std::vector<LegendEntry> legendFor(const std::vector<DiagramPoint>& points) {
  std::vector<LegendEntry> entries;
  for (const std::string& type : criticalPointTypeOrder()) {
    const bool present = std::any_of(points.begin(), points.end(),
                                     [&](const DiagramPoint& d) { return d.type == type; });
    if (!present) continue;
    std::string label = type;
    std::replace(label.begin(), label.end(), '_', ' ');
    entries.push_back({label, type});
  }
  return entries;
}

}  // namespace

RgbaImage renderBifurcationDiagram(const std::vector<DiagramPoint>& points,
                                   const BifurcationDiagramParams& params) {
  if (params.width < 300 || params.width > 8192 || params.height < 200 || params.height > 8192)
    throw std::invalid_argument("bifurcation diagram size " + std::to_string(params.width) +
                                " x " + std::to_string(params.height) +
                                " px is outside [300, 8192] x [200, 8192]");
  const DiagramStyle s = styleFor(params);
  double pLo = std::numeric_limits<double>::infinity(), pHi = -pLo, vLo = pLo, vHi = -pLo;
  for (double v : params.steps) pLo = std::min(pLo, v), pHi = std::max(pHi, v);
  for (const DiagramPoint& d : points) {
    pLo = std::min(pLo, d.parameter), pHi = std::max(pHi, d.parameter);
    vLo = std::min({vLo, d.x, d.y}), vHi = std::max({vHi, d.x, d.y});
  }
  if (!std::isfinite(pLo)) pLo = 0.0, pHi = 1.0;
  if (!std::isfinite(vLo)) vLo = 0.0, vHi = 1.0;
  const auto xRange = padded(pLo, pHi, 0.06);
  const auto yRange = params.position_range ? *params.position_range : padded(vLo, vHi, 0.08);

  const double left = 5.5 * s.fontPx, gap = 6.5 * s.fontPx, right = 1.5 * s.fontPx;
  const double bottom = 3.6 * s.fontPx;
  const double top = params.height - (params.title.empty() ? 1.5 * s.fontPx : 2.6 * s.titlePx);
  const double panelW = (params.width - left - gap - right) / 2;
  const Panel px{left, bottom, left + panelW, top, xRange, yRange};
  const Panel py{left + panelW + gap, bottom, left + 2 * panelW + gap, top, xRange, yRange};

  OffscreenRenderer r(params.width, params.height, s.background);
  drawAxes(r, px, s, params.parameter_label, "x of critical point (m)", params.steps);
  drawAxes(r, py, s, params.parameter_label, "y of critical point (m)", params.steps);
  drawPoints(r, px, points, true, params.glyph_size);
  drawPoints(r, py, points, false, params.glyph_size);
  if (!params.title.empty())
    addText(r, params.title, 0.5 * params.width, params.height - 1.2 * s.titlePx, s.titlePx,
            s.text, true);
  const RgbaImage diagram = r.render();
  const auto entries = legendFor(points);
  if (entries.empty()) return diagram;
  const std::uint8_t bg = params.background == Background::dark ? 20 : 255;
  return stackImages(diagram,
                     renderGlyphLegend(entries, params.width, params.background, params.glyph_size),
                     {bg, bg, bg});
}

}  // namespace fluidviz
