// Attachment and separation points of no-slip walls at rest (filters/topology/WallPoints.h),
// against fields whose wall shear stress is known in closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "filters/topology/VectorFieldTopology.h"
#include "filters/topology/WallPoints.h"

using namespace fluidviz;
using namespace fluidviz::topology;

namespace {

constexpr double kPi = std::numbers::pi;

// Node-centred lattice of n x m cells of side h on [0, n h] x [0, m h]: the domain's sides lie
// half a cell outside the edge nodes, as halfway bounce-back puts an LBM box's walls.
Grid cellCentredGrid(int n, int m, double h) {
  Grid g;
  g.dims = {n, m, 1};
  g.origin = {0.5 * h, 0.5 * h, 0.0};
  g.spacing = {h, h, 1.0};
  return g;
}

template <class F>
VectorField sampled(const Grid& g, F velocity) {
  VectorField v{"velocity", g, {}};
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) v.values.push_back(velocity(g.position(i, j)));
  return v;
}

std::vector<CriticalPoint> ofType(const std::vector<CriticalPoint>& points, CriticalPointType t) {
  std::vector<CriticalPoint> out;
  std::copy_if(points.begin(), points.end(), std::back_inserter(out),
               [&](const CriticalPoint& p) { return p.type == t; });
  std::sort(out.begin(), out.end(), [](const CriticalPoint& a, const CriticalPoint& b) {
    return a.position.x() < b.position.x();
  });
  return out;
}

std::string listed(const std::vector<CriticalPoint>& points) {
  std::string s;
  for (const CriticalPoint& p : points)
    s += p.typeName() + " (" + std::to_string(p.position.x()) + ", " +
         std::to_string(p.position.y()) + ") ";
  return s;
}

RestingWalls restingSide(DomainSide s) {
  RestingWalls w;
  w.sides[static_cast<int>(s)] = true;
  return w;
}

}  // namespace

// Stream function psi = -cos(k x) d^2 / 2 over the wall y = 0 (d = y): u = -cos(k x) d,
// v = -k sin(k x) d^2 / 2, both zero on the wall (no slip), incompressible. The wall shear
// du/dy = -cos(k x) changes sign at k x = pi/2 (the flow along the wall leaves the point both
// ways, and v < 0 brings fluid to the wall: attachment) and at 3 pi/2 (separation). Linear
// interpolation of cos between two nodes half a cell either side of its zero errs by less than
// (k h)^2 / 8 of a cell.
TEST(WallPoints, ShearZerosOfAStagnationFlowOnAWallAreItsAttachmentAndSeparationPoints) {
  const int n = 64;
  const double h = 1.0 / 32, k = 2 * kPi / 1.0;  // two periods over x in [0, 2]
  const Grid g = cellCentredGrid(n, 16, h);
  const VectorField v = sampled(g, [&](const Vec3& p) {
    return Vec3(-std::cos(k * p.x()) * p.y(), -k * std::sin(k * p.x()) * p.y() * p.y() / 2, 0);
  });
  const std::vector<CriticalPoint> points = findWallPoints(v, {}, restingSide(DomainSide::y_min));
  const auto attachments = ofType(points, CriticalPointType::Attachment);
  const auto separations = ofType(points, CriticalPointType::Separation);
  ASSERT_EQ(attachments.size(), 2u);
  ASSERT_EQ(separations.size(), 2u);
  ASSERT_EQ(points.size(), 4u) << listed(points);
  const double tolerance = 0.01 * h;  // (k h)^2 / 8 = 0.005 cells
  for (int m = 0; m < 2; ++m) {
    EXPECT_NEAR(attachments[m].position.x(), (0.25 + m) * 1.0, tolerance);
    EXPECT_NEAR(separations[m].position.x(), (0.75 + m) * 1.0, tolerance);
    for (const CriticalPoint* p : {&attachments[m], &separations[m]}) {
      EXPECT_DOUBLE_EQ(p->position.y(), 0.0) << "on the wall, half a cell below the edge nodes";
      ASSERT_EQ(p->separatrix_directions.size(), 1u);
      EXPECT_NEAR(p->separatrix_directions[0].direction.y(), 1.0, 1e-12) << "into the fluid";
      EXPECT_EQ(p->separatrix_directions[0].outflow, p->type == CriticalPointType::Separation);
      EXPECT_EQ(p->index, 0);
      EXPECT_FALSE(p->index_measured);
    }
  }
}

// The same flow seen by the whole search: the edge nodes' small velocities hold no critical
// point (the field has none inside: u = 0 needs cos(k x) = 0, where v != 0), and the wall points
// come in the wall's stead, whichever way the wall is traced (a wall on y_max, the field
// mirrored).
TEST(WallPoints, TheSearchReportsTheWallPointsOfAMirroredWallToo) {
  const double h = 1.0 / 32, k = 2 * kPi;
  const Grid g = cellCentredGrid(32, 16, h);
  const double top = 16 * h;
  const VectorField v = sampled(g, [&](const Vec3& p) {
    const double d = top - p.y();  // distance from the wall y = top
    return Vec3(-std::cos(k * p.x()) * d, k * std::sin(k * p.x()) * d * d / 2, 0);
  });
  const std::vector<CriticalPoint> points =
      findCriticalPointsInFluid(v, {}, TopologyParams{}, restingSide(DomainSide::y_max));
  ASSERT_EQ(points.size(), 2u) << listed(points);
  const auto attachment = ofType(points, CriticalPointType::Attachment);
  const auto separation = ofType(points, CriticalPointType::Separation);
  ASSERT_EQ(attachment.size(), 1u);
  ASSERT_EQ(separation.size(), 1u);
  EXPECT_NEAR(attachment[0].position.x(), 0.25, 0.01 * h);
  EXPECT_NEAR(separation[0].position.x(), 0.75, 0.01 * h);
  EXPECT_DOUBLE_EQ(attachment[0].position.y(), top);
  EXPECT_NEAR(attachment[0].separatrix_directions[0].direction.y(), -1.0, 1e-12);
}

