// Which zeros of the bilinear interpolant form one critical point (issue 15, defect 3): only
// those that are together ONE degenerate point. Two Morse points (det J clearly non-zero at
// each zero) stay two whatever their distance; the spurious zeros the interpolant makes around a
// degenerate zero (monkey saddle) stay one point.
//
// Saddle-focus pair: v = (y - y0, c ((x - x0)^2 - a^2) + b (y - y0)) on a grid of 1-cell spacing.
// Its first component is linear, so the interpolant's zeros lie exactly on y = y0, where the
// interpolant of the second component is the piecewise-linear interpolant of the parabola: its
// two roots are the exact zeros of the bilinear interpolant (computed below in closed form).
// With a = 0.74 they are 1.30 cells apart: a saddle (chord slope > 0, det < 0) and a spiral sink
// (chord slope < 0, det > 0, trace b = -0.1, |b| < 2 sqrt(det)). |det J| / G^2 is about 0.1 at
// both, ten times the Morse threshold.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

constexpr double kC = 0.1, kA = 0.74, kB = -0.1;
const Vec2 kX0(0.37, 0.23);
// 41 x 41 nodes, spacing 1: world units are cells.
const Grid kLoopGrid = squareGrid(41, -20.0, 20.0);

double parabola(double x) { return kC * ((x - kX0.x()) * (x - kX0.x()) - kA * kA); }

Vec2 saddleFocusField(double x, double y) {
  return {y - kX0.y(), parabola(x) + kB * (y - kX0.y())};
}

/// Root of the piecewise-linear interpolant of `parabola` (nodes at integers) in [k, k + 1].
double chordRoot(int k) {
  const double g0 = parabola(k), g1 = parabola(k + 1);
  return k + g0 / (g0 - g1);
}

const CriticalPoint* nearest(const std::vector<CriticalPoint>& points, const Vec2& q) {
  const CriticalPoint* best = nullptr;
  for (const CriticalPoint& p : points)
    if (!best || (Vec2(p.position.x(), p.position.y()) - q).norm() <
                     (Vec2(best->position.x(), best->position.y()) - q).norm())
      best = &p;
  return best;
}

}  // namespace

TEST(IndexLoopPlacement, SaddleAndFocus1p3CellsApartStayTwoPoints) {
  // Exact zeros of the interpolant: saddle at x0 + a (cell [1, 2]), focus at x0 - a ([-1, 0]).
  const Vec2 saddle(chordRoot(1), kX0.y()), focus(chordRoot(-1), kX0.y());
  ASSERT_GT(saddle.x(), 1.0);
  ASSERT_LT(saddle.x(), 2.0);
  ASSERT_GT(focus.x(), -1.0);
  ASSERT_LT(focus.x(), 0.0);
  ASSERT_NEAR((saddle - focus).norm(), 1.30, 0.01);  // closer than the default cluster_radius

  const TopologyParams defaults;
  ASSERT_LT((saddle - focus).norm(), defaults.cluster_radius);
  const auto points = findCriticalPoints(sampleField(kLoopGrid, saddleFocusField), defaults);
  ASSERT_EQ(points.size(), 2u);
  const CriticalPoint* s = nearest(points, saddle);
  const CriticalPoint* f = nearest(points, focus);
  ASSERT_NE(s, f);
  EXPECT_EQ(s->type, CriticalPointType::Saddle) << s->typeName();
  EXPECT_EQ(f->type, CriticalPointType::SpiralSink) << f->typeName();
  for (const auto& [p, exact] : {std::pair{s, saddle}, std::pair{f, focus}}) {
    EXPECT_TRUE(p->morse);
    EXPECT_EQ(p->cluster_size, 1);
    EXPECT_TRUE(p->index_measured);
    EXPECT_EQ(p->index, p == s ? -1 : 1);
    EXPECT_LT((Vec2(p->position.x(), p->position.y()) - exact).norm(), 0.01);  // cells
    EXPECT_GT(std::abs(p->normalized_det), 5 * defaults.det_threshold);
  }
  EXPECT_EQ(s->sectors.hyperbolic, 4);
}

// Poincare-Hopf for the pair: a loop around both has index -1 + 1 = 0 (the "cusp" the old
// clustering reported); each point's own loop must hold only that point.
TEST(IndexLoopPlacement, EachMorsePointOfThePairGetsALoopThatHoldsOnlyIt) {
  const auto points = findCriticalPoints(sampleField(kLoopGrid, saddleFocusField), {});
  ASSERT_EQ(points.size(), 2u);
  const double d = (points[0].position - points[1].position).norm();
  for (const CriticalPoint& p : points) {
    EXPECT_GT(p.loop_radius, 0.0);
    EXPECT_LT(p.loop_radius, d);
  }
}

// Monkey saddle v = conj(z - z0)^2 = ((x - x0)^2 - (y - y0)^2, -2 (x - x0)(y - y0)), index -2,
// inside a cell and on a node: ONE point of index -2 with six hyperbolic sectors, located at z0
// (the field is quadratic: central differences of the interpolant are exact, so the
// smallest-Jacobian centre is z0 to 1e-6 cells), whatever the spurious zeros around it.
TEST(IndexLoopPlacement, MonkeySaddleConjZSquaredStaysOnePointOfIndexMinusTwo) {
  for (const Vec2& z0 : {Vec2(0.27, -0.41), Vec2(0.0, 0.0), Vec2(3.5, 0.61)}) {
    SCOPED_TRACE(z0.transpose());
    const auto field = sampleField(kLoopGrid, [&](double x, double y) {
      const std::complex<double> w = std::conj(std::complex<double>(x - z0.x(), y - z0.y()));
      return Vec2((w * w).real(), (w * w).imag());
    });
    const auto points = findCriticalPoints(field, {});
    ASSERT_EQ(points.size(), 1u);
    EXPECT_EQ(points[0].type, CriticalPointType::MonkeySaddle) << points[0].typeName();
    EXPECT_EQ(points[0].index, -2);
    EXPECT_EQ(points[0].sectors.hyperbolic, 6);
    EXPECT_FALSE(points[0].morse);
    EXPECT_LT((Vec2(points[0].position.x(), points[0].position.y()) - z0).norm(), 1e-6);
  }
}
