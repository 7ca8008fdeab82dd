// Conservation laws of the whole stream-collide step. References: BGK collision conserves mass
// and momentum at every node, streaming permutes populations, bounce-back reflects them; with the
// Ladd moving-wall terms taken at the reference density their sum over a sliding lid and over the
// surface of a rotating roller is zero (MovingWallBounceBack.h). Hence total mass must be constant
// to round-off (relative 1e-12 allowed after 1000 steps; the sums are taken in long double).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "tests/support/LbmScenes.h"
#include "solvers/lbm/LbmSolverD2Q9.h"

namespace fluidviz::lbm {
namespace {

// Smooth random velocity: 12 Fourier modes with |k| <= 3 wave numbers and seeded random
// amplitudes and phases, scaled to a peak lattice speed of about 0.05; density +-1 %.
void initialiseRandomSmoothFlow(LbmSolverD2Q9& s, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> amp(-1.0, 1.0), phase(0.0, 2 * M_PI);
  std::uniform_int_distribution<int> wave(-3, 3);
  const LatticeUnits& u = s.units();
  const int nx = u.nx, ny = u.ny;
  std::vector<double> rho(std::size_t(nx) * ny, u.density);
  std::vector<Vec3> vel(rho.size(), Vec3::Zero());
  for (int mode = 0; mode < 12; ++mode) {
    const int kx = wave(rng), ky = wave(rng);
    const double ax = amp(rng), ay = amp(rng), ar = amp(rng), p = phase(rng);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double arg = 2 * M_PI * (kx * (i + 0.5) / nx + ky * (j + 0.5) / ny) + p;
        const std::size_t n = std::size_t(j) * nx + i;
        vel[n] += Vec3(ax, ay, 0.0) * u.toPhysicalVelocity(0.05 / 12 * 3) * std::sin(arg);
        rho[n] += u.density * 0.01 / 12 * 3 * ar * std::cos(arg);
      }
  }
  s.initialise(rho, vel);
}

struct Momentum {
  double x = 0, y = 0, magnitude = 0;  // lattice units: sum rho u, and sum rho |u|
};
Momentum totalMomentum(const LbmSolverD2Q9& s) {
  const FieldSet f = s.fields();
  const auto& rho = f.findScalar("density")->values;
  const auto& vel = f.findVector("velocity")->values;
  Momentum m;
  for (std::size_t n = 0; n < rho.size(); ++n) {
    const Vec3 j = s.units().toLatticeDensity(rho[n]) * vel[n] * s.units().dt / s.units().dx;
    m.x += j.x();
    m.y += j.y();
    m.magnitude += j.norm();
  }
  return m;
}

TEST(MassConservation, PeriodicBoxRandomSmoothFlow) {
  // 64 x 64 periodic, tau = 0.6, 1000 steps.
  LbmSolverD2Q9 solver(test::periodicBox(64, 0.6));
  initialiseRandomSmoothFlow(solver, 2024);
  const double mass0 = solver.totalMass();
  const Momentum p0 = totalMomentum(solver);
  ASSERT_NEAR(mass0, 64.0 * 64.0, 64.0 * 64.0 * 0.01);
  ASSERT_GT(p0.magnitude, 10.0);  // the flow is not at rest
  solver.step(1000);
  solver.checkStability();
  const double relativeMassChange = std::abs(solver.totalMass() - mass0) / mass0;
  EXPECT_LT(relativeMassChange, 1e-12);
  std::printf("Periodic box 64^2, 1000 steps: relative mass change %.2e (tolerance 1e-12)\n",
              relativeMassChange);
  // Momentum: no walls, no force -> conserved as well.
  const Momentum p1 = totalMomentum(solver);
  EXPECT_LT(std::abs(p1.x - p0.x), 1e-12 * p0.magnitude);
  EXPECT_LT(std::abs(p1.y - p0.y), 1e-12 * p0.magnitude);
}

TEST(MassConservation, ClosedBoxWithMovingLidAndRotatingRoller) {
  // 96 x 96 cavity (Re 100, u_lb 0.1) with an off-centre roller turning clockwise; 1000 steps.
  LbmParams p = test::lidDrivenCavity(96, 100, 0.1);
  p.rollers.push_back({{0.37, 0.41}, 0.173, -4.0});
  LbmSolverD2Q9 solver(p);
  const double mass0 = solver.totalMass();
  solver.step(1000);
  solver.checkStability();
  const double relativeMassChange = std::abs(solver.totalMass() - mass0) / mass0;
  EXPECT_LT(relativeMassChange, 1e-12);
  std::printf("Cavity + roller 96^2, 1000 steps: relative mass change %.2e (tolerance 1e-12)\n",
              relativeMassChange);
}

}  // namespace
}  // namespace fluidviz::lbm
