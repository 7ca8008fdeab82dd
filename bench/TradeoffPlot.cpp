#include "TradeoffPlot.h"

#include <omp.h>

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
#include <array>
#include <cmath>
#include <cstdio>

#include "fieldviz/render/OffscreenRenderer.h"

namespace fluidviz::bench {

namespace {

void addPolyline(fluidviz::OffscreenRenderer& r, const std::vector<std::array<double, 2>>& pts,
                 const std::array<double, 3>& color, double width, bool closed = false) {
  vtkNew<vtkPoints> points;
  for (const auto& p : pts) points->InsertNextPoint(p[0], p[1], 0.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType count = static_cast<vtkIdType>(pts.size()) + (closed ? 1 : 0);
  lines->InsertNextCell(count);
  for (vtkIdType i = 0; i < count; ++i) lines->InsertCellPoint(i % static_cast<vtkIdType>(pts.size()));
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkActor2D> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  r.addProp(actor);
}

void addText(fluidviz::OffscreenRenderer& r, const std::string& text, double x, double y, int size,
             int hJustify, int vJustify, const std::array<double, 3>& color = {0, 0, 0},
             bool bold = false) {
  vtkNew<vtkTextActor> t;
  t->SetInput(text.c_str());
  t->SetDisplayPosition(static_cast<int>(x), static_cast<int>(y));
  vtkTextProperty* p = t->GetTextProperty();
  p->SetFontSize(size);
  p->SetColor(color[0], color[1], color[2]);
  p->SetBold(bold);
  p->SetJustification(hJustify);       // 0 left, 1 centred, 2 right
  p->SetVerticalJustification(vJustify);  // 0 bottom, 1 centred, 2 top
  r.addProp(t);
}

}  // namespace

void writeTradeoffPlot(const std::vector<TradeoffPoint>& points,
                       const std::vector<TradeoffPanel>& panels, const std::string& title,
                       const std::string& footnote, const std::filesystem::path& png) {
  // A lone panel gets twice the width, so that the title fits.
  const int panelW = panels.size() == 1 ? 880 : 440, panelH = 470;
  const int width = panelW * static_cast<int>(panels.size()), height = 560;
  fluidviz::OffscreenRenderer r(width, height);
  const std::vector<std::array<double, 3>> palette{{0.12, 0.47, 0.71}, {0.84, 0.15, 0.16},
                                                   {0.17, 0.63, 0.17}, {1.00, 0.50, 0.05},
                                                   {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29}};
  addText(r, title, width / 2.0, height - 12, 20, 1, 2, {0, 0, 0}, true);
  addText(r, footnote, width / 2.0, 2, 13, 1, 0);
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const TradeoffPanel& panel = panels[p];
    std::vector<const TradeoffPoint*> mine;
    for (const TradeoffPoint& pt : points)
      if (pt.reference == panel.title) mine.push_back(&pt);
    if (mine.empty()) continue;
    double tMin = 1e300, tMax = 0, eMin = 1e300, eMax = 0;
    for (const TradeoffPoint* pt : mine) {
      tMin = std::min(tMin, pt->seconds);
      tMax = std::max(tMax, pt->seconds);
      eMin = std::min(eMin, pt->error);
      eMax = std::max(eMax, pt->error);
    }
    const double lt0 = std::floor(std::log10(std::max(tMin, 1e-4))), lt1 = std::ceil(std::log10(tMax));
    const double le0 = std::floor(std::log10(eMin)), le1 = std::ceil(std::log10(eMax));
    const double x0 = p * panelW + 80, x1 = (p + 1) * panelW - 25, y0 = 70, y1 = y0 + panelH - 60;
    auto X = [&](double t) { return x0 + (std::log10(std::max(t, 1e-4)) - lt0) / std::max(lt1 - lt0, 1.0) * (x1 - x0); };
    auto Y = [&](double e) { return y0 + (std::log10(e) - le0) / std::max(le1 - le0, 1.0) * (y1 - y0); };
    // Grid and decade labels.
    for (double d = lt0; d <= lt1 + 1e-9; d += 1) {
      addPolyline(r, {{X(std::pow(10, d)), y0}, {X(std::pow(10, d)), y1}}, {0.85, 0.85, 0.85}, 1);
      char s[32];
      std::snprintf(s, sizeof s, "%g s", std::pow(10, d));
      addText(r, s, X(std::pow(10, d)), y0 - 6, 13, 1, 2);
    }
    for (double d = le0; d <= le1 + 1e-9; d += 1) {
      addPolyline(r, {{x0, Y(std::pow(10, d))}, {x1, Y(std::pow(10, d))}}, {0.85, 0.85, 0.85}, 1);
      char s[32];
      std::snprintf(s, sizeof s, "1e%d", static_cast<int>(d));
      addText(r, s, x0 - 6, Y(std::pow(10, d)), 13, 2, 1);
    }
    addPolyline(r, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {0, 0, 0}, 1.5, true);
    addText(r, panel.title, (x0 + x1) / 2, y1 + 28, 17, 1, 1, {0, 0, 0}, true);
    addText(r, "wall time", (x0 + x1) / 2, y0 - 30, 14, 1, 2);
    addText(r, "error", x0 - 40, y1 + 28, 14, 1, 1);
    for (std::size_t v = 0; v < panel.variants.size(); ++v) {
      const auto& color = palette[v % palette.size()];
      std::vector<std::array<double, 2>> line;
      for (const TradeoffPoint* pt : mine)
        if (pt->variant == panel.variants[v]) line.push_back({X(pt->seconds), Y(pt->error)});
      if (line.empty()) continue;
      if (line.size() > 1) addPolyline(r, line, color, 2.5);
      for (const TradeoffPoint* pt : mine) {
        if (pt->variant != panel.variants[v]) continue;
        const double cx = X(pt->seconds), cy = Y(pt->error), h = 4;
        addPolyline(r, {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}},
                    color, 2, true);
        addText(r, std::to_string(pt->n), cx + 6, cy + 4, 11, 0, 0, color);
      }
      // Legend, lower left of the panel.
      const double ly = y0 + 14 + 18.0 * (panel.variants.size() - 1 - v);
      addPolyline(r, {{x0 + 12, ly}, {x0 + 36, ly}}, color, 3);
      addText(r, panel.variants[v], x0 + 42, ly, 13, 0, 1, color);
    }
  }
  r.renderToPng(png);
}


TradeoffArgs parseTradeoffArgs(int argc, char** argv) {
  TradeoffArgs args;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--quick")
      args.quick = true;
    else
      args.outDir = arg;
  }
  std::filesystem::create_directories(args.outDir);
  omp_set_num_threads(1);
  return args;
}

}  // namespace fluidviz::bench
