// Uniform-grid neighbour search against brute force: identical neighbour sets (and displacement
// vectors) for random points in 2D and 3D, with walls and with periodic axes, for the
// particles themselves (neighborLists) and for arbitrary query points (pointsWithin), including
// points outside the box and radii larger than the cell. Exact ties at the radius (the float
// pre-test of neighborLists must leave them to the double test) with 2 threads.
#include <omp.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "fieldviz/particles/UniformGridNeighborSearch.h"

namespace fluidviz::particles {
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

// A lattice whose spacing divides the radius puts many pairs at exactly the radius: the double
// test r^2 < radius^2 decides them, as brute force with the same expression does, whatever the
// float pre-test says. Two points far outside the box widen the float rounding band. 15627
// points (over kParallelMinItems: 2 threads), radii equal to, below and above the cell edge,
// and a sub-range of queries with maxNeighbor (the solver's wall lists). Every 7th query.
TEST(UniformGridNeighborSearch, ListsExactAtTiesWithThreadsAndSubranges) {
  const double dx = 0.1;
  std::vector<Vec3> pts;
  for (int k = 0; k < 25; ++k)
    for (int j = 0; j < 25; ++j)
      for (int i = 0; i < 25; ++i) pts.emplace_back(i * dx, j * dx, k * dx);
  pts.emplace_back(30.0, 0.5, 0.5);
  pts.emplace_back(-20.0, -20.0, 1.0);
  UniformGridNeighborSearch search(3, Vec3::Zero(), Vec3::Constant(2.5), 0.2);
  search.build(pts);
  auto brute = [&](std::size_t i, double radius, std::size_t maxNeighbor) {
    std::vector<int> out;
    for (std::size_t j = 0; j < std::min(pts.size(), maxNeighbor); ++j) {
      const double ex = pts[i][0] - pts[j][0], ey = pts[i][1] - pts[j][1],
                   ez = pts[i][2] - pts[j][2];
      if (j != i && ex * ex + ey * ey + ez * ez < radius * radius) out.push_back(int(j));
    }
    return out;
  };
  const int threadsBefore = omp_get_max_threads();
  omp_set_num_threads(2);
  NeighborLists lists;
  std::size_t ties = 0;
  for (double radius : {0.2, 0.15, 0.3}) {
    search.neighborLists(pts.size(), radius, lists);
    for (std::size_t i = 0; i < pts.size(); i += 7) {
      std::vector<int> got(lists.of(i).begin(), lists.of(i).end());
      std::sort(got.begin(), got.end());
      ASSERT_EQ(got, brute(i, radius, pts.size())) << "radius " << radius << " particle " << i;
      if (radius == 0.2) ties += brute(i, 0.2 + 1e-9, pts.size()).size() - got.size();
    }
  }
  EXPECT_GT(ties, 1000u);  // the lattice does put pairs at the radius
  search.neighborLists(100, pts.size(), 0.2, lists, 5000);
  ASSERT_EQ(lists.size(), pts.size() - 100);
  for (std::size_t k = 0; k < lists.size(); k += 7) {
    std::vector<int> got(lists.of(k).begin(), lists.of(k).end());
    std::sort(got.begin(), got.end());
    ASSERT_EQ(got, brute(100 + k, 0.2, 5000)) << "query " << 100 + k;
  }
  omp_set_num_threads(threadsBefore);
}

}  // namespace
}  // namespace fluidviz::particles
