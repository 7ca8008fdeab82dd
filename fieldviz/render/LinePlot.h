#pragma once
// Line plots of profiles and time series (x-y charts): one or more series drawn as lines or as
// markers (reference data), with a title, axis titles with units, round tick values and a
// legend naming each series. Drawn by VTK's chart (vtkChartXY in a vtkContextActor) through the
// off-screen renderer (no X needed).
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

/// The chart. Throws std::invalid_argument for a size out of range, no series, or a series
/// whose x and y differ in size.
RgbaImage renderLinePlot(const std::vector<PlotSeries>& series, const LinePlotParams& params);

}  // namespace fluidviz
