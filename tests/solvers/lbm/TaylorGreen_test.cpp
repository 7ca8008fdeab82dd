// Decaying Taylor-Green vortex in a periodic box (Taylor & Green 1937; TaylorGreenVortex.h):
//   u = U0 sin(k x) cos(k y) e^{-2 nu k^2 t},  v = -U0 cos(k x) sin(k y) e^{-2 nu k^2 t}
//   p = rho U0^2 / 4 (cos 2kx + cos 2ky) e^{-4 nu k^2 t}
// checks that the physical viscosity the user asked for is the one the lattice produces
// (tau = 3 nu dt / dx^2 + 1/2) and that initialise() starts from the given fields.
// Resolution 64 x 64, tau = 0.8, U0 = 0.04 lattice, run to one e-folding of the amplitude.
// Second test: convergence in diffusive scaling (tau fixed, lattice speed ~ 1/N, so dt ~ dx^2):
// the LBM velocity error is second order in dx (Junk, Klar & Luo 2005, J. Comput. Phys.
// 210:676), i.e. it falls by 4 per doubling of the resolution; asserted > 3.5 per doubling from
// 16 to 128 nodes, for BGK and TRT in double precision.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/support/LbmScenes.h"
#include "solvers/lbm/LbmSolver.h"
#include "solvers/lbm/LbmSolverD2Q9.h"
#include "solvers/lbm/validation/TaylorGreenVortex.h"

namespace fluidviz::lbm {
namespace {

TEST(TaylorGreen, DecayRateMatchesTheViscosity) {
  const int n = 64;
  const double nu = 1e-3;
  LbmSolverD2Q9 solver(test::periodicBox(n, 0.8, nu));
  const LatticeUnits& lu = solver.units();
  const double k = 2 * M_PI, u0 = lu.toPhysicalVelocity(0.04);  // one period across the box
  std::vector<double> rho(n * n, lu.density);
  std::vector<Vec3> vel(n * n);
  const Grid& g = solver.grid();
  const TaylorGreenVortex vortex{k, k, u0, nu};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) vel[g.index(i, j)] = vortex.velocity(g.position(i, j), 0.0);
  // Pressure of the vortex, p = rho U0^2 / 4 (cos 2kx + cos 2ky), as lattice density
  // rho = rho0 (1 + p / (rho0 cs^2)): without it the start launches sound waves.
  const double u0Lattice = 0.04;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3 x = g.position(i, j);
      rho[g.index(i, j)] =
          lu.density * (1.0 + 0.75 * u0Lattice * u0Lattice *
                                  (std::cos(2 * k * x.x()) + std::cos(2 * k * x.y())));
    }
  solver.initialise(rho, vel);
  const double tEnd = 1.0 / (2 * nu * k * k);
  solver.step(static_cast<int>(std::lround(tEnd / lu.dt)));
  const FieldSet f = solver.fields();
  const double l2 = vortex.relativeL2Error(*f.findVector("velocity"), solver.time());
  std::printf("Taylor-Green, 64^2, tau 0.8, t = %.3f s: relative L2 error %.2e (tolerance 2e-3)\n",
              solver.time(), l2);
  EXPECT_LT(l2, 2e-3);
}

// Relative L2 velocity error at t = 1 / (2 nu k^2) of the vortex started exactly (with its
// pressure) on n x n nodes; tau = 0.8, lattice amplitude U0 = 0.08 * 16 / n.
double taylorGreenError(int n, const std::string& collision, const std::string& precision) {
  const double nu = 1e-3, k = 2 * M_PI;
  LbmParams p = test::periodicBox(n, 0.8, nu);
  p.collision = fluidviz::choiceNamed<fluidviz::lbm::Collision>(collision);
  p.precision = fluidviz::choiceNamed<fluidviz::lbm::Precision>(precision);
  p.initial_flow = fluidviz::lbm::InitialFlow::taylor_green;
  const double dx = 1.0 / n, dt = *p.time_step;
  p.initial_speed = 0.08 * 16.0 / n * dx / dt;  // m/s; the same for every n (dx/dt ~ n)
  // The initial flow counts as moving: dt then follows from lattice_velocity.
  p.time_step.reset();
  p.lattice_velocity = 0.08 * 16.0 / n;
  auto solver = createLbmSolver(p);
  EXPECT_NEAR(solver->units().tau, 0.8, 1e-12);
  const double tEnd = 1.0 / (2 * nu * k * k);
  solver->step(static_cast<int>(std::lround(tEnd / solver->units().dt)));
  const FieldSet f = solver->fields();
  return TaylorGreenVortex{k, k, p.initial_speed, nu}.relativeL2Error(*f.findVector("velocity"),
                                                                     solver->time());
}

TEST(TaylorGreen, DiffusiveScalingConvergesSecondOrder) {
  for (const char* collision : {"bgk", "trt"}) {
    double previous = 0;
    for (int n : {16, 32, 64, 128}) {
      const double e = taylorGreenError(n, collision, "double");
      std::printf("Taylor-Green %s double, %3d^2, tau 0.8: relative L2 error %.3e", collision, n, e);
      if (previous > 0) {
        std::printf(", ratio %.2f (tolerance > 3.5)", previous / e);
        EXPECT_GT(previous / e, 3.5) << collision << " " << n;
      }
      std::printf("\n");
      previous = e;
    }
  }
}

}  // namespace
}  // namespace fluidviz::lbm
