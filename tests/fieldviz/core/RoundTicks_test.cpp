#include "fieldviz/core/RoundTicks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

namespace fluidviz {
namespace {

std::vector<std::string> labels(const RoundTicks& t) {
  std::vector<std::string> out;
  for (double v : t.values) {
    char text[64];
    std::snprintf(text, sizeof text, tickLabelFormat(t).c_str(), v);
    out.emplace_back(text);
  }
  return out;
}

// Heckbert's examples: steps of 1, 2 or 5 x 10^k, every multiple inside the range.
TEST(RoundTicks, StepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(roundTicks(0, 2.5).step, 0.5);
  EXPECT_EQ(labels(roundTicks(0, 2.5)), (std::vector<std::string>{"0.0", "0.5", "1.0", "1.5", "2.0", "2.5"}));
  EXPECT_DOUBLE_EQ(roundTicks(-60, 60).step, 20);
  EXPECT_EQ(labels(roundTicks(-60, 60)).front(), "-60");
  EXPECT_EQ(roundTicks(-60, 60).values.size(), 7u);
  EXPECT_DOUBLE_EQ(roundTicks(0, 1.3717).step, 0.2);  // a cavity's max speed
  for (double hi : {0.37, 3.7, 37.0, 3.7e5, 1.0, 9.99})
    for (double lo : {0.0, -hi / 3}) {
      const RoundTicks t = roundTicks(lo, hi);
      const double m = t.step / std::pow(10.0, std::floor(std::log10(t.step) + 1e-12));
      EXPECT_TRUE(std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 5) < 1e-9)
          << lo << " " << hi << " step " << t.step;
      EXPECT_GE(t.values.size(), 3u);
      EXPECT_LE(t.values.size(), 7u);
      for (double v : t.values) {
        EXPECT_GE(v, lo - 1e-9 * (hi - lo));
        EXPECT_LE(v, hi + 1e-9 * (hi - lo));
        EXPECT_NEAR(v / t.step, std::round(v / t.step), 1e-9);
      }
    }
}

// The axis ranges of the bifurcation diagrams (roller positions in m, speed ratios).
TEST(RoundTicks, DiagramRangesGetFiveTicks) {
  auto expectTicks = [](const std::vector<double>& got, const std::vector<double>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12);
  };
  expectTicks(roundTicks(0.46, 0.54).values, {0.46, 0.48, 0.5, 0.52, 0.54});
  expectTicks(roundTicks(-3.0, 7.0).values, {-2, 0, 2, 4, 6});
  EXPECT_NEAR(roundTicks(0.0013, 0.0091).step, 0.002, 1e-12);
}

// A range whose bound is zero up to round-off still labels 0 (it was dropped before).
TEST(RoundTicks, RoundOffAtABoundKeepsTheZeroTick) {
  const RoundTicks t = roundTicks(-1e-17, 5.0);
  ASSERT_FALSE(t.values.empty());
  EXPECT_EQ(t.values.front(), 0.0);
  EXPECT_EQ(labels(t).front(), "0");
  EXPECT_EQ(labels(roundTicks(-5.0, 1e-16)).back(), "0");
}

// A settled SPH density 1000-1000.25 kg/m^3: labels differ and say 1000.05, not "1e+03".
TEST(RoundTicks, NarrowRangeFarFromZeroPrintsDistinctLabels) {
  const std::vector<std::string> l = labels(roundTicks(1000.0, 1000.25));
  EXPECT_EQ(std::set<std::string>(l.begin(), l.end()).size(), l.size());
  EXPECT_EQ(l.front(), "1000.00");
  EXPECT_EQ(l[1], "1000.05");
}

TEST(RoundTicks, TinyAndHugeValuesUseExponents) {
  const std::vector<std::string> small = labels(roundTicks(-1e-6, 1e-6));
  EXPECT_EQ(small.front(), "-1.0e-06");
  EXPECT_EQ(std::set<std::string>(small.begin(), small.end()).size(), small.size());
  EXPECT_EQ(labels(roundTicks(0, 4e7)).back(), "4.0e+07");
}

TEST(RoundTicks, EmptyOrNonFiniteRangeIsRefused) {
  EXPECT_THROW(roundTicks(1, 1), std::invalid_argument);
  EXPECT_THROW(roundTicks(2, 1), std::invalid_argument);
  EXPECT_THROW(roundTicks(0, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz
