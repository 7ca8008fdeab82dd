// Classification of an isolated zero from the EXACT Jacobian of the bilinear interpolant at the
// zero (issue 15, defect 5), not from central differences over the neighbouring nodes.
//
// Spiral sink with a small trace (TopologyTestFields.h, WeakSpiralSink): the interpolant in the
// zero's cell is exactly J (x - x0) with J = [[-0.02, -1], [1, -0.02]] (eigenvalues -0.02 +- i:
// |re| / |im| = 0.02, twice the centre tolerance), while central differences over the
// neighbouring nodes give trace +0.096 — a spiral source.
#include <gtest/gtest.h>

#include <cmath>

#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

Mat2 weakSpiralSink() { return WeakSpiralSink::jacobian(); }
const Vec2 kZero = WeakSpiralSink::zero();

const Grid kUnitGrid = squareGrid(41, -20.0, 20.0);

}  // namespace

TEST(VectorFieldTopology, SpiralSinkWithSmallTraceIsClassifiedFromTheBilinearJacobian) {
  const VectorField field = sampleField(WeakSpiralSink::grid(), WeakSpiralSink::field);
  // The premise: central differences at the zero call it a spiral source.
  const PlanarField planar(field, 0);
  const Vec2 q = planar.toIndex(Vec3(kZero.x(), kZero.y(), 0.0));
  const double fdTrace = planar.jacobianFiniteDifference(q).trace();
  ASSERT_NEAR(fdTrace, -0.04 + 0.3 * 0.454, 2e-3);

  const auto points = findCriticalPoints(field, {});
  ASSERT_EQ(points.size(), 1u);
  const CriticalPoint& p = points[0];
  EXPECT_EQ(p.type, CriticalPointType::SpiralSink) << p.typeName() << " trace " << p.trace;
  EXPECT_TRUE(p.morse);
  EXPECT_EQ(p.index, 1);
  // The interpolant in the zero's cell is exactly J (x - x0): zero and Jacobian to rounding.
  EXPECT_LT((Vec2(p.position.x(), p.position.y()) - kZero).norm(), 1e-9);
  EXPECT_LT((p.jacobian - weakSpiralSink()).norm(), 1e-9);
  EXPECT_NEAR(p.trace, -0.04, 1e-9);
  EXPECT_NEAR(p.det, weakSpiralSink().determinant(), 1e-9);
  EXPECT_NEAR(p.eigenvalues[0].real(), -0.02, 1e-9);
}

// On a node the interpolant's Jacobian jumps between the four cells that share it; the point is
// classified from their mean, which is the central difference at the node. Linear field plus a
// quadratic term that vanishes with its slope at the node, so the mean is exact: J.
TEST(VectorFieldTopology, ZeroOnANodeUsesTheMeanJacobianOfItsCells) {
  const Vec2 node(4.0, -2.0);
  const VectorField field = sampleField(kUnitGrid, [&](double x, double y) {
    const Vec2 d = Vec2(x, y) - node;
    return Vec2(weakSpiralSink() * d + Vec2(0.2 * d.x() * d.x(), 0.0));
  });
  const auto points = findCriticalPoints(field, {});
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(points[0].type, CriticalPointType::SpiralSink) << points[0].typeName();
  EXPECT_LT((Vec2(points[0].position.x(), points[0].position.y()) - node).norm(), 1e-9);
  EXPECT_LT((points[0].jacobian - weakSpiralSink()).norm(), 1e-9);
}
