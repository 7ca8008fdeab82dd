// Morse critical points of linear fields v = A (x - x0): the bilinear interpolant reproduces a
// linear field exactly, so the zero must be located to Newton's tolerance (asserted: 1e-6 cell)
// and the Jacobian, det, trace and eigenvalues must equal A's (asserted: 1e-9 relative), wherever
// x0 lies: inside a cell, on a cell edge, or exactly on a node (found once, not 2 or 4 times).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

struct PlanarLinearCase {
  std::string name;
  Mat2 a;
  CriticalPointType type;
  int index;
  SectorCounts sectors;
};

std::vector<PlanarLinearCase> planarLinearCases() {
  Mat2 saddle, source, sink, spiralSource, spiralSink, centre, shearedSaddle;
  saddle << 1, 0, 0, -1;
  shearedSaddle << 0.5, 2.0, 1.0, -1.0;  // det -2.5, eigenvectors not on the axes
  source << 1, 0.3, 0, 2;
  sink << -1.5, 0, 0.4, -0.5;
  spiralSource << 0.2, -1, 1, 0.2;
  spiralSink << -0.3, -2, 1, -0.1;
  centre << 0, -1, 1, 0;
  // Nodes: all directions enter/leave, one parabolic sector; foci and centres have none.
  return {{"saddle", saddle, CriticalPointType::Saddle, -1, {0, 4, 0}},
          {"sheared_saddle", shearedSaddle, CriticalPointType::Saddle, -1, {0, 4, 0}},
          {"source", source, CriticalPointType::Source, 1, {0, 0, 1}},
          {"sink", sink, CriticalPointType::Sink, 1, {0, 0, 1}},
          {"spiral_source", spiralSource, CriticalPointType::SpiralSource, 1, {0, 0, 0}},
          {"spiral_sink", spiralSink, CriticalPointType::SpiralSink, 1, {0, 0, 0}},
          {"centre", centre, CriticalPointType::Centre, 1, {0, 0, 0}}};
}

// 21 x 17 nodes, non-square cells (0.1 x 0.125), so index space != world space.
Grid testGrid() {
  Grid g;
  g.dims = {21, 17, 1};
  g.origin = {-1.0, -1.0, 0.0};
  g.spacing = {0.1, 0.125, 1.0};
  return g;
}

void expectLinearPointFound(const PlanarLinearCase& c, const Vec2& x0, const std::string& where) {
  SCOPED_TRACE(c.name + " " + where);
  const Grid g = testGrid();
  const VectorField f = sampleField(g, linearField(c.a, x0));
  const auto points = findCriticalPoints(f, TopologyParams{});
  ASSERT_EQ(points.size(), 1u);
  const CriticalPoint& p = points[0];
  const double errCellsX = std::abs(p.position.x() - x0.x()) / g.spacing[0];
  const double errCellsY = std::abs(p.position.y() - x0.y()) / g.spacing[1];
  EXPECT_LT(errCellsX, 1e-6);
  EXPECT_LT(errCellsY, 1e-6);
  EXPECT_EQ(p.type, c.type) << p.typeName();
  EXPECT_TRUE(p.morse);
  EXPECT_TRUE(p.index_measured);
  EXPECT_EQ(p.index, c.index);
  EXPECT_EQ(p.sectors, c.sectors) << "e=" << p.sectors.elliptic << " h=" << p.sectors.hyperbolic
                                  << " p=" << p.sectors.parabolic;
  EXPECT_TRUE(p.bendixson_holds);
  EXPECT_FALSE(p.on_boundary);
  EXPECT_EQ(p.cluster_size, 1);
  const double scale = c.a.norm();
  EXPECT_LT((p.jacobian - c.a).norm(), 1e-9 * scale);
  EXPECT_LT((p.jacobian_interpolant - c.a).norm(), 1e-9 * scale);
  EXPECT_NEAR(p.det, c.a.determinant(), 1e-9 * scale * scale);
  EXPECT_NEAR(p.trace, c.a.trace(), 1e-9 * scale);
  const auto ev = c.a.eigenvalues();
  for (int k = 0; k < 2; ++k) {
    const std::complex<double> e(ev[k].real(), ev[k].imag());
    const double d = std::min(std::abs(p.eigenvalues[0] - e), std::abs(p.eigenvalues[1] - e));
    EXPECT_LT(d, 1e-9 * scale);
  }
}

}  // namespace

TEST(MorseCriticalPoints, LinearFieldsInsideACell) {
  for (const auto& c : planarLinearCases()) expectLinearPointFound(c, Vec2(0.0337, -0.0521), "inside");
}

TEST(MorseCriticalPoints, LinearFieldsOnACellEdge) {
  const Grid g = testGrid();
  const Vec3 node = g.position(12, 7);
  for (const auto& c : planarLinearCases()) {
    expectLinearPointFound(c, Vec2(node.x(), node.y() + 0.041), "on a vertical edge");
    expectLinearPointFound(c, Vec2(node.x() - 0.063, node.y()), "on a horizontal edge");
  }
}

