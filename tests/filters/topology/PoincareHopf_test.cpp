// Poincaré–Hopf (for planar fields: the argument principle): the winding number of the field
// along a closed loop free of critical points equals the sum of the indices of the critical
// points inside. The field w(z) = (z-a1)(z-a2) conj((z-b1)(z-b2)) (z-c)^2 conj(z-d)^2, scaled by
// 1/sqrt(1 + |w|^2) (same zeros and windings), has analytic indices +1, +1, -1, -1, +2, -2.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <complex>
#include <numbers>
#include <random>
#include <set>

#include "filters/topology/PoincareIndex.h"
#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

using Complex = std::complex<double>;

struct AnalyticPoint {
  Vec2 position;
  int index;
};

const std::vector<AnalyticPoint> kPoints = {{{-1.1, 0.7}, 1},  {{0.93, -0.81}, 1},
                                            {{0.21, 0.92}, -1}, {{-0.57, -0.93}, -1},
                                            {{1.02, 0.63}, 2},  {{-0.88, -0.07}, -2}};

Vec2 mixedField(double x, double y) {
  const Complex z(x, y);
  auto at = [](const AnalyticPoint& p) { return Complex(p.position.x(), p.position.y()); };
  const Complex w = (z - at(kPoints[0])) * (z - at(kPoints[1])) *
                    std::conj((z - at(kPoints[2])) * (z - at(kPoints[3]))) *
                    (z - at(kPoints[4])) * (z - at(kPoints[4])) *
                    std::conj((z - at(kPoints[5])) * (z - at(kPoints[5])));
  const double scale = 1.0 / std::sqrt(1.0 + std::norm(w));
  return {w.real() * scale, w.imag() * scale};
}

const Grid kHopfGrid = squareGrid(161, -2.0, 2.0);  // 0.025 per cell

bool insidePolygon(const std::vector<Vec2>& poly, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i], &b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

double distanceToPolygon(const std::vector<Vec2>& poly, const Vec2& p) {
  double d = 1e300;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    d = std::min(d, (a + t * (b - a) - p).norm());
  }
  return d;
}

// Random star-shaped loop r(t) = r0 (1 + 0.3 sin(3t + f1) + 0.2 cos(5t + f2)), counter-clockwise.
std::vector<Vec2> randomLoop(std::mt19937& rng) {
  std::uniform_real_distribution<double> centre(-1.4, 1.4), radius(0.25, 1.3),
      phase(0, 2 * std::numbers::pi);
  const Vec2 c(centre(rng), centre(rng));
  const double r0 = radius(rng), f1 = phase(rng), f2 = phase(rng);
  std::vector<Vec2> loop;
  for (int k = 0; k < 240; ++k) {
    const double t = 2 * std::numbers::pi * k / 240;
    const double r = r0 * (1 + 0.3 * std::sin(3 * t + f1) + 0.2 * std::cos(5 * t + f2));
    loop.push_back(c + r * Vec2(std::cos(t), std::sin(t)));
  }
  return loop;
}

}  // namespace

TEST(PoincareHopf, DetectsEveryPointOfTheMixedFieldWithItsIndex) {
  const auto points = findCriticalPoints(sampleField(kHopfGrid, mixedField), {});
  ASSERT_EQ(points.size(), kPoints.size());
  for (const AnalyticPoint& a : kPoints) {
    const CriticalPoint* nearest = nullptr;
    double best = 1e300;
    for (const auto& p : points) {
      const double d = (Vec2(p.position.x(), p.position.y()) - a.position).norm();
      if (d < best) best = d, nearest = &p;
    }
    SCOPED_TRACE("analytic point at " + std::to_string(a.position.x()) + ", " +
                 std::to_string(a.position.y()));
    EXPECT_LT(best / kHopfGrid.spacing[0], 0.3);
    EXPECT_EQ(nearest->index, a.index);
    EXPECT_EQ(nearest->morse, std::abs(a.index) == 1);
  }
  EXPECT_EQ(points[0].index + points[1].index + points[2].index + points[3].index +
                points[4].index + points[5].index,
            0);
}

// 40 random loops that keep >= 4 cells from every point: winding number = sum of the detected
// indices inside = sum of the analytic indices inside.
TEST(PoincareHopf, WindingNumberOfRandomLoopsIsTheSumOfEnclosedIndices) {
  const VectorField field = sampleField(kHopfGrid, mixedField);
  const PlanarField planar(field, 0);
  const auto points = findCriticalPoints(planar, {});
  std::mt19937 rng(20240611);
  std::set<int> sumsSeen;
  int tested = 0;
  while (tested < 40) {
    const std::vector<Vec2> loop = randomLoop(rng);
    bool usable = true;
    for (const Vec2& v : loop) usable &= std::abs(v.x()) < 1.98 && std::abs(v.y()) < 1.98;
    for (const AnalyticPoint& a : kPoints) usable &= distanceToPolygon(loop, a.position) > 0.1;
    if (!usable) continue;
    ++tested;
    int analytic = 0, detected = 0;
    for (const AnalyticPoint& a : kPoints) analytic += insidePolygon(loop, a.position) ? a.index : 0;
    for (const auto& p : points)
      detected += insidePolygon(loop, Vec2(p.position.x(), p.position.y())) ? p.index : 0;
    const auto winding = windingNumberAlongPolygon(planar, loop);
    ASSERT_TRUE(winding.has_value());
    EXPECT_EQ(*winding, analytic) << "loop " << tested;
    EXPECT_EQ(detected, analytic) << "loop " << tested;
    // Reversing the loop reverses the winding.
    const std::vector<Vec2> reversed(loop.rbegin(), loop.rend());
    EXPECT_EQ(*windingNumberAlongPolygon(planar, reversed), -analytic);
    sumsSeen.insert(analytic);
  }
  // The loops must have probed several different sums (so this test can fail).
  EXPECT_GE(sumsSeen.size(), 4u);
}

// On a circle the index does not depend on the radius as long as no other zero is crossed.
TEST(PoincareHopf, IndexOnCirclesAroundTheDegeneratePoints) {
  const PlanarField planar(sampleField(kHopfGrid, mixedField), 0);
  for (const AnalyticPoint& a : kPoints) {
    const Vec2 q = planar.toIndex(Vec3(a.position.x(), a.position.y(), 0));
    for (double r : {3.0, 6.0, 10.0}) EXPECT_EQ(indexOnCircle(planar, q, r), a.index) << r;
  }
}
