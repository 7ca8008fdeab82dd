// Forced channel (Poiseuille flow) between no-slip bounce-back walls, periodic along x, at channel
// density d = 0.2, for FHP-I, FHP-II and FHP-III. In the steady state the time- and row-averaged
// current obeys nu j''(y) = -F(y) (F: momentum added per node and step), so with a uniform force
// j(y) is a parabola whose curvature gives nu. Reference: the Boltzmann viscosities nu(d) of
// Frisch et al. 1987 (Complex Systems 1:649, section 6; FhpTestSupport.h); Kadanoff, McNamara &
// Zanetti 1987 (Complex Systems 1:791) measured lattice-gas viscosities with this Poiseuille
// viscometer.
//
// The force by momentum flips is not uniform: a flip needs a particle along -c_0 and a hole along
// +c_0, so its rate p n_3 (1 - n_0) falls where the flow is fast (by about 2.5 u relative in
// FHP-I; about 10% between wall and centre here). Fitting a plain parabola with the mean force
// then overestimates nu by 5-15%, growing with the flow speed. The test therefore measures the
// force of every row, p times the nodes where a flip can happen after the collision (the same
// tables and chirality bits as the stepper; on a few steps the flips themselves are predicted with
// the stepper's random bits and checked against its count, and over the run the candidates must
// give the force of the flips made), and fits j = c0 + c1 y - G(y) / nu with G'' = F(y). The
// parabola's R^2 is checked on its own. Tolerances (the acceptance of issue 19): R^2 > 0.99, nu
// within 10%.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <string>

#include "solvers/fhp/kernel/RandomBits.h"
#include "solvers/fhp/lattice/BitLattice.h"
#include "solvers/fhp/lattice/Initialisation.h"
#include "solvers/fhp/lattice/TriangularLattice.h"
#include "tests/solvers/fhp/FhpTestSupport.h"

namespace fluidviz::fhp {
namespace {

BitLattice channel(int nx, int ny) {
  BitLattice lattice(nx, ny);
  for (int x = 0; x < nx; ++x) {
    lattice.setSolid(x, 0, true);
    lattice.setSolid(x, ny - 1, true);
  }
  return lattice;
}

/// Flips the next step of `lattice` will make, per row: the stepper's rule (collision with the
/// node's chirality bit, then the flip event) applied to the current state.
std::vector<std::uint64_t> flipsPerRow(const BitLattice& lattice, const CollisionTable& table,
                                       const StepRules& rules) {
  const std::uint64_t threshold = probabilityThreshold(rules.forceProbability);
  const std::uint64_t t = lattice.time();
  std::vector<std::uint64_t> flips(lattice.ny(), 0);
  for (int y = 0; y < lattice.ny(); ++y)
    for (int x = 0; x < lattice.nx(); ++x) {
      if (lattice.isSolid(x, y) || !eventHappens(rules.seed, t, x, y, threshold)) continue;
      const std::uint8_t s = table.after[chiralityBit(rules.seed, t, x, y)][lattice.node(x, y)];
      flips[y] += applyForceFlip(s, rules.forceDirection) != s;
    }
  return flips;
}

/// Fluid nodes per row where the next step could flip (after the collision a particle along -c_d
/// and a hole along +c_d): p times this count is the row's expected number of flips, a far less
/// noisy measure of the force profile than the flips themselves (a few hundred per row and run).
std::vector<double> flipCandidatesPerRow(const BitLattice& lattice, const CollisionTable& table,
                                         const StepRules& rules) {
  const std::uint64_t t = lattice.time();
  std::vector<double> candidates(lattice.ny(), 0.0);
  for (int y = 0; y < lattice.ny(); ++y)
    for (int w = 0; w < lattice.wordsPerRow(); ++w) {
      const std::uint64_t chirality = chiralityWord(rules.seed, t, y, w), solid = lattice.solidWord(y, w);
      for (int b = 0; b < 64; ++b) {
        if ((solid >> b) & 1u) continue;
        const std::uint8_t s = table.after[(chirality >> b) & 1u][lattice.node(64 * w + b, y)];
        candidates[y] += applyForceFlip(s, rules.forceDirection) != s;
      }
    }
  return candidates;
}

struct ChannelResult {
  double force = 0;          ///< mean momentum added per fluid node and step (flips counted)
  double expectedForce = 0;  ///< the same from the flip candidates
  double jMax = 0;           ///< largest row-pair current
  double r2 = 0;             ///< R^2 of the plain parabola
  double nu = 0;             ///< from the fit with the measured force profile
  bool flipCountsAgree = false;
};

/// Rows sampled every 2nd step (a popcount per word), flip candidates every `candidateEvery`-th;
/// the flips of the first 8 candidate samples are also predicted exactly and checked against the
/// stepper's count.
ChannelResult runChannel(Model model, double d, double p, int nx, int ny, int settle, int window,
                         int candidateEvery, std::uint64_t seed) {
  const CollisionTable table = buildCollisionTable(model);
  BitLattice lattice = channel(nx, ny);
  fillEquilibrium(lattice, model, d, [](int, int) { return std::array<double, 2>{0.0, 0.0}; }, seed);
  const StepRules rules{.model = model, .seed = seed + 1, .forceProbability = p, .forceDirection = 0};
  for (int t = 0; t < settle; ++t) lattice.step(table, rules);

  std::vector<double> jx(ny, 0.0), candidates(ny, 0.0);
  std::uint64_t flips = 0;
  int rowSamples = 0, candidateSamples = 0;
  bool agree = true;
  for (int t = 0; t < window; ++t) {
    if (t % 2 == 0) {
      const auto rows = testing::rowCurrentX(lattice);
      for (int y = 0; y < ny; ++y) jx[y] += rows[y];
      ++rowSamples;
    }
    std::uint64_t predicted = 0;
    const bool sampleCandidates = t % candidateEvery == 0, checkFlips = candidateSamples < 8;
    if (sampleCandidates) {
      const auto c = flipCandidatesPerRow(lattice, table, rules);
      for (int y = 0; y < ny; ++y) candidates[y] += c[y];
      if (checkFlips)
        for (std::uint64_t f : flipsPerRow(lattice, table, rules)) predicted += f;
      ++candidateSamples;
    }
    const std::uint64_t made = lattice.step(table, rules);
    if (sampleCandidates && checkFlips) agree = agree && made == predicted;
    flips += made;
  }
  ChannelResult r;
  r.flipCountsAgree = agree;
  const double fluidNodes = static_cast<double>(nx) * (ny - 2);
  r.force = 2.0 * static_cast<double>(flips) / (fluidNodes * window);  // each flip adds 2 c_0
  std::vector<double> rowForce(ny);
  for (int y = 0; y < ny; ++y) {
    rowForce[y] = 2.0 * p * candidates[y] / (static_cast<double>(nx) * candidateSamples);
    r.expectedForce += rowForce[y] * nx / fluidNodes;
    jx[y] /= rowSamples;
  }

  // Row pairs (1, 2), (3, 4), ...: the staggered invariants of FHP (Kadanoff, McNamara & Zanetti
  // 1989), which alternate from row to row and never decay, cancel in a pair. Pair k is centred at
  // y_k = (2 k + 1.5) sqrt(3)/2 links, pairs are h = sqrt(3) links apart.
  const int n = (ny - 2) / 2;
  const double h = 2 * kRowSpacing;
  Eigen::VectorXd j(n), f(n), y(n), g(n);
  for (int k = 0; k < n; ++k) {
    y(k) = (2 * k + 1.5) * kRowSpacing;
    j(k) = 0.5 * (jx[2 * k + 1] + jx[2 * k + 2]);
    f(k) = 0.5 * (rowForce[2 * k + 1] + rowForce[2 * k + 2]);
  }
  // G'' = F by the central difference, G_0 = G_1 = 0 (the linear part is fitted by c0, c1).
  g(0) = 0;
  g(1) = 0;
  for (int k = 1; k + 1 < n; ++k) g(k + 1) = 2 * g(k) - g(k - 1) + h * h * f(k);

  Eigen::MatrixXd parabola(n, 3), forced(n, 3);
  for (int k = 0; k < n; ++k) {
    parabola.row(k) << y(k) * y(k), y(k), 1.0;
    forced.row(k) << -g(k), y(k), 1.0;
  }
  const Eigen::VectorXd quadratic = parabola.colPivHouseholderQr().solve(j);
  const Eigen::VectorXd residual = j - parabola * quadratic;
  r.r2 = 1.0 - residual.squaredNorm() / (j.array() - j.mean()).square().sum();
  r.nu = 1.0 / forced.colPivHouseholderQr().solve(j)(0);
  r.jMax = j.maxCoeff();
  return r;
}

struct ChannelCase {
  Model model;
  int ny;         ///< rows, the two wall rows included
  double p;       ///< flip probability
  int settle;     ///< steps from rest before averaging
  int window;     ///< steps averaged
};

class ChannelTest : public ::testing::TestWithParam<ChannelCase> {};

// d = 0.2, 512 nodes along x, settled from rest for about 3.5 e-folding times of the slowest mode,
// then 4000 (FHP-I) or 6000 steps averaged (rows every 2nd step, flip candidates every 16th);
// centre velocities 0.09-0.1 links per step. Measured over four seeds each (R^2 >= 0.993 in every
// run; candidates x p within 1.5% of the flips made):
//   FHP-I   32 fluid rows: +0.1% to +4.1% (in 16 rows +8% to +10%: the mean free path of FHP-I
//           is no longer small against the width, and R^2 fell to 0.987)
//   FHP-II  16 fluid rows: +2.7% to +5.7%
//   FHP-III 16 fluid rows: +3.0% to +5.4%
TEST_P(ChannelTest, ForcedFlowIsParabolicWithTheBoltzmannViscosity) {
  const auto [model, ny, p, settle, window] = GetParam();
  const double d = 0.2, nu = latticeViscosity(model, d);
  const ChannelResult r = runChannel(model, d, p, 512, ny, settle, window, 16, 1);
  std::printf("channel %s: F %.3e (expected %.3e), j_max %.4f, R^2 %.5f, nu Boltzmann %.4f measured %.4f (%+.1f%%)\n",
              std::string(paramChoices(model)[static_cast<int>(model)].name).c_str(), r.force,
              r.expectedForce, r.jMax, r.r2, nu, r.nu, 100 * (r.nu / nu - 1));
  RecordProperty("nu_measured", std::to_string(r.nu));
  EXPECT_TRUE(r.flipCountsAgree);
  EXPECT_NEAR(r.expectedForce, r.force, 0.03 * r.force);  // candidates x p against flips made
  EXPECT_GT(r.r2, 0.99);
  EXPECT_NEAR(r.nu, nu, 0.10 * nu);
}

INSTANTIATE_TEST_SUITE_P(AllModels, ChannelTest,
                         ::testing::Values(ChannelCase{Model::fhp1, 34, 0.003, 400, 4000},
                                           ChannelCase{Model::fhp2, 18, 0.006, 600, 6000},
                                           ChannelCase{Model::fhp3, 18, 0.004, 600, 6000}));

// Without forcing, bounce-back walls and a periodic x: the particle count is conserved exactly.
TEST(Channel, UnforcedChannelConservesTheParticleCountExactly) {
  for (Model model : {Model::fhp1, Model::fhp2, Model::fhp3}) {
    const CollisionTable table = buildCollisionTable(model);
    BitLattice lattice = channel(128, 18);
    fillEquilibrium(lattice, model, 0.3,
                    [](int, int y) { return std::array<double, 2>{0.1 * std::sin(0.4 * y), 0.05}; }, 4);
    const std::uint64_t before = lattice.particleCount();
    for (int t = 0; t < 500; ++t) lattice.step(table, {.model = model, .seed = 6});
    EXPECT_EQ(lattice.particleCount(), before);
  }
}

}  // namespace
}  // namespace fluidviz::fhp
