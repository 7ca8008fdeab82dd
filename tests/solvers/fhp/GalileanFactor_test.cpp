// The lattice gas is not Galilean invariant: its advection term is div(rho g(rho) u u), so a shear
// wave u_y = delta sin(k x) in a uniform flow U along x is carried at g(d) U, not U (Frisch et al.
// 1987, Complex Systems 1:649, section 4):
//   FHP-I            g = (1 - 2 d) / (2 (1 - d))
//   FHP-II, FHP-III  g = 7 (1 - 2 d) / (12 (1 - d))
// The speed is the drift of the phase of the wave's Fourier mode (the longest wave of a 128-link
// periodic lattice, 512 rows), fitted by least squares weighted by the mode's power over 600 steps
// (the wave of FHP-I decays by e in that time); U is the measured mean velocity (total current over
// total particle number). Tolerance 10% (the acceptance of issue 19). Measured at d = 0.2,
// U = 0.2, delta = 0.2 over five sets of seeds: FHP-I +2.1% to +5.6%, FHP-II +3.0% to +4.8%,
// FHP-III +2.7% to +3.9%; at U = 0.1 -1.4% to +3.4% with more noise (the excess at U = 0.2 is
// consistent with the O(U^2) terms the Boltzmann g(d) leaves out).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>

#include "solvers/fhp/lattice/BitLattice.h"
#include "solvers/fhp/lattice/Initialisation.h"
#include "tests/solvers/fhp/FhpTestSupport.h"

namespace fluidviz::fhp {
namespace {

using testing::fourierModeX;
using testing::Moment;

/// Mean velocity along x: total current over total particle number.
double meanVelocityX(const BitLattice& lattice) {
  double jx = 0, n = 0;
  for (int c = 0; c < kMaxChannels; ++c)
    for (int y = 0; y < lattice.ny(); ++y)
      for (int w = 0; w < lattice.wordsPerRow(); ++w) {
        const int bits = std::popcount(lattice.word(c, y, w));
        jx += kCx[c] * bits;
        n += bits;
      }
  return jx / n;
}

/// Weighted least-squares slope of y(t).
double slope(const std::vector<double>& t, const std::vector<double>& y, const std::vector<double>& w) {
  double s = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    s += w[i];
    st += w[i] * t[i];
    sy += w[i] * y[i];
    stt += w[i] * t[i] * t[i];
    sty += w[i] * t[i] * y[i];
  }
  return (s * sty - st * sy) / (s * stt - st * st);
}

class GalileanFactorTest : public ::testing::TestWithParam<Model> {};

TEST_P(GalileanFactorTest, ShearWaveIsCarriedAtGTimesTheFlowSpeed) {
  const Model model = GetParam();
  const int nx = 128, ny = 512, steps = 600, sampleEvery = 2;
  const double d = 0.2, flow = 0.2, delta = 0.2, k = 2 * std::numbers::pi / nx;
  const double g = galileanFactor(model, d);
  const CollisionTable table = buildCollisionTable(model);
  BitLattice lattice(nx, ny);
  fillEquilibrium(lattice, model, d,
                  [&](int x, int y) {
                    return std::array<double, 2>{flow, delta * std::sin(k * (x + 0.5 * (y % 2)))};
                  },
                  41);
  const double u = meanVelocityX(lattice);
  // The mode of u_y = delta sin(k (x - v t)) turns as exp(-i k v t): its phase falls at k v.
  std::vector<double> times, phases, weights;
  double unwrapped = 0, previous = 0;
  for (int t = 0; t <= steps; ++t) {
    if (t % sampleEvery == 0) {
      const std::complex<double> mode = fourierModeX(lattice, Moment::currentY);
      const double phase = std::arg(mode);
      if (t > 0) unwrapped += std::remainder(phase - previous, 2 * std::numbers::pi);
      previous = phase;
      if (t >= 10) {  // after the non-hydrodynamic transient
        times.push_back(t);
        phases.push_back(unwrapped);
        weights.push_back(std::norm(mode));
      }
    }
    lattice.step(table, {.model = model, .seed = 43});
  }
  const double measured = -slope(times, phases, weights) / k / u;
  RecordProperty("g_measured", std::to_string(measured));
  std::printf("%s: U %.4f, g theory %.4f measured %.4f (%+.1f%%)\n",
              std::string(paramChoices(model)[static_cast<int>(model)].name).c_str(), u, g, measured,
              100 * (measured / g - 1));
  EXPECT_NEAR(measured, g, 0.10 * g);
}

INSTANTIATE_TEST_SUITE_P(AllModels, GalileanFactorTest,
                         ::testing::Values(Model::fhp1, Model::fhp2, Model::fhp3));

}  // namespace
}  // namespace fluidviz::fhp
