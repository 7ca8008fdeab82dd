// Force-driven plane Poiseuille flow between walls at y = 0 and y = H, periodic in x.
// Analytic: u(y) = g / (2 nu) y (H - y) (e.g. Krueger et al. 2017, sec. 5.2.1).
// With BGK and halfway bounce-back the discrete solution is a parabola whose wall slip depends on
// tau; it vanishes at tau = 1/2 + sqrt(3/16) (He, Zou, Luo & Dembo 1997, J. Stat. Phys. 87:115;
// Ginzburg's "magic" Lambda = (tau - 1/2)^2 = 3/16), where the profile is exact to round-off.
// Resolution: 32 nodes across the channel (8 along the periodic x axis), peak lattice speed 0.05.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "solvers/lbm/LbmSolverD2Q9.h"

namespace fluidviz::lbm {
namespace {

struct PoiseuilleResult {
  double relativeL2Error;
  double maxCrossVelocity;  // |u_y| / u_max
};

PoiseuilleResult runPoiseuille(double tau) {
  const double height = 1e-3, nu = 1e-6;  // m, m^2/s (water)
  const int across = 32;
  const double dx = height / across;
  const double dt = (tau - 0.5) / 3.0 * dx * dx / nu;
  const double uMax = 0.05 * dx / dt;                 // lattice peak speed 0.05
  const double g = 8.0 * nu * uMax / (height * height);  // u_max = g H^2 / (8 nu)
  LbmParams p;
  p.domain_size = {height / 4, height};
  p.resolution = across / 4;
  p.viscosity = nu;
  p.time_step = dt;
  p.body_force = {g, 0.0};
  p.walls.x_min.type = p.walls.x_max.type = "periodic";
  p.end_time = 200000 * dt;
  p.steady_tolerance = 1e-12;
  p.check_interval = 500;
  LbmSolverD2Q9 solver(p);
  EXPECT_EQ(solver.run(), StopReason::Steady);

  const FieldSet f = solver.fields();
  const VectorField& u = *f.findVector("velocity");
  double err2 = 0, ref2 = 0, cross = 0;
  for (int j = 0; j < u.grid.dims[1]; ++j)
    for (int i = 0; i < u.grid.dims[0]; ++i) {
      const double y = u.grid.position(i, j).y();
      const double exact = g / (2 * nu) * y * (height - y);
      const Vec3& v = u.values[u.grid.index(i, j)];
      err2 += (v.x() - exact) * (v.x() - exact);
      ref2 += exact * exact;
      cross = std::max(cross, std::abs(v.y()) / uMax);
    }
  return {std::sqrt(err2 / ref2), cross};
}

TEST(Poiseuille, Tau1At32NodesWithinOnePercent) {
  const PoiseuilleResult r = runPoiseuille(1.0);
  std::printf("Poiseuille, 32 nodes, tau = 1: relative L2 error %.3e (tolerance 1e-2)\n",
              r.relativeL2Error);
  EXPECT_LT(r.relativeL2Error, 1e-2);
  EXPECT_LT(r.maxCrossVelocity, 1e-10);
}

TEST(Poiseuille, ExactAtMagicTau) {
  const double magicTau = 0.5 + std::sqrt(3.0 / 16.0);
  const PoiseuilleResult r = runPoiseuille(magicTau);
  std::printf("Poiseuille, 32 nodes, tau = %.4f: relative L2 error %.3e (tolerance 1e-8)\n",
              magicTau, r.relativeL2Error);
  EXPECT_LT(r.relativeL2Error, 1e-8);
}

}  // namespace
}  // namespace fluidviz::lbm
