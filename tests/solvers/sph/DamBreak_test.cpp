// Collapse of a water column (Martin & Moyce 1952), 2D: column a = 0.5 m wide, 2a high, tank
// 4a long, a / dx = 20 (800 particles), c0 = 10 sqrt(2 g a) = 31.3 m/s.
// Surge front Z = (max x + dx/2) / a against T = t sqrt(2 g / a), sampled every 0.05 in T and
// interpolated at the published points after shifting simulated T by +0.175 (gate opening,
// see the data file's header). The front is that of the water body: particles with fewer than
// two fluid neighbours within 1.5 dx (isolated spray drops) are not counted.
//   model B (alpha = 0.1, delta-SPH 0.1): |Z - Z_MM| <= 0.15 for T <= 2.5    (measured 0.070;
//     model B throws no spray: the same with every particle counted)
//   model A (no viscosity; h = 1.5 dx, max_density_error 0.2): error reported, and bounded by
//     0.5 so that a broken model A still fails                            (measured 0.27; its
//     spray runs up to 0.5 a ahead of the water body)
//   both: no particle, spray included, ever passes Ritter's dry-bed bound Z < 1 + 2 T
//   (unshifted T > 0).
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/support/SphScenes.h"
#include "solvers/sph/SurgeFrontMartinMoyce.h"

namespace fluidviz::sph {
namespace {

// The front sampling and comparison live in solvers/sph/SurgeFrontMartinMoyce.h (shared with
// bench/sph_tradeoff.cpp).
SurgeFrontComparison runDamBreak(const SphParams& p, double a) {
  SphSolver s(p);
  const std::vector<SurgeFrontPoint> data =
      readMartinMoyce(std::string(FLUIDVIZ_EXAMPLE_DATA_DIR) + "/martin_moyce_1952_surge_front.csv");
  EXPECT_GE(data.size(), 11u) << "reference data missing";
  const SurgeFrontComparison r = compareSurgeFront(s, a, test::kGravity, data);
  EXPECT_LT(test::largestMagnitude(s.fluid()), 1e6);  // finite, sane
  return r;
}

TEST(DamBreak, ModelBFollowsMartinMoyce) {
  const double a = 0.5;
  SphParams p = test::damBreak2D("B", a, 20);
  p.alpha = 0.1;
  const SurgeFrontComparison r = runDamBreak(p, a);
  EXPECT_LE(r.maxError, 0.15);
  EXPECT_LT(r.maxRitterExcess, 0.0);
  std::printf("[measured] model B: max |dZ| = %.3f, max Z - (1 + 2T) = %.3f\n", r.maxError,
              r.maxRitterExcess);
}

TEST(DamBreak, ModelAErrorIsReportedAndBelowRitter) {
  const double a = 0.5;
  SphParams p = test::damBreak2D("A", a, 20);
  p.smoothing_length_ratio = 1.5;  // at 1.3 particles clump at the impact (>20% compression)
  p.max_density_error = 0.2;       // summation density piles up at the bottom corner
  const SurgeFrontComparison r = runDamBreak(p, a);
  EXPECT_LE(r.maxError, 0.5);
  EXPECT_LT(r.maxRitterExcess, 0.0);
  std::printf("[measured] model A: max |dZ| = %.3f, max Z - (1 + 2T) = %.3f\n", r.maxError,
              r.maxRitterExcess);
}

}  // namespace
}  // namespace fluidviz::sph
