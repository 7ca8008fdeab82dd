// Solver bookkeeping: initialise() and fields() are inverse to each other (also across walls,
// moving lids, rollers and a body force), the field grid is node-centred with the walls on the
// box edges, and advance() stops where LbmParams says.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/LbmScenes.h"
#include "solvers/lbm/LbmSolverD2Q9.h"

namespace fluidviz::lbm {
namespace {

LbmParams cavityWithRollerAndForce() {
  LbmParams p = test::lidDrivenCavity(48, 100, 0.1);
  p.domain_size = {1.0, 0.75};  // 48 x 36 nodes
  p.rollers.push_back({{0.6, 0.35}, 0.15, 3.0});
  p.body_force = {0.0, -0.5};
  return p;
}

TEST(SolverState, FieldsReturnWhatInitialiseWasGiven) {
  LbmSolverD2Q9 solver(cavityWithRollerAndForce());
  const Grid& g = solver.grid();
  std::vector<double> rho(g.nodeCount());
  std::vector<Vec3> vel(g.nodeCount());
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      const Vec3 x = g.position(i, j);
      rho[g.index(i, j)] = 1000.0 * (1.0 + 0.01 * std::sin(7 * x.x() + 3 * x.y()));
      vel[g.index(i, j)] = Vec3(0.3 * std::cos(5 * x.y()), -0.2 * std::sin(4 * x.x()), 0.0);
    }
  solver.initialise(rho, vel);
  const FieldSet f = solver.fields();
  const auto& rhoOut = f.findScalar("density")->values;
  const auto& velOut = f.findVector("velocity")->values;
  const auto& speed = f.findScalar("speed")->values;
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      const std::size_t n = g.index(i, j);
      if (solver.isSolid(i, j)) {
        EXPECT_EQ(rhoOut[n], 1000.0);  // reference density
        const Vec3 x = g.position(i, j);
        EXPECT_NEAR(velOut[n].x(), -3.0 * (x.y() - 0.35), 1e-12);  // omega x (x - c)
        EXPECT_NEAR(velOut[n].y(), 3.0 * (x.x() - 0.6), 1e-12);
        continue;
      }
      EXPECT_NEAR(rhoOut[n], rho[n], 1e-10) << i << "," << j;
      EXPECT_NEAR((velOut[n] - vel[n]).norm(), 0.0, 1e-12) << i << "," << j;
      EXPECT_NEAR(speed[n], velOut[n].norm(), 1e-15);
      EXPECT_EQ(velOut[n].z(), 0.0);
    }
}

TEST(SolverState, NodeCentredGridWithWallsOnTheBoxEdges) {
  LbmSolverD2Q9 solver(cavityWithRollerAndForce());
  const Grid& g = solver.fields().grid;
  const double dx = 1.0 / 48;
  EXPECT_EQ(g.dims[0], 48);
  EXPECT_EQ(g.dims[1], 36);
  EXPECT_EQ(g.dims[2], 1);
  EXPECT_NEAR(g.origin[0], dx / 2, 1e-15);
  EXPECT_NEAR(g.origin[1], dx / 2, 1e-15);
  EXPECT_NEAR(g.spacing[0], dx, 1e-15);
  EXPECT_NEAR(g.upperCorner().x() + dx / 2, 1.0, 1e-12);
  EXPECT_NEAR(g.upperCorner().y() + dx / 2, 0.75, 1e-12);
  // Roller nodes are solid: centre (0.6, 0.35) is inside, a node 0.16 away is not.
  EXPECT_TRUE(solver.isSolid(28, 16));   // (0.594, 0.344)
  EXPECT_FALSE(solver.isSolid(36, 16));  // (0.760, 0.344)
  EXPECT_EQ(solver.fluidNodeCount() + [&] {
    int solid = 0;
    for (int j = 0; j < 36; ++j)
      for (int i = 0; i < 48; ++i) solid += solver.isSolid(i, j);
    return solid;
  }(), 48 * 36);
}

TEST(SolverState, AdvanceStopsAtTargetEndTimeAndMaxSteps) {
  LbmParams p = test::lidDrivenCavity(32, 100, 0.1);  // dt = 0.1 / 32 / 1 = 3.125e-3 s
  p.end_time = 1.0;                                    // 320 steps
  p.check_interval = 50;
  LbmSolverD2Q9 solver(p);
  EXPECT_EQ(solver.advance(0.5), StopReason::ReachedTime);
  EXPECT_EQ(solver.stepCount(), 160);
  EXPECT_NEAR(solver.time(), 0.5, 1e-12);
  EXPECT_EQ(solver.advance(5.0), StopReason::EndTime);
  EXPECT_EQ(solver.stepCount(), 320);
  p.max_steps = 100;
  LbmSolverD2Q9 capped(p);
  EXPECT_EQ(capped.run(), StopReason::MaxSteps);
  EXPECT_EQ(capped.stepCount(), 100);
}

}  // namespace
}  // namespace fluidviz::lbm
