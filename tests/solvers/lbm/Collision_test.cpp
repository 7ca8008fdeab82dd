// Properties of the collision operators (CollisionBGK.h, CollisionTRT.h) with Guo forcing, node
// by node, for D2Q9 and D3Q19. References: collision conserves mass; it conserves momentum
// without force and adds exactly F = rho g with it (Guo, Zheng & Shi 2002:
// sum_q c_q f_q* = sum_q c_q f_q + F); the pair-split arithmetic on shifted populations
// g = f - w equals the textbook formulas f - omega (f - f^eq) + (1 - omega/2) S (BGK) and
// f - omega+ (f+ - f+eq) - omega- (f- - f-eq) + (1 - omega+/2) S+ + (1 - omega-/2) S- (TRT,
// Ginzburg et al. 2008); TRT with omega- = omega+ is BGK; the equilibrium reproduces rho and
// rho u (Qian et al. 1992). Tolerances: 1e-15 (double round-off of O(1) sums).
#include <gtest/gtest.h>

#include <random>

#include "solvers/lbm/collision/CollisionBGK.h"
#include "solvers/lbm/collision/CollisionTRT.h"
#include "solvers/lbm/lattice/LatticeD2Q9.h"
#include "solvers/lbm/lattice/LatticeD3Q19.h"

