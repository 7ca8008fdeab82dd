// Uniform-grid neighbour search against brute force: identical neighbour sets (and displacement
// vectors) for random points in 2D and 3D, with walls and with periodic axes, for the
// particles themselves (neighborLists) and for arbitrary query points (pointsWithin), including
// points outside the box and radii larger than the cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "solvers/sph/UniformGridNeighborSearch.h"

namespace fluidviz::sph {
namespace {

std::vector<Vec3> randomPoints(int n, int dim, const Vec3& lo, const Vec3& hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Vec3> p(n);
  for (Vec3& x : p) {
    for (int a = 0; a < 3; ++a) {
      std::uniform_real_distribution<double> u(lo[a], hi[a]);
      x[a] = a < dim ? u(rng) : 0.0;
    }
  }
  return p;
}

// a - b with the minimum image on periodic axes.
Vec3 minimumImage(Vec3 d, const Vec3& period, const std::array<bool, 3>& periodic) {
  for (int a = 0; a < 3; ++a)
    if (periodic[a]) d[a] -= period[a] * std::round(d[a] / period[a]);
  return d;
}

std::vector<int> bruteForce(const std::vector<Vec3>& pts, const Vec3& x, double radius,
                            const Vec3& period, const std::array<bool, 3>& periodic, int self) {
  std::vector<int> out;
  for (int j = 0; j < static_cast<int>(pts.size()); ++j)
    if (j != self && minimumImage(x - pts[j], period, periodic).squaredNorm() < radius * radius)
      out.push_back(j);
  return out;
}

void expectSameAsBruteForce(int dim, std::array<bool, 3> periodic) {
  const Vec3 lo(-0.3, 0.1, 0.2), hi(0.9, 0.7, 0.85);
  const double cell = 0.05;
  const std::vector<Vec3> pts = randomPoints(dim == 2 ? 3000 : 6000, dim, lo, hi, 7 + dim);
  UniformGridNeighborSearch search(dim, lo, hi, cell, periodic);
  search.build(pts);
  const Vec3 period = hi - lo;
  // Neighbour lists of every particle, radius = cell size.
  NeighborLists lists;
  search.neighborLists(pts.size(), cell, lists);
  std::size_t total = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::vector<int> got(lists.of(i).begin(), lists.of(i).end());
    std::sort(got.begin(), got.end());
    ASSERT_EQ(got, bruteForce(pts, pts[i], cell, period, periodic, static_cast<int>(i)))
        << "particle " << i;
    total += got.size();
  }
  EXPECT_GT(total, pts.size() * (dim == 2 ? 20 : 5));  // ~32 (2D), ~6.7 (3D) on average
  // Arbitrary points (some outside the box), radii below and above the cell size.
  const std::vector<Vec3> queries = randomPoints(300, dim, lo - Vec3::Constant(0.2),
                                                 hi + Vec3::Constant(0.2), 99);
  std::vector<int> got;
  for (double radius : {0.03, 0.05, 0.12}) {
    for (const Vec3& q : queries) {
      search.pointsWithin(q, radius, got);
      std::sort(got.begin(), got.end());
      ASSERT_EQ(got, bruteForce(pts, q, radius, period, periodic, -1)) << "radius " << radius;
    }
  }
  // The displacement handed to the callback is the minimum-image x - x_j.
  search.forEachWithin(queries[0], 0.12, [&](int j, const Vec3& d, double r2) {
    EXPECT_LT((d - minimumImage(queries[0] - pts[j], period, periodic)).norm(), 1e-12);
    EXPECT_NEAR(r2, d.squaredNorm(), 1e-15);
  });
}

TEST(UniformGridNeighborSearch, MatchesBruteForce2D) { expectSameAsBruteForce(2, {false, false, false}); }
TEST(UniformGridNeighborSearch, MatchesBruteForce3D) { expectSameAsBruteForce(3, {false, false, false}); }
TEST(UniformGridNeighborSearch, MatchesBruteForcePeriodic2D) {
  expectSameAsBruteForce(2, {true, false, false});
}
TEST(UniformGridNeighborSearch, MatchesBruteForcePeriodic3D) {
  expectSameAsBruteForce(3, {true, true, true});
}

TEST(UniformGridNeighborSearch, WrapAndRejectTooShortPeriod) {
  const Vec3 lo(0, 0, 0), hi(1, 1, 1);
  UniformGridNeighborSearch s(2, lo, hi, 0.1, {true, false, false});
  EXPECT_NEAR(s.wrap(Vec3(1.25, 0.5, 0))[0], 0.25, 1e-15);
  EXPECT_NEAR(s.wrap(Vec3(-0.25, 0.5, 0))[0], 0.75, 1e-15);
  EXPECT_NEAR(s.displacement(Vec3(0.95, 0, 0), Vec3(0.05, 0, 0))[0], -0.1, 1e-15);
  EXPECT_THROW(UniformGridNeighborSearch(2, lo, hi, 0.4, {true, false, false}),
               std::invalid_argument);
  std::vector<Vec3> pts{Vec3(0.5, 0.5, 0)};
  s.build(pts);
  std::vector<int> out;
  EXPECT_THROW(s.pointsWithin(Vec3(0.5, 0.5, 0), 0.6, out), std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz::sph
