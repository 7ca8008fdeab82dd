// Properties of the D2Q9 BGK collision with Guo forcing (CollisionBGK.h), node by node:
// collision conserves mass; it conserves momentum without force and adds exactly F = rho g with
// it (Guo, Zheng & Shi 2002: sum_q c_q f_q* = sum_q c_q f_q + F); the optimised pair-split
// arithmetic equals the textbook formula f - omega (f - f^eq) + (1 - omega/2) S; and the
// equilibrium reproduces rho and rho u (Qian et al. 1992).
#include <gtest/gtest.h>

#include <random>

#include "solvers/lbm/CollisionBGK.h"
#include "solvers/lbm/LatticeD2Q9.h"

namespace fluidviz::lbm {
namespace {

using L = LatticeD2Q9;

struct Populations {
  double f[L::Q];
};

// Near-equilibrium populations with random non-equilibrium parts (seeded).
Populations randomPopulations(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.08, 0.08), rho(0.9, 1.1), noise(-0.01, 0.01);
  const double r = rho(rng), ux = u(rng), uy = u(rng);
  Populations p;
  for (int q = 0; q < L::Q; ++q) p.f[q] = equilibrium<L>(q, r, ux, uy) * (1.0 + noise(rng));
  return p;
}

struct Moments {
  double rho, jx, jy;
};
Moments moments(const double* f) {
  Moments m{0, 0, 0};
  for (int q = 0; q < L::Q; ++q) {
    m.rho += f[q];
    m.jx += f[q] * L::cx[q];
    m.jy += f[q] * L::cy[q];
  }
  return m;
}

TEST(CollisionBGK, EquilibriumHasTheGivenDensityAndMomentum) {
  double f[L::Q];
  for (int q = 0; q < L::Q; ++q) f[q] = equilibrium<L>(q, 1.05, 0.07, -0.03);
  const Moments m = moments(f);
  EXPECT_NEAR(m.rho, 1.05, 1e-15);
  EXPECT_NEAR(m.jx, 1.05 * 0.07, 1e-15);
  EXPECT_NEAR(m.jy, 1.05 * -0.03, 1e-15);
}

TEST(CollisionBGK, ConservesMassAndMomentumWithoutForce) {
  std::mt19937 rng(7);
  const CollisionBGK bgk{1.0 / 0.6, 0.0, 0.0};
  for (int trial = 0; trial < 100; ++trial) {
    Populations p = randomPopulations(rng);
    const Moments before = moments(p.f);
    bgk.collide<L, false>(p.f);
    const Moments after = moments(p.f);
    EXPECT_NEAR(after.rho, before.rho, 1e-15);
    EXPECT_NEAR(after.jx, before.jx, 1e-15);
    EXPECT_NEAR(after.jy, before.jy, 1e-15);
  }
}

TEST(CollisionBGK, GuoForcingAddsExactlyTheForce) {
  std::mt19937 rng(11);
  const double gx = 2e-4, gy = -5e-5;
  const CollisionBGK bgk{1.0 / 0.9, gx, gy};
  for (int trial = 0; trial < 100; ++trial) {
    Populations p = randomPopulations(rng);
    const Moments before = moments(p.f);
    bgk.collide<L, true>(p.f);
    const Moments after = moments(p.f);
    EXPECT_NEAR(after.rho, before.rho, 1e-15);
    EXPECT_NEAR(after.jx, before.jx + before.rho * gx, 1e-15);
    EXPECT_NEAR(after.jy, before.jy + before.rho * gy, 1e-15);
  }
}

TEST(CollisionBGK, PairSplitEqualsTextbookFormula) {
  std::mt19937 rng(3);
  const double omega = 1.0 / 0.7, gx = 1e-4, gy = 3e-4;
  const CollisionBGK bgk{omega, gx, gy};
  for (int trial = 0; trial < 100; ++trial) {
    Populations p = randomPopulations(rng);
    const NodeMoments m = nodeMoments<L>(p.f, gx, gy);
    double expected[L::Q];
    for (int q = 0; q < L::Q; ++q)
      expected[q] = p.f[q] - omega * (p.f[q] - equilibrium<L>(q, m.rho, m.ux, m.uy)) +
                    (1 - omega / 2) * guoSourceTerm<L>(q, m.ux, m.uy, m.rho * gx, m.rho * gy);
    bgk.collide<L, true>(p.f);
    for (int q = 0; q < L::Q; ++q) EXPECT_NEAR(p.f[q], expected[q], 1e-16) << "q = " << q;
  }
}

}  // namespace
}  // namespace fluidviz::lbm
