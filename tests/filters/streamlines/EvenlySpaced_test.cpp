// Jobard & Lefer (1997) evenly spaced streamlines: separation and coverage.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "filters/streamlines/EvenlySpacedStreamlines.h"
#include "tests/support/AnalyticFields.h"

using namespace fluidviz;
using namespace fluidviz::streamlines;
using namespace fluidviz::testing;

namespace {

// Double gyre on [0, 2] x [0, 1]: two counter-rotating cells with centres (0.5, 0.5), (1.5, 0.5)
// and saddles at (1, 0) and (1, 1); spacing 0.01 m, so one cell = 0.01 m.
VectorField doubleGyre() {
  Grid g;
  g.dims = {201, 101, 1};
  g.spacing = {0.01, 0.01, 1.0};
  const double pi = std::numbers::pi;
  return sampleField(g, [pi](const Vec3& p) {
    return Vec3(-std::sin(pi * p.x()) * std::cos(pi * p.y()),
                std::cos(pi * p.x()) * std::sin(pi * p.y()), 0.0);
  });
}

struct Separation {
  double minBetweenLines = 1e300;  // m, closest points of two different lines
  double maxGap = 0.0;             // m, largest distance from a grid node to the nearest line point
};

Separation measure(const std::vector<Streamline>& lines, const Grid& g) {
  Separation s;
  for (std::size_t a = 0; a < lines.size(); ++a)
    for (std::size_t b = a + 1; b < lines.size(); ++b)
      for (const Vec3& p : lines[a].points)
        for (const Vec3& q : lines[b].points) s.minBetweenLines = std::min(s.minBetweenLines, (p - q).norm());
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      const Vec3 x = g.position(i, j);
      double nearest = 1e300;
      for (const auto& line : lines)
        for (const Vec3& p : line.points) nearest = std::min(nearest, (p - x).squaredNorm());
      s.maxGap = std::max(s.maxGap, std::sqrt(nearest));
    }
  return s;
}

}  // namespace

TEST(EvenlySpaced, LinesKeepDTestApartAndCoverTheDomainWithinOneAndAHalfDSep) {
  const VectorField v = doubleGyre();
  EvenlySpacedParams p;
  p.separating_distance = 8.0;  // 0.08 m
  p.test_ratio = 0.5;           // d_test = 0.04 m
  StreamlineParams integration;
  integration.step = 0.5;
  const auto lines = evenlySpacedStreamlines(v, p, integration);
  const Separation s = measure(lines, v.grid);
  std::printf("double gyre: %zu lines, min distance between lines %.4f m (d_test 0.04), largest "
              "gap %.4f m (d_sep 0.08)\n", lines.size(), s.minBetweenLines, s.maxGap);
  EXPECT_GE(s.minBetweenLines, 0.04 * (1 - 1e-12));
  EXPECT_LE(s.maxGap, 1.5 * 0.08);
  EXPECT_GT(lines.size(), 10u);
}

// Concentric circles: spacing between neighbours is d_sep, so lines ~ radius / d_sep of them,
// and each closes on itself.
TEST(EvenlySpaced, RotationGivesClosedCirclesAboutDSepApart) {
  const VectorField v = rotationField(squareGrid(101, -1.0, 1.0));  // spacing 0.02 m
  EvenlySpacedParams p;
  p.separating_distance = 10.0;  // 0.2 m
  const auto lines = evenlySpacedStreamlines(v, p, StreamlineParams{});
  const Separation s = measure(lines, v.grid);
  int closed = 0;
  for (const auto& line : lines) closed += line.forward_end == TerminationReason::closed_loop;
  std::printf("rotation: %zu lines, %d closed, min distance %.4f m, largest gap %.4f m\n",
              lines.size(), closed, s.minBetweenLines, s.maxGap);
  // Circles of radius < 1 lie fully inside [-1, 1]^2: about 1 / 0.2 = 5 of them.
  EXPECT_GE(closed, 4);
  EXPECT_GE(s.minBetweenLines, 0.1 * (1 - 1e-12));
  EXPECT_LE(s.maxGap, 1.5 * 0.2);
}

TEST(EvenlySpaced, ThreeDimensionalFieldIsRejectedNamingTheArray) {
  Grid g;
  g.dims = {5, 5, 5};
  VectorField v = uniformField(g, Vec3(1, 0, 0));
  v.name = "u";
  try {
    evenlySpacedStreamlines(v, {}, {});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'u'"), std::string::npos) << e.what();
  }
  EvenlySpacedParams bad;
  bad.test_ratio = 0.0;
  v.grid.dims[2] = 1;
  v.values.resize(25);
  EXPECT_THROW(evenlySpacedStreamlines(v, bad, {}), ParamError);
}
