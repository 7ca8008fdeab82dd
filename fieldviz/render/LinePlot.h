#pragma once
// Line plots of profiles and time series (x-y charts): one or more series drawn as lines or as
// markers (reference data), with a title, axis titles with units, round tick values and, for
// more than one series, a legend naming each. Drawn by VTK's chart (vtkChartXY in a vtkContextActor) through the
// off-screen renderer (no X needed).
#include <array>
#include <string>
#include <vector>

#include "fieldviz/render/OffscreenRenderer.h"
#include "fieldviz/render/RgbaImage.h"

namespace fluidviz {

enum class PlotMarks { line, markers };

struct PlotSeries {
  std::string label;  ///< legend entry
  std::vector<double> x, y;  ///< same size; points with a non-finite coordinate are left out
  PlotMarks marks = PlotMarks::line;
};

struct LinePlotParams {
  int width = 900;   ///< px, [200, 8192]
  int height = 600;  ///< px, [150, 8192]
  std::string title;
  std::string x_label;  ///< axis title with its unit, e.g. "y (m)"
  std::string y_label;
};

/// An axis of a plot: its range ends on round ticks around the data (1, 2 or 5 x 10^k,
/// fieldviz/core/RoundTicks.h), with the labels printed to the digits the step needs.
struct AxisTicks {
  std::array<double, 2> range{};
  double step = 0;  ///< between neighbouring ticks
  std::vector<double> values;
  std::vector<std::string> labels;
};

/// The axis for data spanning `range` (min, max); a single value gets a unit-wide window around
/// it, no finite data the window [0, 1].
AxisTicks plotAxisTicks(std::array<double, 2> range);

/// The chart. Throws std::invalid_argument for a size out of range, no series, or a series
/// whose x and y differ in size.
RgbaImage renderLinePlot(const std::vector<PlotSeries>& series, const LinePlotParams& params);

}  // namespace fluidviz
