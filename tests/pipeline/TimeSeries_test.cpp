// pipeline/TimeSeries.h: the oscillation summary the run logs for drag and lift (mean, extremes
// and frequency over the second half of a series), on signals whose answer is known exactly.
#include "pipeline/TimeSeries.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fluidviz {
namespace {

constexpr double kPi = 3.14159265358979323846;

// 3 + 0.5 sin(2 pi f t) sampled every dt on [0, end].
void sine(double f, double dt, double end, std::vector<double>& t, std::vector<double>& v) {
  for (int n = 0; n * dt <= end + 1e-12; ++n) {
    t.push_back(n * dt);
    v.push_back(3.0 + 0.5 * std::sin(2 * kPi * f * t.back()));
  }
}

// Mean, extremes and frequency of a sine to the sampling's accuracy: the extremes are samples
// (off the peak by at most 1 - cos(pi f dt) = 2e-3 of the amplitude at f dt = 0.02), the mean
// over whole periods is exact, the crossings are placed by linear interpolation.
TEST(OscillationSummary, SineGivesItsMeanExtremesAndFrequency) {
  std::vector<double> t, v;
  sine(2.0, 0.01, 10.0, t, v);
  const OscillationSummary s = summarizeOscillation(t, v);
  EXPECT_DOUBLE_EQ(s.from, 5.0);
  EXPECT_NEAR(s.mean, 3.0, 1e-3);  // 501 samples over 10 periods: one sample off whole periods
  EXPECT_NEAR(s.max, 3.5, 0.5 * 2e-3);
  EXPECT_NEAR(s.min, 2.5, 0.5 * 2e-3);
  EXPECT_NEAR(s.frequency, 2.0, 2e-3);
}

// Fewer than three upward crossings (two periods) give no frequency: a steady flow's
// coefficient, a single bump.
TEST(OscillationSummary, SteadyOrShortSeriesHasNoFrequency) {
  std::vector<double> t, v;
  sine(0.15, 0.01, 10.0, t, v);  // 0.75 periods in the second half
  EXPECT_TRUE(std::isnan(summarizeOscillation(t, v).frequency));
  const std::vector<double> flat(t.size(), 5.58);
  const OscillationSummary s = summarizeOscillation(t, flat);
  EXPECT_TRUE(std::isnan(s.frequency));
  EXPECT_NEAR(s.mean, 5.58, 1e-12);  // a sum of 501 terms
  EXPECT_DOUBLE_EQ(s.min, 5.58);
  EXPECT_TRUE(std::isnan(summarizeOscillation({}, {}).frequency));
}

}  // namespace
}  // namespace fluidviz
