// Line plots through the off-screen renderer: the picture has the asked size, a line series is
// drawn in the first palette colour (0, 114, 178), a marker series in the second (213, 94, 0),
// where the data puts them, and bad input is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "fieldviz/render/LinePlot.h"

namespace fluidviz {
namespace {

// Pixels within 40 (sum of channel differences) of a colour, in a band of rows.
int countNear(const RgbaImage& img, std::array<int, 3> c, int rowLo, int rowHi) {
  int n = 0;
  for (int y = rowLo; y < rowHi; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto p = img.pixel(x, y);
      if (std::abs(p[0] - c[0]) + std::abs(p[1] - c[1]) + std::abs(p[2] - c[2]) < 40) ++n;
    }
  return n;
}

TEST(LinePlot, DrawsLinesAndMarkersWithLegend) {
  PlotSeries line{"simulation", {}, {}, PlotMarks::line};
  for (int i = 0; i <= 50; ++i) {
    line.x.push_back(i / 50.0);
    line.y.push_back(i / 50.0);  // the diagonal
  }
  line.y[10] = std::nan("");  // left out, not drawn
  const PlotSeries ref{"reference", {0.2, 0.5, 0.8}, {0.8, 0.8, 0.8}, PlotMarks::markers};
  const RgbaImage img =
      renderLinePlot({line, ref}, {600, 400, "Test plot", "x (m)", "u (m/s)"});
  ASSERT_EQ(img.width, 600);
  ASSERT_EQ(img.height, 400);
  // The diagonal crosses the whole chart: its colour is in the top and the bottom half.
  EXPECT_GT(countNear(img, {0, 114, 178}, 40, 200), 50);
  EXPECT_GT(countNear(img, {0, 114, 178}, 200, 360), 50);
  // The markers sit at y = 0.8: in the upper half of the plot area only (the legend's marker
  // too, which is at the top right).
  EXPECT_GT(countNear(img, {213, 94, 0}, 0, 200), 30);
  EXPECT_EQ(countNear(img, {213, 94, 0}, 220, 400), 0);
}

TEST(LinePlot, RefusesBadInput) {
  const PlotSeries s{"s", {0, 1}, {0, 1}, PlotMarks::line};
  EXPECT_THROW(renderLinePlot({s}, {100, 400, "", "", ""}), std::invalid_argument);
  EXPECT_THROW(renderLinePlot({}, {600, 400, "", "", ""}), std::invalid_argument);
  EXPECT_THROW(renderLinePlot({{"bad", {0, 1}, {0}, PlotMarks::line}}, {600, 400, "", "", ""}),
               std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz
