// The one-method-per-file pair terms against their formulas on two particles, with the
// properties that make them correct: antisymmetry (momentum), signs (pressure pushes apart,
// viscosity and artificial viscosity damp relative motion, the boundary force repels inside r0
// only, cohesion attracts), and the Tait equation of state inverting itself.
#include <gtest/gtest.h>

#include "solvers/sph/ArtificialViscosityMonaghan1992.h"
#include "solvers/sph/BoundaryRepulsionLennardJones.h"
#include "solvers/sph/CohesionBeckerTeschner2007.h"
#include "solvers/sph/DensityContinuity.h"
#include "solvers/sph/EquationOfStateTait.h"
#include "fieldviz/particles/KernelCubicSpline.h"
#include "solvers/sph/PressureMonaghan1992.h"
#include "solvers/sph/ViscosityMorris1997.h"
#include "solvers/sph/XsphCorrection.h"

namespace fluidviz::sph {
namespace {

const particles::KernelCubicSpline kW(0.013, 2);
const Vec3 xi(0.0, 0.0, 0.0), xj(0.008, 0.006, 0.0);  // r = 0.01 m
const Vec3 xij = xi - xj;
const double r = xij.norm(), m = 0.1;

TEST(PairTerms, PressureIsAntisymmetricAndRepulsive) {
  const Vec3 gi = kW.gradW(xij, r), gj = kW.gradW(-xij, r);
  const Vec3 ai = PressureMonaghan1992::acceleration(m, 1e-3, 2e-3, gi);
  const Vec3 aj = PressureMonaghan1992::acceleration(m, 2e-3, 1e-3, gj);
  EXPECT_LT((ai + aj).norm(), 1e-15 * ai.norm());  // equal masses: a_i = -a_j
  EXPECT_GT(ai.dot(xij), 0.0);                     // positive pressure pushes i away from j
  EXPECT_NEAR(ai.norm(), m * 3e-3 * std::abs(kW.dWdr(r)), 1e-12);
}

TEST(PairTerms, ContinuityGrowsDensityOfApproachingParticles) {
  const Vec3 vij(0.8, 0.6, 0.0);  // i moves towards j (x_j - x_i = (0.008, 0.006))
  EXPECT_GT(DensityContinuity::rate(m, vij, kW.gradW(xij, r)), 0.0);
  EXPECT_NEAR(DensityContinuity::rate(m, vij, kW.gradW(xij, r)), m * std::abs(kW.dWdr(r)), 1e-9);
}

TEST(PairTerms, ViscosityDampsRelativeVelocity) {
  const Vec3 vij(0.0, 1.0, 0.0), g = kW.gradW(xij, r);
  const double eta2 = 0.01 * 0.013 * 0.013;
  const Vec3 ai = ViscosityMorris1997::acceleration(m, 2e-3, 1000, 1000, xij, r * r, g, vij, eta2);
  const Vec3 aj =
      ViscosityMorris1997::acceleration(m, 2e-3, 1000, 1000, -xij, r * r, kW.gradW(-xij, r), -vij, eta2);
  EXPECT_LT(ai.dot(vij), 0.0);
  EXPECT_LT((ai + aj).norm(), 1e-15);
  // Wall extrapolation: 1 + d_j / d_i, with d_i bounded below.
  const Vec3 d = ViscosityMorris1997::wallVelocityDifference(Vec3(1, 0, 0), Vec3::Zero(), 0.005,
                                                           0.015, 0.005);
  EXPECT_NEAR(d[0], 4.0, 1e-15);
  EXPECT_NEAR(ViscosityMorris1997::wallVelocityDifference(Vec3(1, 0, 0), Vec3::Zero(), 1e-9,
                                                          0.015, 0.005)[0],
              4.0, 1e-15);
}

TEST(PairTerms, ArtificialViscosityActsOnlyOnApproach) {
  const ArtificialViscosityMonaghan1992 av{1.0, 2.0, 0.013, 0.01 * 0.013 * 0.013};
  const Vec3 g = kW.gradW(xij, r);
  const Vec3 approaching = -xij / r, receding = xij / r;  // v_ij
  const Vec3 a = av.acceleration(m, xij, r * r, approaching, 10.0, 1000.0, g);
  EXPECT_GT(a.dot(xij), 0.0);  // pushes i back, away from j
  EXPECT_EQ(av.acceleration(m, xij, r * r, receding, 10.0, 1000.0, g).norm(), 0.0);
  const double mu = 0.013 * approaching.dot(xij) / (r * r + 0.01 * 0.013 * 0.013);
  EXPECT_NEAR(a.norm(), m * (-1.0 * 10.0 * mu + 2.0 * mu * mu) / 1000.0 * g.norm(), 1e-12);
}

TEST(PairTerms, BoundaryRepulsionOnlyInsideCutOff) {
  const BoundaryRepulsionLennardJones lj{50.0, 0.012, 12, 4};
  const Vec3 a = lj.acceleration(xij, r * r);  // r = 0.01 < r0
  const double s = 0.012 / r;
  EXPECT_NEAR(a.norm(), 50.0 * (std::pow(s, 12) - std::pow(s, 4)) / r, 1e-9);
  EXPECT_GT(a.dot(xij), 0.0);
  EXPECT_EQ(lj.acceleration(1.3 * xij, 1.69 * r * r).norm(), 0.0);
  EXPECT_EQ(lj.acceleration(Vec3::Zero(), 0.0).norm(), 0.0);  // coincident: no direction
}

TEST(PairTerms, CohesionAttractsAndXsphAverages) {
  const Vec3 a = CohesionBeckerTeschner2007::acceleration(0.01, m, m, kW.W(r), xij);
  EXPECT_LT(a.dot(xij), 0.0);
  EXPECT_NEAR(a.norm(), 0.01 * kW.W(r) * r, 1e-12);
  const Vec3 corr = XsphCorrection::term(m, 1000.0, Vec3(1, 0, 0), kW.W(r));
  EXPECT_NEAR(corr[0], m / 1000.0 * kW.W(r), 1e-15);
}

TEST(PairTerms, TaitPressureAndDensityAreInverse) {
  const EquationOfStateTait eos(1000.0, 20.0, 7.0);
  EXPECT_DOUBLE_EQ(eos.pressure(1000.0), 0.0);
  EXPECT_NEAR(eos.density(eos.pressure(1013.0)), 1013.0, 1e-9);
  EXPECT_NEAR(eos.stiffness(), 1000.0 * 400.0 / 7.0, 1e-9);
  // c^2 = dp/drho
  const double e = 1e-4, c = eos.soundSpeed(1010.0);
  EXPECT_NEAR(c * c, (eos.pressure(1010.0 + e) - eos.pressure(1010.0 - e)) / (2 * e), 1e-4);
}

}  // namespace
}  // namespace fluidviz::sph
