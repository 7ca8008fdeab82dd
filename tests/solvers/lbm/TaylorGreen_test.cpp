// Decaying Taylor-Green vortex in a periodic box (Taylor & Green 1937):
//   u = U0 sin(k x) cos(k y) e^{-2 nu k^2 t},  v = -U0 cos(k x) sin(k y) e^{-2 nu k^2 t}
//   p = rho U0^2 / 4 (cos 2kx + cos 2ky) e^{-4 nu k^2 t}
// checks that the physical viscosity the user asked for is the one the lattice produces
// (tau = 3 nu dt / dx^2 + 1/2) and that initialise() starts from the given fields.
// Resolution 64 x 64, tau = 0.8, U0 = 0.04 lattice, run to one e-folding of the amplitude.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "LbmTestScenes.h"
#include "solvers/lbm/LbmSolverD2Q9.h"

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
  auto exactField = [&](double t, std::vector<Vec3>& out) {
    const double decay = std::exp(-2 * nu * k * k * t);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 x = g.position(i, j);
        out[g.index(i, j)] = u0 * decay *
                             Vec3(std::sin(k * x.x()) * std::cos(k * x.y()),
                                  -std::cos(k * x.x()) * std::sin(k * x.y()), 0.0);
      }
  };
  exactField(0.0, vel);
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
  exactField(solver.time(), vel);
  const FieldSet f = solver.fields();
  const auto& u = f.findVector("velocity")->values;
  double err2 = 0, ref2 = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    err2 += (u[i] - vel[i]).squaredNorm();
    ref2 += vel[i].squaredNorm();
  }
  const double l2 = std::sqrt(err2 / ref2);
  std::printf("Taylor-Green, 64^2, tau 0.8, t = %.3f s: relative L2 error %.2e (tolerance 2e-3)\n",
              solver.time(), l2);
  EXPECT_LT(l2, 2e-3);
}

}  // namespace
}  // namespace fluidviz::lbm
