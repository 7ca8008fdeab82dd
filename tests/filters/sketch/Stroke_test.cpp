// Stroke filters: even resampling and Gaussian smoothing along the curve.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/filters/sketch/SketchTestFields.h"

namespace fluidviz::sketch {
namespace {

// A polyline with uneven vertices becomes points at equal arc length on the same path: on a
// straight line every interval is L / ceil(L / spacing) to round-off and the ends are the drawn
// ones.
TEST(Stroke, ResamplingIsEvenAndKeepsTheEnds) {
  const Stroke s{.points = {{0, 0, 0}, {0.3, 0.4, 0}, {0.3, 0.4, 0}, {3, 4, 0}}, .speed = 2.0};
  const Stroke r = resampleStroke(s, 0.3);
  ASSERT_EQ(r.points.size(), 18u);  // 5 / 0.3 -> 17 intervals
  for (std::size_t k = 1; k < r.points.size(); ++k) {
    EXPECT_NEAR((r.points[k] - r.points[k - 1]).norm(), 5.0 / 17, 1e-12);
    EXPECT_NEAR(r.points[k][0] * 4.0 - r.points[k][1] * 3.0, 0.0, 1e-12);  // on the line
  }
  EXPECT_EQ(r.points.back(), Vec3(3, 4, 0));
  EXPECT_EQ(r.speed, 2.0);
  EXPECT_THROW(resampleStroke(Stroke{.points = {{1, 1, 0}, {1, 1, 0}}}, 0.3),
               std::invalid_argument);
}

// Jitter of +-0.3 on a straight line drops below 0.05 after smoothing with sigma = 2 (the
// alternating pattern's Gaussian gain is exp(-2 pi^2 sigma^2 / (2 ds)^2) ~ 0); ends stay.
TEST(Stroke, SmoothingRemovesJitterAndKeepsTheEnds) {
  Stroke s = resampleStroke(testing::lineStroke({0, 0, 0}, {20, 0, 0}, 1.0), 0.5);
  for (std::size_t k = 1; k + 1 < s.points.size(); ++k) s.points[k][1] = k % 2 ? 0.3 : -0.3;
  const Stroke smooth = smoothStroke(s, 2.0);
  double jitter = 0.0;
  for (std::size_t k = 6; k + 6 < smooth.points.size(); ++k)  // beyond 3 sigma of the ends
    jitter = std::max(jitter, std::abs(smooth.points[k][1]));
  EXPECT_LT(jitter, 0.05);
  EXPECT_EQ(smooth.points.front(), s.points.front());
  EXPECT_EQ(smooth.points.back(), s.points.back());
}

}  // namespace
}  // namespace fluidviz::sketch
