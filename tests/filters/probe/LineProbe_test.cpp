// Line probes on analytic fields: bilinear (2D) and trilinear (3D) interpolation reproduce a
// field of the form a + b x + c y + d xy (+ e z + ... + h xyz) exactly, so a profile along any
// line inside the grid equals the formula to round-off (1e-12 relative to the values, ~1).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "filters/probe/LineProbe.h"

namespace fluidviz::probe {
namespace {

double bilinear(const Vec3& p) { return 0.3 + 0.7 * p.x() - 0.4 * p.y() + 1.1 * p.x() * p.y(); }
double trilinear(const Vec3& p) {
  return bilinear(p) + 0.5 * p.z() - 0.8 * p.x() * p.z() + 0.9 * p.x() * p.y() * p.z();
}

template <class F>
ScalarField analyticField(const Grid& g, F f) {
  ScalarField s{"f", g, std::vector<double>(g.nodeCount())};
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) s.values[g.index(i, j, k)] = f(g.position(i, j, k));
  return s;
}

Grid grid2D() {
  Grid g;
  g.dims = {11, 7, 1};
  g.origin = {0.05, 0.05, 0.0};
  g.spacing = {0.1, 0.15, 1.0};
  return g;
}

TEST(LineProbe, DiagonalOfBilinearFieldIsExact) {
  const ScalarField f = analyticField(grid2D(), bilinear);
  const ProbeLine line{{0.1, 0.2, 0.0}, {0.9, 0.85, 0.0}, 17};
  const auto profile = sampleLine(f, line);
  ASSERT_EQ(profile.size(), 17u);
  EXPECT_DOUBLE_EQ(profile.front().distance, 0.0);
  EXPECT_NEAR(profile.back().distance, line.length(), 1e-15);
  for (const ProfilePoint& p : profile) EXPECT_NEAR(p.value, bilinear(p.position), 1e-12);
  EXPECT_NEAR(profile[8].position.x(), 0.5, 1e-15);  // the middle sample is the line's midpoint
  EXPECT_NEAR(profile[8].position.y(), 0.525, 1e-15);
}

TEST(LineProbe, TrilinearFieldIsExactIn3D) {
  Grid g;
  g.dims = {6, 5, 4};
  g.spacing = {0.2, 0.25, 0.3};
  const ScalarField f = analyticField(g, trilinear);
  const ProbeLine line{{0.05, 0.9, 0.1}, {0.95, 0.1, 0.85}, 9};
  for (const ProfilePoint& p : sampleLine(f, line))
    EXPECT_NEAR(p.value, trilinear(p.position), 1e-12);
}

TEST(LineProbe, PointsOutsideTheGridAreNaN) {
  const ScalarField f = analyticField(grid2D(), bilinear);  // nodes x in [0.05, 1.05]
  const auto profile = sampleLine(f, {{0.0, 0.5, 0.0}, {1.0, 0.5, 0.0}, 3});
  EXPECT_TRUE(std::isnan(profile[0].value));
  EXPECT_NEAR(profile[1].value, bilinear({0.5, 0.5, 0.0}), 1e-12);
  EXPECT_NEAR(profile[2].value, bilinear({1.0, 0.5, 0.0}), 1e-12);
}

TEST(LineProbe, DeviationFromReferenceSkipsPointsOutside) {
  const ScalarField f = analyticField(grid2D(), bilinear);
  const ProbeLine line{{0.0, 0.5, 0.0}, {1.0, 0.5, 0.0}, 5};  // s = x
  // Reference = field + offsets 0.1 and -0.3 inside, one point outside the grid (x = 0).
  const std::vector<ReferencePoint> ref{{0.0, 99.0},
                                        {0.25, bilinear({0.25, 0.5, 0}) + 0.1},
                                        {0.75, bilinear({0.75, 0.5, 0}) - 0.3}};
  const ProfileDeviation d = compareWithReference(f, line, ref);
  EXPECT_EQ(d.compared, 2);
  EXPECT_NEAR(d.max, 0.3, 1e-12);
  EXPECT_NEAR(d.rms, std::sqrt((0.01 + 0.09) / 2), 1e-12);
  EXPECT_EQ(compareWithReference(f, line, {{0.0, 1.0}}).compared, 0);
}

TEST(LineProbe, RejectsDegenerateLines) {
  const ScalarField f = analyticField(grid2D(), bilinear);
  EXPECT_THROW(sampleLine(f, {{0.1, 0.1, 0}, {0.1, 0.1, 0}, 5}), std::invalid_argument);
  EXPECT_THROW(sampleLine(f, {{0.1, 0.1, 0}, {0.5, 0.1, 0}, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz::probe
