#include "fieldviz/render/LinePlot.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "fieldviz/core/RoundTicks.h"

namespace fluidviz {

namespace {

// Colours of successive series (Okabe & Ito's colour-blind-safe palette), 0-255.
constexpr std::array<std::array<unsigned char, 3>, 6> kPalette{
    {{0, 114, 178}, {213, 94, 0}, {0, 158, 115}, {204, 121, 167}, {230, 159, 0}, {86, 180, 233}}};

void checkPlot(const std::vector<PlotSeries>& series, const LinePlotParams& p) {
  if (p.width < 200 || p.width > 8192 || p.height < 150 || p.height > 8192)
    throw std::invalid_argument("plot size " + std::to_string(p.width) + " x " +
                                std::to_string(p.height) +
                                " px is outside [200, 8192] x [150, 8192]");
  if (series.empty()) throw std::invalid_argument("a plot needs at least one series");
  for (const PlotSeries& s : series)
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("plot series '" + s.label + "' has " +
                                  std::to_string(s.x.size()) + " x values but " +
                                  std::to_string(s.y.size()) + " y values");
}

// The finite points of a series as a two-column table ("x", label).
vtkSmartPointer<vtkTable> seriesTable(const PlotSeries& s) {
  vtkNew<vtkDoubleArray> x, y;
  x->SetName("x");
  y->SetName(s.label.c_str());
  for (std::size_t n = 0; n < s.x.size(); ++n)
    if (std::isfinite(s.x[n]) && std::isfinite(s.y[n])) {
      x->InsertNextValue(s.x[n]);
      y->InsertNextValue(s.y[n]);
    }
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

void styleText(vtkTextProperty* t, int px, bool bold = false) {
  t->SetFontFamilyToArial();
  t->SetFontSize(px);
  t->SetColor(0, 0, 0);
  t->SetBold(bold);
}

void styleAxis(vtkAxis* axis, const std::string& title, const AxisTicks& ticks, int fontPx) {
  axis->SetTitle(title);
  styleText(axis->GetTitleProperties(), fontPx);
  styleText(axis->GetLabelProperties(), fontPx);
  axis->GetTitleProperties()->SetBold(false);
  // vtkAxis's own ticks follow its padded range (-0.2, 0.3, 0.8, ...): fixed range, our ticks.
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(ticks.range[0], ticks.range[1]);
  vtkNew<vtkDoubleArray> positions;
  vtkNew<vtkStringArray> labels;
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    positions->InsertNextValue(ticks.values[i]);
    labels->InsertNextValue(ticks.labels[i]);
  }
  axis->SetCustomTickPositions(positions, labels);
  axis->GetGridPen()->SetColor(220, 220, 220);
}

// The finite values of one coordinate over all series.
std::array<double, 2> dataRange(const std::vector<PlotSeries>& series, bool yAxis) {
  std::array<double, 2> r{std::numeric_limits<double>::infinity(),
                          -std::numeric_limits<double>::infinity()};
  for (const PlotSeries& s : series)
    for (std::size_t n = 0; n < s.x.size(); ++n)
      if (std::isfinite(s.x[n]) && std::isfinite(s.y[n])) {
        const double v = yAxis ? s.y[n] : s.x[n];
        r = {std::min(r[0], v), std::max(r[1], v)};
      }
  return r;
}

void addSeries(vtkChartXY& chart, const PlotSeries& s, std::size_t index, float lineWidth) {
  const auto& c = kPalette[index % kPalette.size()];
  vtkPlot* plot = chart.AddPlot(s.marks == PlotMarks::line ? vtkChart::LINE : vtkChart::POINTS);
  plot->SetInputData(seriesTable(s), 0, 1);
  plot->SetColor(c[0], c[1], c[2], 255);
  plot->SetWidth(lineWidth);
  plot->SetLabel(s.label);
  if (auto* points = vtkPlotPoints::SafeDownCast(plot)) {
    points->SetMarkerStyle(s.marks == PlotMarks::line ? vtkPlotPoints::NONE
                                                      : vtkPlotPoints::CIRCLE);
    points->SetMarkerSize(2.5f * lineWidth + 4.0f);
  }
}

}  // namespace

AxisTicks plotAxisTicks(std::array<double, 2> range) {
  if (!std::isfinite(range[0]) || !std::isfinite(range[1])) range = {0, 1};  // nothing to draw
  if (!(range[0] < range[1])) {  // one value: a unit-wide window around it
    const double half = std::max(0.5 * std::abs(range[0]), 0.5);
    range = {range[0] - half, range[0] + half};
  }
  // Loose labelling (Heckbert 1990): the axis ends on the round multiples around the data.
  const double step = roundTicks(range[0], range[1], 6).step;
  AxisTicks t;
  t.range = {std::floor(range[0] / step + 1e-9) * step, std::ceil(range[1] / step - 1e-9) * step};
  const RoundTicks round = roundTicks(t.range[0], t.range[1], 6);
  t.step = round.step;
  t.values = round.values;
  const std::string format = tickLabelFormat(round);
  for (double v : t.values) {
    char text[64];
    std::snprintf(text, sizeof text, format.c_str(), v);
    t.labels.push_back(text);
  }
  return t;
}

RgbaImage renderLinePlot(const std::vector<PlotSeries>& series, const LinePlotParams& params) {
  checkPlot(series, params);
  const int shortSide = std::min(params.width, params.height);
  const int fontPx = std::max(10, static_cast<int>(std::lround(0.028 * shortSide)));
  const float lineWidth = std::max(1.5f, 0.004f * static_cast<float>(shortSide));

  OffscreenRenderer r(params.width, params.height);
  vtkNew<vtkChartXY> chart;
  chart->SetTitle(params.title);
  styleText(chart->GetTitleProperties(), static_cast<int>(std::lround(1.25 * fontPx)), true);
  styleAxis(chart->GetAxis(vtkAxis::BOTTOM), params.x_label,
            plotAxisTicks(dataRange(series, false)), fontPx);
  styleAxis(chart->GetAxis(vtkAxis::LEFT), params.y_label, plotAxisTicks(dataRange(series, true)),
            fontPx);
  for (std::size_t i = 0; i < series.size(); ++i) addSeries(*chart, series[i], i, lineWidth);
  // One series needs no legend (the title and the axis say what it is); the legend box sits
  // inside the plot area and would only hide part of the curve.
  chart->SetShowLegend(series.size() > 1);
  styleText(chart->GetLegend()->GetLabelProperties(), fontPx);
  chart->SetAutoSize(true);

  vtkNew<vtkContextActor> actor;
  actor->GetScene()->AddItem(chart);
  actor->GetScene()->SetRenderer(r.renderer());
  r.addProp(actor);
  return r.render();
}

}  // namespace fluidviz
