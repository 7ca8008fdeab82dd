// Momentum balance of the momentum-exchange force (LbmSolver::bodyForces): a fully periodic box
// (no walls) with one fixed cylinder, driven by a body acceleration g along x (Guo forcing adds
// exactly rho g per node and step). At steady state the fluid's momentum no longer changes, so
// everything the body force puts in leaves through the cylinder: F_x = rho g A_fluid (per metre of
// depth), with rho A_fluid = total lattice mass * lattice density * dx^2 and F_y = 0 by symmetry.
// 40 x 40 nodes, cylinder radius 0.15 Lx, tau 0.8, lattice speed ~0.01; steady to 1e-10.
// Measured: relative error 6e-11 (staircase), 1e-10 (Bouzidi), |F_y| / F_x 4e-14; asserted 1e-6.
#include <gtest/gtest.h>

#include <cmath>

#include "solvers/lbm/LbmSolver.h"

namespace fluidviz::lbm {
namespace {

void expectMomentumBalance(RollerBoundary boundary) {
  const double length = 1e-3, nu = 1e-6, tau = 0.8;  // m, m^2/s
  const int n = 40;
  const double dx = length / n, dt = (tau - 0.5) / 3.0 * dx * dx / nu;
  const double g = 1e-5 * dx / (dt * dt);  // lattice acceleration 1e-5
  LbmParams p;
  p.domain_size = {length, length};
  p.resolution = n;
  p.viscosity = nu;
  p.time_step = dt;
  p.body_force = {g, 0.0};
  p.walls.x_min.type = p.walls.x_max.type = p.walls.y_min.type = p.walls.y_max.type =
      WallType::periodic;
  p.rollers.push_back({{0.5 * length, 0.5 * length}, 0.15 * length, 0.0});
  p.rollers[0].boundary = boundary;
  p.end_time = 200000 * dt;
  p.max_steps = 200000;
  p.steady_tolerance = 1e-10;
  p.check_interval = 500;
  auto solver = createLbmSolver(p);
  ASSERT_EQ(solver->run(), StopReason::Steady);
  const std::vector<BodyForce> forces = solver->bodyForces();
  ASSERT_EQ(forces.size(), 1u);
  const double expected = solver->totalMass() * solver->units().density * dx * dx * g;  // N/m
  EXPECT_NEAR(forces[0].force.x(), expected, 1e-6 * expected);
  EXPECT_NEAR(forces[0].force.y(), 0.0, 1e-6 * expected);
  EXPECT_EQ(forces[0].force.z(), 0.0);
}

TEST(BodyForce, StaircaseCylinderBalancesBodyForce) {
  expectMomentumBalance(RollerBoundary::staircase);
}

TEST(BodyForce, InterpolatedCylinderBalancesBodyForce) {
  expectMomentumBalance(RollerBoundary::interpolated);
}

}  // namespace
}  // namespace fluidviz::lbm
