// Separatrices traced with the shared streamline integrator (filters/streamlines).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "filters/topology/Separatrices.h"
#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {
const Grid kSeparatrixGrid = squareGrid(41, -1.0, 1.0);
const double kSeparatrixH = kSeparatrixGrid.spacing[0];

double angleOf(const Vec3& from, const Vec3& to) {
  return std::atan2(to.y() - from.y(), to.x() - from.x());
}

bool onBoundary(const Vec3& p) {
  return std::abs(std::abs(p.x()) - 1.0) < 1e-6 || std::abs(std::abs(p.y()) - 1.0) < 1e-6;
}
}  // namespace

// Saddle v = (x - x0, -(y - y0)): the separatrices are the axes through (x0, y0); every traced
// point within 1e-6 of them; outgoing ones along x, incoming along y, all ending on the boundary.
TEST(Separatrices, LinearSaddleSeparatricesAreTheAxes) {
  const Vec2 x0(0.0123, -0.0371);
  Mat2 a;
  a << 1, 0, 0, -1;
  const VectorField f = sampleField(kSeparatrixGrid, linearField(a, x0));
  const auto points = findCriticalPoints(f, {});
  ASSERT_EQ(points.size(), 1u);
  const auto separatrices = computeSeparatrices(f, points, {});
  ASSERT_EQ(separatrices.size(), 4u);
  int outgoing = 0;
  for (const Separatrix& s : separatrices) {
    EXPECT_EQ(s.origin, 0);
    EXPECT_EQ(s.end, SeparatrixEnd::Boundary) << toString(s.end);
    ASSERT_GE(s.points.size(), 10u);
    double offAxis = 0.0;
    for (const Vec3& p : s.points)
      offAxis = std::max(offAxis, s.start.outflow ? std::abs(p.y() - x0.y()) : std::abs(p.x() - x0.x()));
    EXPECT_LT(offAxis, 1e-6);
    EXPECT_TRUE(onBoundary(s.points.back())) << s.points.back().transpose();
    EXPECT_LT((s.points.front() - points[0].position).norm(), 1e-12);  // starts at the saddle
    outgoing += s.start.outflow;
  }
  EXPECT_EQ(outgoing, 2);
}

// Monkey saddle grad(x^3 - 3xy^2): six separatrices, the invariant rays at 60 degree spacing
// (outgoing along 0, 120, 240 degrees). Measured on 41 x 41 nodes: start directions (radial
// directions on the index loop of the interpolant) within 0.74 degree, far ends of the traced
// lines within 0.0008 degree of their ray (the rays attract the traced lines).
TEST(Separatrices, MonkeySaddleHasSixSeparatricesAtSixtyDegrees) {
  for (const Vec2& x0 : {Vec2(0, 0), Vec2(0.246 * kSeparatrixH, -0.742 * kSeparatrixH)}) {
    SCOPED_TRACE("monkey saddle at " + std::to_string(x0.x()) + ", " + std::to_string(x0.y()));
    const VectorField f = sampleField(kSeparatrixGrid, [&](double x, double y) {
      x -= x0.x();
      y -= x0.y();
      return Vec2(3 * x * x - 3 * y * y, -6 * x * y);
    });
    const auto points = findCriticalPoints(f, {});
    ASSERT_EQ(points.size(), 1u);
    const auto separatrices = computeSeparatrices(f, points, {});
    ASSERT_EQ(separatrices.size(), 6u);
    std::vector<double> starts;
    for (const Separatrix& s : separatrices) {
      const double a = std::atan2(s.start.direction.y(), s.start.direction.x());
      starts.push_back(a < 0 ? a + 2 * std::numbers::pi : a);
      const int k = static_cast<int>(std::lround(starts.back() / (std::numbers::pi / 3))) % 6;
      EXPECT_EQ(s.start.outflow, k % 2 == 0);
      EXPECT_EQ(s.end, SeparatrixEnd::Boundary);
      const Vec3 analyticOrigin(x0.x(), x0.y(), 0.0);
      double end = angleOf(analyticOrigin, s.points.back());
      if (end < 0) end += 2 * std::numbers::pi;
      EXPECT_NEAR(end, k * std::numbers::pi / 3 + (k == 0 && end > std::numbers::pi ? 2 * std::numbers::pi : 0), 0.01 * std::numbers::pi / 180);
      EXPECT_NEAR(starts.back(), k * std::numbers::pi / 3 + (k == 0 && starts.back() > std::numbers::pi ? 2 * std::numbers::pi : 0),
                  1.0 * std::numbers::pi / 180);
    }
    std::sort(starts.begin(), starts.end());
    for (int k = 0; k < 6; ++k) {
      const double gap = (k < 5 ? starts[k + 1] : starts[0] + 2 * std::numbers::pi) - starts[k];
      EXPECT_NEAR(gap, std::numbers::pi / 3, 1.5 * std::numbers::pi / 180);
    }
  }
}

// Cellular flow: the separatrices of the interior saddles run along the cell walls x, y = integer
// and end at the neighbouring saddles (saddle connections) or on the domain boundary.
TEST(Separatrices, CellularFlowSaddlesConnectToTheirNeighbours) {
  const Grid g = squareGrid(65, -0.313, 2.271);
  const VectorField f = sampleField(g, [](double x, double y) {
    return Vec2(std::numbers::pi * std::sin(std::numbers::pi * x) * std::cos(std::numbers::pi * y), -std::numbers::pi * std::cos(std::numbers::pi * x) * std::sin(std::numbers::pi * y));
  });
  const auto points = findCriticalPoints(f, {});
  const auto separatrices = computeSeparatrices(f, points, {});
  int saddles = 0, connections = 0;
  for (const auto& p : points) saddles += p.type == CriticalPointType::Saddle;
  EXPECT_EQ(saddles, 9);
  EXPECT_EQ(separatrices.size(), 36u);
  for (const Separatrix& s : separatrices) {
    const Vec3 o = points[s.origin].position;
    if (s.end == SeparatrixEnd::CriticalPoint) {
      ++connections;
      const Vec3 e = points[s.end_point].position;
      EXPECT_EQ(points[s.end_point].type, CriticalPointType::Saddle);
      EXPECT_NEAR((e - o).norm(), 1.0, 1e-3);  // the next saddle along a cell wall
    } else {
      EXPECT_EQ(s.end, SeparatrixEnd::Boundary) << toString(s.end);
    }
    // Along a wall: x or y stays at the saddle's value.
    double dx = 0, dy = 0;
    for (const Vec3& p : s.points) {
      dx = std::max(dx, std::abs(p.x() - o.x()));
      dy = std::max(dy, std::abs(p.y() - o.y()));
    }
    EXPECT_LT(std::min(dx, dy), 1e-3);
  }
  // Each of the 12 interior wall segments between two of the 9 saddles is traced from both ends
  // (once outgoing from one, once incoming to the other): 24 connections.
  EXPECT_EQ(connections, 24);
}
