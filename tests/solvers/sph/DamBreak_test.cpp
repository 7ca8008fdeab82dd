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
#include <fstream>
#include <sstream>

#include "SphTestScenes.h"

namespace fluidviz::sph {
namespace {

struct Point {
  double T, Z;
};

std::vector<Point> martinMoyce() {
  std::ifstream in(std::string(FLUIDVIZ_SHARED_DATA_DIR) + "/martin_moyce_1952_surge_front.csv");
  std::vector<Point> data;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'T') continue;
    std::istringstream s(line);
    Point p;
    char comma;
    s >> p.T >> comma >> p.Z;
    data.push_back(p);
  }
  return data;
}

double interpolate(const std::vector<Point>& curve, double T) {
  if (T <= curve.front().T) return curve.front().Z;
  for (std::size_t k = 1; k < curve.size(); ++k)
    if (T <= curve[k].T)
      return curve[k - 1].Z + (curve[k].Z - curve[k - 1].Z) * (T - curve[k - 1].T) /
                                  (curve[k].T - curve[k - 1].T);
  return curve.back().Z;
}

struct DamBreakResult {
  double maxError = 0.0;        // max |Z_sim(T - 0.175) - Z_MM(T)| over T <= 2.5
  double maxRitterExcess = -1;  // max Z - (1 + 2T) over samples, every particle counted
};

// Largest x of a particle with at least two others within 1.5 dx, and of any particle.
std::pair<double, double> frontPositions(const std::vector<Vec3>& x, double dx) {
  double body = 0.0, any = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    any = std::max(any, x[i][0]);
    if (x[i][0] <= body) continue;
    int close = 0;
    for (std::size_t j = 0; j < x.size() && close < 2; ++j)
      if (j != i && (x[i] - x[j]).squaredNorm() < 2.25 * dx * dx) ++close;
    if (close >= 2) body = x[i][0];
  }
  return {body, any};
}

DamBreakResult runDamBreak(const SphParams& p, double a) {
  SphSolver s(p);
  const double timeScale = std::sqrt(2 * test::kGravity / a);
  std::vector<Point> front{{0.0, 1.0}};
  DamBreakResult r;
  for (double T = 0.05; T <= 2.5 - 0.175 + 0.05 + 1e-9; T += 0.05) {
    s.advance(T / timeScale);
    const auto [body, any] = frontPositions(s.state().x, p.particle_spacing);
    front.push_back({T, (body + 0.5 * p.particle_spacing) / a});
    r.maxRitterExcess =
        std::max(r.maxRitterExcess, (any + 0.5 * p.particle_spacing) / a - (1 + 2 * T));
  }
  const std::vector<Point> data = martinMoyce();
  EXPECT_GE(data.size(), 11u) << "reference data missing";
  for (const Point& d : data) {
    if (d.T > 2.5) continue;
    const double err = interpolate(front, d.T - 0.175) - d.Z;
    r.maxError = std::max(r.maxError, std::abs(err));
  }
  EXPECT_LT(test::largestMagnitude(s.fluid()), 1e6);  // finite, sane
  return r;
}

TEST(DamBreak, ModelBFollowsMartinMoyce) {
  const double a = 0.5;
  SphParams p = test::damBreak2D("B", a, 20);
  p.alpha = 0.1;
  const DamBreakResult r = runDamBreak(p, a);
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
  const DamBreakResult r = runDamBreak(p, a);
  EXPECT_LE(r.maxError, 0.5);
  EXPECT_LT(r.maxRitterExcess, 0.0);
  std::printf("[measured] model A: max |dZ| = %.3f, max Z - (1 + 2T) = %.3f\n", r.maxError,
              r.maxRitterExcess);
}

}  // namespace
}  // namespace fluidviz::sph
