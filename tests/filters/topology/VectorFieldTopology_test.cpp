// Classification of an isolated zero from the EXACT Jacobian of the bilinear interpolant at the
// zero (issue 15, defect 5), not from central differences over the neighbouring nodes.
//
// Spiral sink with a small trace: v = J (x - x0) + (k phi(x), 0) with J = [[-0.02, -1],
// [1, -0.02]] (eigenvalues -0.02 +- i: |re| / |im| = 0.02, twice the centre tolerance) and
//   phi(x) = (x - i0)(x - i0 - 1)(x - x0)^2 exp(-((x - x0) / 1.5)^2),
// zero with zero slope at x0 (the field's own Jacobian at x0 is J) and zero on the columns i0,
// i0 + 1 of the cell that holds x0: there the interpolant is exactly J (x - x0), so its zero is
// x0 and its Jacobian J. Central differences of the interpolant (step one cell) see phi on the
// columns i0 - 1 and i0 + 2: with x0 at 0.8 of the cell they add 0.454 k to du/dx, and with
// k = 0.3 turn the trace from -0.04 to +0.096 — a spiral source.
#include <gtest/gtest.h>

#include <cmath>

#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

Mat2 weakSpiralSink() {
  Mat2 j;
  j << -0.02, -1.0, 1.0, -0.02;
  return j;
}

constexpr int kI0 = 2;
const Vec2 kZero(kI0 + 0.8, -3 + 0.35);  // inside cell (2, -3) of a unit grid on [-20, 20]^2

double phi(double x) {
  const double d = x - kZero.x();
  return (x - kI0) * (x - kI0 - 1) * d * d * std::exp(-(d / 1.5) * (d / 1.5));
}

Vec2 weakSpiralSinkField(double x, double y) {
  const Vec2 linear = weakSpiralSink() * (Vec2(x, y) - kZero);
  return linear + Vec2(0.3 * phi(x), 0.0);
}

const Grid kUnitGrid = squareGrid(41, -20.0, 20.0);

}  // namespace

TEST(VectorFieldTopology, SpiralSinkWithSmallTraceIsClassifiedFromTheBilinearJacobian) {
  const VectorField field = sampleField(kUnitGrid, weakSpiralSinkField);
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
