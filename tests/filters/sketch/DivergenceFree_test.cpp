// Divergence-free projection: the discrete divergence it leaves, and that it is the orthogonal
// (least-change) projection.
#include "filters/sketch/grid/DivergenceFree.h"

#include <gtest/gtest.h>

#include <random>

#include "filters/sketch/SketchedFlow.h"
#include "tests/filters/sketch/SketchTestFields.h"

namespace fluidviz::sketch {
namespace {

double dot(const VectorField& a, const VectorField& b) {
  double s = 0.0;
  for (std::size_t n = 0; n < a.values.size(); ++n) s += a.values[n].dot(b.values[n]);
  return s;
}

// A random field (lattice units, |v| <= 0.1) on zero-flux and periodic grids: max |div u|
// below 1e-10 afterwards (issue 20); u is orthogonal to v - u (a projection, not just some
// divergence-free field), and projecting u again changes it by round-off only.
TEST(DivergenceFree, LeavesNoDivergenceAndIsAnOrthogonalProjection) {
  const Grid grid = testing::latticeGrid(40, 32);
  VectorField v{"v", grid, std::vector<Vec3>(grid.nodeCount())};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> r(-0.1, 0.1);
  for (Vec3& x : v.values) x = Vec3(r(rng), r(rng), 0.0);
  for (SketchBoundary b : {SketchBoundary::zero_flux, SketchBoundary::periodic}) {
    const PlaneGrid g = PlaneGrid::of(grid, b, b);
    const DivergenceFreeResult p = projectDivergenceFree(v, g);
    EXPECT_GT(p.divergenceBefore, 0.05);
    EXPECT_LT(p.divergenceAfter, 1e-10);
    EXPECT_LT(maxDivergence(p.field, g), 1e-10);
    VectorField change = v;
    for (std::size_t n = 0; n < v.values.size(); ++n) change.values[n] -= p.field.values[n];
    EXPECT_LT(std::abs(dot(change, p.field)), 1e-10 * dot(v, v)) << choiceName(b);
    const DivergenceFreeResult again = projectDivergenceFree(p.field, g);
    double moved = 0.0;
    for (std::size_t n = 0; n < v.values.size(); ++n)
      moved = std::max(moved, (again.field.values[n] - p.field.values[n]).norm());
    EXPECT_LT(moved, 1e-10);
  }
}

// In the sketch pipeline: a circle stroke's GVF field made divergence-free.
TEST(DivergenceFree, SketchedCircleBecomesDivergenceFree) {
  SketchParams p;
  p.divergence_free = true;
  const SketchedFlow f = sketchFlow({testing::circleStroke({24, 24, 0}, 12, 60, 0.05)},
                                    testing::latticeGrid(48, 48), p);
  EXPECT_GT(f.divergenceBefore, 1e-4);
  EXPECT_LT(f.divergenceAfter, 1e-10);
  RecordProperty("divergence_before", formatNumber(f.divergenceBefore, 3));
  RecordProperty("divergence_after", formatNumber(f.divergenceAfter, 3));
}

}  // namespace
}  // namespace fluidviz::sketch
