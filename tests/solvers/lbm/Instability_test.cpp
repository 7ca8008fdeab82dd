// checkStability / advance report a run that leaves the valid range with InstabilityError:
// where (step, node position), and why (NaN, negative density, lattice speed past 0.5).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "tests/support/LbmScenes.h"
#include "solvers/lbm/LbmSolverD2Q9.h"

namespace fluidviz::lbm {
namespace {

TEST(Instability, HugeBodyForceExceedsTheLatticeSpeedLimit) {
  // Periodic 32^2 box accelerated by g_lb = 2e-3 per step: u = g t reaches 0.5 after 250 steps.
  LbmParams p = test::periodicBox(32, 0.8);
  const double dx = 1.0 / 32, dt = *p.time_step;
  p.body_force = {2e-3 * dx / (dt * dt), 0.0};
  p.check_interval = 100;
  LbmSolverD2Q9 solver(p);
  try {
    solver.advance(1000 * dt);
    FAIL() << "no InstabilityError";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.reason(), "lattice speed past limit");
    EXPECT_EQ(e.step(), 300);  // first check after u passes 0.5
    EXPECT_GT(e.x(), 0.0);
    EXPECT_LT(e.x(), 1.0);
    const std::string m = e.what();
    EXPECT_NE(m.find("step 300"), std::string::npos) << m;
    EXPECT_NE(m.find("lbm.body_force"), std::string::npos) << m;
  }
}

TEST(Instability, StableRunPassesTheCheck) {
  LbmParams p = test::periodicBox(32, 0.8);
  LbmSolverD2Q9 solver(p);
  solver.step(100);
  EXPECT_NO_THROW(solver.checkStability());
}

// A state with one bad node at (i, j) = (5, 7), set through initialise().
InstabilityError errorForBadNode(double density, double velocity) {
  LbmSolverD2Q9 solver(test::periodicBox(16, 0.8));
  const std::size_t nodes = 16 * 16, bad = 7 * 16 + 5;
  std::vector<double> rho(nodes, 1000.0);
  std::vector<Vec3> u(nodes, Vec3::Zero());
  rho[bad] = density;
  u[bad] = Vec3(velocity, 0.0, 0.0);
  solver.initialise(rho, u);
  try {
    solver.checkStability();
  } catch (const InstabilityError& e) {
    return e;
  }
  ADD_FAILURE() << "no InstabilityError";
  return InstabilityError(0, 0, 0, "", "");
}

TEST(Instability, NaNIsReportedWithItsPosition) {
  const InstabilityError e = errorForBadNode(1000.0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(e.reason(), "NaN");
  EXPECT_NEAR(e.x(), 5.5 / 16, 1e-12);
  EXPECT_NEAR(e.y(), 7.5 / 16, 1e-12);
}

TEST(Instability, NegativeDensityIsReported) {
  const InstabilityError e = errorForBadNode(-10.0, 0.0);
  EXPECT_EQ(e.reason(), "negative density");
  EXPECT_NE(std::string(e.what()).find("lattice density -0.01"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace fluidviz::lbm