// Potential flow past a cylinder with zero velocity inside (a solid at rest): u_theta =
// -2 U sin(theta) on the circle, so the wall's only sign changes are the front (theta = pi,
// attachment) and rear (theta = 0, separation) stagnation points, on the closed chain around the
// solid. The chain lies on the staircase of the masked nodes, within a cell of the circle.
TEST(WallPoints, CylinderAtRestHasItsStagnationPointsOnItsWall) {
  const double h = 0.1, R = 1.0;
  Grid g;
  g.dims = {61, 41, 1};
  g.origin = {-3.0, -2.0, 0.0};
  g.spacing = {h, h, 1.0};
  RestingWalls walls;
  walls.solid.assign(g.nodeCount(), 0);
  const VectorField v = sampled(g, [&](const Vec3& p) {
    const double r2 = p.x() * p.x() + p.y() * p.y();
    if (r2 < R * R) return Vec3(0, 0, 0);
    const double a = R * R / (r2 * r2);
    return Vec3(1.0 - a * (p.x() * p.x() - p.y() * p.y()), -a * 2 * p.x() * p.y(), 0.0);
  });
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i)
      walls.solid[g.index(i, j)] = g.position(i, j).squaredNorm() < R * R;
  const PointMask mask = walls.solid;
  const std::vector<CriticalPoint> points = findWallPoints(v, mask, walls);
  ASSERT_EQ(points.size(), 2u);
  const auto front = ofType(points, CriticalPointType::Attachment);
  const auto rear = ofType(points, CriticalPointType::Separation);
  ASSERT_EQ(front.size(), 1u);
  ASSERT_EQ(rear.size(), 1u);
  EXPECT_LT((front[0].position - Vec3(-R, 0, 0)).norm(), h) << front[0].position.transpose();
  EXPECT_LT((rear[0].position - Vec3(R, 0, 0)).norm(), h) << rear[0].position.transpose();
  EXPECT_NEAR(front[0].separatrix_directions[0].direction.x(), -1.0, 0.05);
  EXPECT_NEAR(rear[0].separatrix_directions[0].direction.x(), 1.0, 0.05);
}

// A single eddy in a box with four no-slip walls at rest, psi = sin^2(pi x) sin^2(pi y): the
// flow runs along every wall in one sense, so there is no wall point, and the eddy's centre is
// the only critical point. Noise of 1e-3 of the peak speed, its sign flipping every two nodes,
// added to the 5 x 5 nodes of each corner, where the eddy's velocity falls to zero, flips the
// sign of the flow along the walls there several times over more than kWallClusterCells: those
// are the unresolved corner eddies (Moffatt 1964), which must not show up as wall points.
TEST(WallPoints, AnEddyInABoxHasOnlyItsCentreEvenWithNoiseInTheCorners) {
  const int n = 48;
  const double h = 1.0 / n;
  const Grid g = cellCentredGrid(n, n, h);
  VectorField v = sampled(g, [&](const Vec3& p) {
    const double sx = std::sin(kPi * p.x()), sy = std::sin(kPi * p.y());
    const double cx = std::cos(kPi * p.x()), cy = std::cos(kPi * p.y());
    return Vec3(2 * kPi * sx * sx * sy * cy, -2 * kPi * sy * sy * sx * cx, 0.0);
  });
  double peak = 0;
  for (const Vec3& u : v.values) peak = std::max(peak, u.norm());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = std::min(i, n - 1 - i), b = std::min(j, n - 1 - j);  // nodes from the walls
      if (a < 5 && b < 5) v.values[g.index(i, j)] += Vec3(1, 1, 0) * (((a + b) / 2 % 2) ? 1e-3 : -1e-3) * peak;
    }
  RestingWalls box;
  box.sides = {true, true, true, true};
  const std::vector<CriticalPoint> points =
      findCriticalPointsInFluid(v, {}, TopologyParams{}, box);
  ASSERT_EQ(points.size(), 1u) << listed(points);
  EXPECT_EQ(points[0].index, 1);
  EXPECT_LT((points[0].position - Vec3(0.5, 0.5, 0)).norm(), 0.01 * h);
}

// The wall layer: a point in a cell with a corner on a resting solid node, or on a fluid node
// next to one or next to a resting side, is in it; a point two cells off is not.
TEST(WallPoints, TheWallLayerIsTheFirstFluidLayerAndTheSolid) {
  const Grid g = cellCentredGrid(10, 10, 1.0);
  const PointMask layer = restingWallLayer(g, {}, restingSide(DomainSide::x_min));
  EXPECT_TRUE(inWallLayer(g, layer, Vec3(1.2, 5.0, 0)));   // cell between nodes 0 and 1
  EXPECT_FALSE(inWallLayer(g, layer, Vec3(1.7, 5.0, 0)));  // cell between nodes 1 and 2
  RestingWalls disc;
  disc.solid.assign(g.nodeCount(), 0);
  disc.solid[g.index(5, 5)] = 1;
  const PointMask around = restingWallLayer(g, disc.solid, disc);
  EXPECT_EQ(maskedCount(around), 5u);  // the node and its four neighbours
  EXPECT_TRUE(inWallLayer(g, around, g.position(6, 5) + Vec3(0.5, 0.5, 0)));
  EXPECT_FALSE(inWallLayer(g, around, g.position(7, 5) + Vec3(0.5, 0.5, 0)));
}
