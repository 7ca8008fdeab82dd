// Rigid rollers made of boundary particles (SPH N-roll mills):
//   - kinematics: after time t every roller particle sits at its start position turned by
//     omega t about the axis (to 1e-12 m) and moves with omega x r; in 3D the cylinder spans
//     the domain along z and z never changes;
//   - no-slip: a roller (R = 0.1 m, omega = 1 rad/s) centred in a closed 0.6 m box of viscous
//     fluid (nu = 0.01 m^2/s, Re = omega R^2 / nu = 1; dx = 0.01 m, 3300 particles), after
//     1 s (= R^2 / nu, the spin-up time): the fluid in the first layer (r < R + dx) turns with
//     the roller. In an unbounded fluid the steady Stokes solution is v = omega R^2 / r, i.e.
//     0.95 omega R at r = R + dx/2; the box walls (at 2R .. 4R) slow it. Accepted: mean
//     tangential speed in [0.75, 1.0] omega R (measured 0.82), radial speed < 5% of omega R.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/support/SphScenes.h"

namespace fluidviz::sph {
namespace {

SphParams rollerBox(int dim) {
  SphParams p;
  p.dimension = dim;
  p.particle_spacing = 0.01;
  p.domain_lower = {0, 0, 0};
  p.domain_upper = {0.6, 0.6, dim == 3 ? 0.08 : 0.0};
  if (dim == 3) p.walls.z_min = p.walls.z_max = fluidviz::sph::SphSide::periodic;
  p.fluid_blocks = {{{0, 0, 0}, {0.6, 0.6, dim == 3 ? 0.08 : 0.0}}};
  p.rollers = {{{0.3, 0.3}, 0.1, 1.0}};
  p.gravity = {0, 0, 0};
  p.viscosity = 0.01;
  p.speed_of_sound = 1.0;  // 10 omega R
  p.end_time = 10;
  return p;
}

void expectRigidRotation(const SphSolver& s, double t) {
  const BoundaryParticles& b = s.boundaryParticles();
  const double omega = 1.0, c = std::cos(omega * t), sn = std::sin(omega * t);
  int rollerParticles = 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (b.surfaces[b.surface[k]].kind != BoundarySurface::Kind::Roller) continue;
    ++rollerParticles;
    const Vec3 r0 = b.restPositions[k] - Vec3(0.3, 0.3, 0.0);
    const Vec3 expected(0.3 + c * r0[0] - sn * r0[1], 0.3 + sn * r0[0] + c * r0[1],
                        b.restPositions[k][2]);
    EXPECT_LT((b.positions[k] - expected).norm(), 1e-12);
    const Vec3 r = b.positions[k] - Vec3(0.3, 0.3, b.positions[k][2]);
    EXPECT_LT((b.velocities[k] - Vec3(-omega * r[1], omega * r[0], 0.0)).norm(), 1e-12);
  }
  EXPECT_GT(rollerParticles, 100);
}

TEST(Roller, TurnsRigidlyAndDragsTheFluidAlong2D) {
  SphSolver s(rollerBox(2));
  s.advance(1.0);
  expectRigidRotation(s, s.time());
  double tangential = 0.0, radial = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < s.fluidCount(); ++i) {
    const Vec3 r = s.state().x[i] - Vec3(0.3, 0.3, 0.0);
    if (r.norm() > 0.1 + 0.01) continue;
    const Vec3 e = r / r.norm(), t(-e[1], e[0], 0.0);
    tangential += s.state().v[i].dot(t);
    radial = std::max(radial, std::abs(s.state().v[i].dot(e)));
    ++n;
  }
  ASSERT_GT(n, 30);
  const double omegaR = 0.1;
  EXPECT_GT(tangential / n, 0.75 * omegaR);
  EXPECT_LT(tangential / n, 1.0 * omegaR);
  EXPECT_LT(radial, 0.05 * omegaR);
  std::printf("[measured] first layer (%d particles): mean v_t = %.3f omega R, max |v_r| = %.3f "
              "omega R\n", n, tangential / n / omegaR, radial / omegaR);
}

TEST(Roller, SpansTheDomainAlongZ3D) {
  SphSolver s(rollerBox(3));
  s.step();
  s.step();
  expectRigidRotation(s, s.time());
  double zMin = 1, zMax = -1;
  for (std::size_t k = 0; k < s.boundaryParticles().size(); ++k) {
    zMin = std::min(zMin, s.boundaryParticles().positions[k][2]);
    zMax = std::max(zMax, s.boundaryParticles().positions[k][2]);
  }
  EXPECT_NEAR(zMin, 0.005, 1e-12);
  EXPECT_NEAR(zMax, 0.075, 1e-12);
}

}  // namespace
}  // namespace fluidviz::sph