namespace fluidviz::lbm {
namespace {

template <class L>
struct Populations {
  double f[L::Q];  // full populations
  void toShifted(double* g) const {
    for (int q = 0; q < L::Q; ++q) g[q] = f[q] - L::w[q];
  }
  void fromShifted(const double* g) {
    for (int q = 0; q < L::Q; ++q) f[q] = g[q] + L::w[q];
  }
};

// Near-equilibrium populations with random non-equilibrium parts (seeded).
template <class L>
Populations<L> randomPopulations(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.08, 0.08), rho(0.9, 1.1), noise(-0.01, 0.01);
  const double r = rho(rng), ux = u(rng), uy = u(rng), uz = L::D == 3 ? u(rng) : 0.0;
  Populations<L> p;
  for (int q = 0; q < L::Q; ++q) p.f[q] = equilibrium<L>(q, r, ux, uy, uz) * (1.0 + noise(rng));
  return p;
}

struct Moments {
  double rho, j[3];
};
template <class L>
Moments moments(const double* f) {
  Moments m{0, {0, 0, 0}};
  for (int q = 0; q < L::Q; ++q) {
    m.rho += f[q];
    m.j[0] += f[q] * L::cx[q];
    m.j[1] += f[q] * L::cy[q];
    m.j[2] += f[q] * L::cz[q];
  }
  return m;
}

template <class L>
class CollisionTest : public ::testing::Test {};
using Lattices = ::testing::Types<LatticeD2Q9, LatticeD3Q19>;
TYPED_TEST_SUITE(CollisionTest, Lattices);

TYPED_TEST(CollisionTest, EquilibriumHasTheGivenDensityAndMomentum) {
  using L = TypeParam;
  double f[L::Q], g[L::Q];
  for (int q = 0; q < L::Q; ++q) {
    f[q] = equilibrium<L>(q, 1.05, 0.07, -0.03, L::D == 3 ? 0.02 : 0.0);
    g[q] = shiftedEquilibrium<L>(q, 1.05, 0.07, -0.03, L::D == 3 ? 0.02 : 0.0);
    EXPECT_NEAR(g[q], f[q] - L::w[q], 1e-15);
  }
  const Moments m = moments<L>(f);
  EXPECT_NEAR(m.rho, 1.05, 1e-15);
  EXPECT_NEAR(m.j[0], 1.05 * 0.07, 1e-15);
  EXPECT_NEAR(m.j[1], 1.05 * -0.03, 1e-15);
  EXPECT_NEAR(m.j[2], L::D == 3 ? 1.05 * 0.02 : 0.0, 1e-15);
}

// Applies `op` (a collision on shifted populations) to full populations.
template <class L, class Op>
void collideFull(Populations<L>& p, Op op) {
  double g[L::Q];
  p.toShifted(g);
  op(g);
  p.fromShifted(g);
}

TYPED_TEST(CollisionTest, ConservesMassAndMomentumWithoutForce) {
  using L = TypeParam;
  std::mt19937 rng(7);
  const CollisionBGK bgk{1.0 / 0.6};
  const CollisionTRT trt{1.0 / 0.6, CollisionTRT::omegaMinusFor(0.6, 3.0 / 16)};
  for (int trial = 0; trial < 100; ++trial) {
    for (int which = 0; which < 2; ++which) {
      Populations<L> p = randomPopulations<L>(rng);
      const Moments before = moments<L>(p.f);
      collideFull(p, [&](double* g) {
        if (which == 0)
          bgk.collide<L, false>(g);
        else
          trt.collide<L, false>(g);
      });
      const Moments after = moments<L>(p.f);
      EXPECT_NEAR(after.rho, before.rho, 1e-15);
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(after.j[a], before.j[a], 1e-15);
    }
  }
}

TYPED_TEST(CollisionTest, GuoForcingAddsExactlyTheForce) {
  using L = TypeParam;
  std::mt19937 rng(11);
  const double g3[3] = {2e-4, -5e-5, L::D == 3 ? 7e-5 : 0.0};
  const CollisionBGK bgk{1.0 / 0.9, g3[0], g3[1], g3[2]};
  const CollisionTRT trt{1.0 / 0.9, CollisionTRT::omegaMinusFor(0.9, 0.25), g3[0], g3[1], g3[2]};
  for (int trial = 0; trial < 100; ++trial) {
    for (int which = 0; which < 2; ++which) {
      Populations<L> p = randomPopulations<L>(rng);
      const Moments before = moments<L>(p.f);
      collideFull(p, [&](double* g) {
        if (which == 0)
          bgk.collide<L, true>(g);
        else
          trt.collide<L, true>(g);
      });
      const Moments after = moments<L>(p.f);
      EXPECT_NEAR(after.rho, before.rho, 1e-15);
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(after.j[a], before.j[a] + before.rho * g3[a], 1e-15);
    }
  }
}

// Velocity u = (sum f c + F/2) / rho of full populations.
template <class L>
void halfForceVelocity(const double* f, const double (&g)[3], double& rho, double (&u)[3]) {
  const Moments m = moments<L>(f);
  rho = m.rho;
  for (int a = 0; a < 3; ++a) u[a] = m.j[a] / m.rho + 0.5 * g[a];
}

TYPED_TEST(CollisionTest, BgkPairSplitEqualsTextbookFormula) {
  using L = TypeParam;
  std::mt19937 rng(3);
  const double omega = 1.0 / 0.7, g[3] = {1e-4, 3e-4, L::D == 3 ? -2e-4 : 0.0};
  const CollisionBGK bgk{omega, g[0], g[1], g[2]};
  for (int trial = 0; trial < 100; ++trial) {
    Populations<L> p = randomPopulations<L>(rng);
    double rho, u[3];
    halfForceVelocity<L>(p.f, g, rho, u);
    double expected[L::Q];
    for (int q = 0; q < L::Q; ++q)
      expected[q] = p.f[q] - omega * (p.f[q] - equilibrium<L>(q, rho, u[0], u[1], u[2])) +
                    (1 - omega / 2) *
                        guoSourceTerm<L>(q, u[0], u[1], u[2], rho * g[0], rho * g[1], rho * g[2]);
    collideFull(p, [&](double* s) { bgk.collide<L, true>(s); });
    for (int q = 0; q < L::Q; ++q) EXPECT_NEAR(p.f[q], expected[q], 1e-15) << "q = " << q;
  }
}

TYPED_TEST(CollisionTest, TrtEqualsTextbookFormulaAndBgkAtEqualRates) {
  using L = TypeParam;
  std::mt19937 rng(5);
  const double tau = 0.62, magic = 3.0 / 16, g[3] = {-1e-4, 2e-4, L::D == 3 ? 1e-4 : 0.0};
  const double op = 1.0 / tau, om = CollisionTRT::omegaMinusFor(tau, magic);
  EXPECT_NEAR((tau - 0.5) * (1.0 / om - 0.5), magic, 1e-15);  // the magic parameter
  const CollisionTRT trt{op, om, g[0], g[1], g[2]};
  for (int trial = 0; trial < 100; ++trial) {
    Populations<L> p = randomPopulations<L>(rng);
    double rho, u[3];
    halfForceVelocity<L>(p.f, g, rho, u);
    double expected[L::Q];
    for (int q = 0; q < L::Q; ++q) {
      const int o = L::opposite[q];
      const double eq = equilibrium<L>(q, rho, u[0], u[1], u[2]);
      const double eo = equilibrium<L>(o, rho, u[0], u[1], u[2]);
      const double sq = guoSourceTerm<L>(q, u[0], u[1], u[2], rho * g[0], rho * g[1], rho * g[2]);
      const double so = guoSourceTerm<L>(o, u[0], u[1], u[2], rho * g[0], rho * g[1], rho * g[2]);
      const double plus = 0.5 * (p.f[q] + p.f[o]), minus = 0.5 * (p.f[q] - p.f[o]);
      expected[q] = p.f[q] - op * (plus - 0.5 * (eq + eo)) - om * (minus - 0.5 * (eq - eo)) +
                    (1 - op / 2) * 0.5 * (sq + so) + (1 - om / 2) * 0.5 * (sq - so);
    }
    Populations<L> asBgk = p;
    collideFull(p, [&](double* s) { trt.collide<L, true>(s); });
    for (int q = 0; q < L::Q; ++q) EXPECT_NEAR(p.f[q], expected[q], 1e-15) << "q = " << q;
    // Equal rates: the BGK result.
    const CollisionTRT equal{op, op, g[0], g[1], g[2]};
    const CollisionBGK bgk{op, g[0], g[1], g[2]};
    Populations<L> asTrt = asBgk;
    collideFull(asBgk, [&](double* s) { bgk.collide<L, true>(s); });
    collideFull(asTrt, [&](double* s) { equal.collide<L, true>(s); });
    for (int q = 0; q < L::Q; ++q) EXPECT_NEAR(asTrt.f[q], asBgk.f[q], 1e-15) << "q = " << q;
  }
}

// Single precision on shifted populations: the float collision agrees with the double one to
// float round-off of the deviations g (|g| <~ 0.05 here, so 1e-8 absolute), not of f ~ 0.3
// (3e-8), which is what storing g instead of f buys.
TYPED_TEST(CollisionTest, FloatCollisionOnShiftedPopulationsMatchesDouble) {
  using L = TypeParam;
  std::mt19937 rng(13);
  const CollisionTRT trt{1.0 / 0.55, CollisionTRT::omegaMinusFor(0.55, 0.25), 1e-5, 0.0, 0.0};
  double worst = 0.0;
  for (int trial = 0; trial < 100; ++trial) {
    const Populations<L> p = randomPopulations<L>(rng);
    double gd[L::Q];
    float gf[L::Q];
    p.toShifted(gd);
    for (int q = 0; q < L::Q; ++q) gf[q] = static_cast<float>(gd[q]);
    trt.collide<L, true>(gd);
    trt.collide<L, true>(gf);
    for (int q = 0; q < L::Q; ++q) worst = std::max(worst, std::abs(double(gf[q]) - gd[q]));
  }
  EXPECT_LT(worst, 2e-8);
}

}  // namespace
}  // namespace fluidviz::lbm