TEST(MorseCriticalPoints, LinearFieldsExactlyOnANode) {
  const Grid g = testGrid();
  for (const auto& c : planarLinearCases()) {
    const Vec3 node = g.position(9, 10);
    expectLinearPointFound(c, Vec2(node.x(), node.y()), "on a node");
  }
}

// Saddle separatrix directions of a Morse saddle are the eigenvectors of J.
TEST(MorseCriticalPoints, SaddleSeparatrixDirectionsAreTheEigenvectors) {
  Mat2 a;
  a << 0.5, 2.0, 1.0, -1.0;
  const auto points = findCriticalPoints(sampleField(testGrid(), linearField(a, {0.1, 0.2})), {});
  ASSERT_EQ(points.size(), 1u);
  ASSERT_EQ(points[0].separatrix_directions.size(), 4u);
  int outflow = 0;
  for (const RadialDirection& d : points[0].separatrix_directions) {
    // A d = lambda d with lambda > 0 for the outgoing, < 0 for the incoming directions.
    const Vec2 ad = a * d.direction;
    const double lambda = ad.dot(d.direction);
    EXPECT_LT((ad - lambda * d.direction).norm(), 1e-9 * ad.norm());
    EXPECT_EQ(lambda > 0, d.outflow);
    outflow += d.outflow;
  }
  EXPECT_EQ(outflow, 2);
}

// A point exactly on the domain boundary: found once, flagged on_boundary, index from det J.
TEST(MorseCriticalPoints, PointOnTheDomainBoundaryIsFlagged) {
  const Grid g = testGrid();
  Mat2 a;
  a << 1, 0, 0, -1;
  const Vec3 edge = g.position(0, 5);
  const auto points = findCriticalPoints(sampleField(g, linearField(a, {edge.x(), edge.y()})), {});
  ASSERT_EQ(points.size(), 1u);
  EXPECT_TRUE(points[0].on_boundary);
  EXPECT_FALSE(points[0].index_measured);
  EXPECT_EQ(points[0].type, CriticalPointType::Saddle);
  EXPECT_EQ(points[0].index, -1);
  EXPECT_LT((points[0].position - edge).norm(), 1e-9);
}

// Segments of exact zeros (no-slip walls) are not isolated critical points and are skipped,
// while an isolated point in the interior is still found.
TEST(MorseCriticalPoints, NoSlipWallsAreNotCriticalPoints) {
  const Grid g = squareGrid(33, 0.0, 1.0);
  // Cellular flow psi = sin(pi x) sin(pi y) times a wall factor that vanishes on y = 0 and 1.
  VectorField f = sampleField(g, [](double x, double y) {
    const double pi = std::acos(-1.0);
    return Vec2(std::sin(pi * x) * std::sin(pi * y), -std::sin(pi * y) * (x - 0.37));
  });
  for (int i = 0; i < 33; ++i) {
    f.values[g.index(i, 0)].setZero();
    f.values[g.index(i, 32)].setZero();
  }
  const auto points = findCriticalPoints(f, {});
  // Interior zeros: u = 0 needs x in {0, 1} (boundary, not interior) or y in {0, 1}; so the only
  // isolated zeros are on x = 0 and x = 1 where v = 0 needs y in {0, 1}: none off the walls.
  // (0.37, y) has v = 0 but u != 0. Hence no point at all may be reported.
  EXPECT_EQ(points.size(), 0u);
}

// A 3D field: the topology of the requested z-slice (in-plane components) is analysed.
TEST(MorseCriticalPoints, ZSliceOfA3DField) {
  Grid g;
  g.dims = {17, 17, 3};
  g.origin = {-1, -1, 0};
  g.spacing = {0.125, 0.125, 0.5};
  VectorField f{"v", g, {}};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 17; ++j)
      for (int i = 0; i < 17; ++i) {
        const Vec3 p = g.position(i, j, k);
        const double cx = -0.3 + 0.3 * k;  // the point moves with the slice
        if (k == 1)
          f.values.emplace_back(-(p.y() - 0.1), p.x() - cx, 5.0);  // centre
        else
          f.values.emplace_back(p.x() - cx, -(p.y() - 0.1), 5.0);  // saddle
      }
  TopologyParams params;
  params.slice_index = 1;
  auto points = findCriticalPoints(f, params);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(points[0].type, CriticalPointType::Centre);
  EXPECT_NEAR(points[0].position.x(), 0.0, 1e-9);
  EXPECT_NEAR(points[0].position.y(), 0.1, 1e-9);
  EXPECT_NEAR(points[0].position.z(), 0.5, 1e-12);
  params.slice_index = 2;
  points = findCriticalPoints(f, params);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(points[0].type, CriticalPointType::Saddle);
  EXPECT_NEAR(points[0].position.x(), 0.3, 1e-9);
  params.slice_index = 3;
  try {
    findCriticalPoints(f, params);
    FAIL() << "slice 3 of 3 layers accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "slice_index");
  }
}
