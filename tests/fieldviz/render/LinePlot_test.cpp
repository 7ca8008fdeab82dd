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

RgbaImage cropped(const RgbaImage& img, int x0, int y0, int w, int h) {
  RgbaImage out{w, h, std::vector<std::uint8_t>(4 * w * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) out.pixels[4 * (y * w + x) + c] = img.pixel(x0 + x, y0 + y)[c];
  return out;
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

// The drag coefficient of examples/cylinder_channel.json spans -0.0 to 3.33: vtkAxis's own
// ticks read -0.2, 0.3, 0.8, ...; the axis now ends on round ticks around the data.
TEST(LinePlot, AxesEndOnRoundTicksAroundTheData) {
  const AxisTicks drag = plotAxisTicks({-2.2e-15, 3.332});
  EXPECT_DOUBLE_EQ(drag.step, 0.5);
  EXPECT_EQ(drag.range[0], 0.0);  // -2e-15 is round-off on 0, not a reason for a -0.5 tick
  EXPECT_NEAR(drag.range[1], 3.5, 1e-12);
  ASSERT_EQ(drag.labels.size(), 8u);
  EXPECT_EQ(drag.labels.front(), "0.0");
  EXPECT_EQ(drag.labels[1], "0.5");
  EXPECT_EQ(drag.labels.back(), "3.5");
  EXPECT_NEAR(plotAxisTicks({-0.2, 3.332}).range[0], -0.5, 1e-12);
  const AxisTicks time = plotAxisTicks({0, 12});
  EXPECT_EQ(time.range, (std::array<double, 2>{0, 12}));
  EXPECT_EQ(time.labels, (std::vector<std::string>{"0", "2", "4", "6", "8", "10", "12"}));
  const AxisTicks constant = plotAxisTicks({2, 2});  // a window around the one value
  EXPECT_LT(constant.range[0], 2);
  EXPECT_GT(constant.range[1], 2);
  const AxisTicks none = plotAxisTicks({INFINITY, -INFINITY});  // no finite point
  EXPECT_EQ(none.range, (std::array<double, 2>{0, 1}));
}

// One series draws no legend: its box would hide the curve's top right (seen on the drag plot).
TEST(LinePlot, OneSeriesDrawsNoLegend) {
  // From the top left to the bottom right: the top right corner, where a legend goes, stays free.
  const PlotSeries falling{"simulation", {0, 1}, {1, 0}, PlotMarks::line};
  const RgbaImage img = renderLinePlot({falling}, {600, 400, "", "x (m)", "u (m/s)"});
  const RgbaImage right = cropped(img, 400, 0, 200, 120);
  EXPECT_GT(countNear(img, {0, 114, 178}, 0, 400), 200);
  EXPECT_EQ(countNear(right, {0, 114, 178}, 0, right.height), 0);
  // Two series do get a legend there (its sample lines in the two colours).
  const PlotSeries rising{"reference", {0, 1}, {0, 1}, PlotMarks::markers};
  const RgbaImage two = cropped(renderLinePlot({falling, rising}, {600, 400, "", "", ""}), 400,
                                0, 200, 120);
  EXPECT_GT(countNear(two, {0, 114, 178}, 0, two.height), 10);
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
