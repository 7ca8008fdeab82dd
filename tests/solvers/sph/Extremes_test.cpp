// Bad settings end in a correct run or a clear InstabilityError, never in NaN: on the dam break
// of DamBreak_test (a = 0.5 m, a / dx = 20), run to T = t sqrt(2g/a) = 1, for both models:
//   - a fixed time step twice the stable limit: flagged (stableLimitExceeded, one warning naming
//     time_step); here both models still complete, with the front behind Ritter's bound;
//   - an EOS stiffness far too low (c0 = 0.5 sqrt(g a), 1/20 of the usual): InstabilityError
//     "density error" naming speed_of_sound (model B at step 0: the hydrostatic start alone is
//     78% compressed; model A after a few steps);
//   - the bottom fluid row started overlapping the wall (y = 0.1 dx instead of 0.5 dx, 0.6 dx
//     from the first wall layer): a run that pushes it out (model B) or a density-error stop
//     (model A); a particle started inside the wall: InstabilityError "left domain" at step 0;
//     a particle started 0.01 dx from an obstacle's boundary particle: InstabilityError "time
//     step collapsed" before the first step.
// After every outcome the fluid arrays are finite (the last good state is kept).
#include <gtest/gtest.h>

#include <functional>

#include "tests/support/SphScenes.h"

namespace fluidviz::sph {
namespace {

constexpr double kA = 0.5;

SphParams scene(const std::string& model) {
  SphParams p = test::damBreak2D(model, kA, 20);
  if (model == "B") p.alpha = 0.1;
  if (model == "A") p.smoothing_length_ratio = 1.5;
  return p;
}

struct Outcome {
  bool completed = false;
  std::string reason, message;
};

// Runs to T = 1 and checks the invariant of every outcome: finite output arrays.
Outcome runToT1(SphSolver& s) {
  Outcome o;
  try {
    s.advance(1.0 / std::sqrt(2 * test::kGravity / kA));
    o.completed = true;
  } catch (const InstabilityError& e) {
    o.reason = e.reason();
    o.message = e.what();
    EXPECT_GE(e.particle(), 0);
    EXPECT_LT(e.particle(), static_cast<long long>(s.fluidCount()));
  }
  EXPECT_TRUE(std::isfinite(test::largestMagnitude(s.fluid())));
  EXPECT_TRUE(std::isfinite(test::largestMagnitude(s.boundary())));
  return o;
}

double frontZ(const SphSolver& s) {
  double x = 0.0;
  for (const Vec3& p : s.state().x) x = std::max(x, p[0]);
  return (x + 0.5 * s.params().particle_spacing) / kA;
}

class Extremes : public ::testing::TestWithParam<std::string> {};

TEST_P(Extremes, TimeStepTwiceTheStableLimitIsFlagged) {
  SphParams p = scene(GetParam());
  p.time_step = 2.0 * SphSolver(p).timeStepLimits().stable();
  SphSolver s(p);
  const Outcome o = runToT1(s);
  EXPECT_TRUE(s.stableLimitExceeded());
  ASSERT_FALSE(s.warnings().empty());
  EXPECT_NE(s.warnings()[0].find("time_step"), std::string::npos) << s.warnings()[0];
  if (o.completed)
    EXPECT_LT(frontZ(s), 1.0 + 2.0 * 1.0);  // Ritter at T = 1
  else
    EXPECT_FALSE(o.message.empty());
}

TEST_P(Extremes, FarTooSoftEquationOfStateStopsWithDensityError) {
  SphParams p = scene(GetParam());
  p.speed_of_sound = 0.5 * std::sqrt(test::kGravity * kA);
  SphSolver s(p);
  const Outcome o = runToT1(s);
  ASSERT_FALSE(o.completed);
  EXPECT_EQ(o.reason, "density error");
  EXPECT_NE(o.message.find("speed_of_sound"), std::string::npos) << o.message;
}

TEST_P(Extremes, ParticlesOverlappingTheWallRunOrStopClearly) {
  SphParams p = scene(GetParam());
  SphSolver s(p);
  std::vector<Vec3> x = s.state().x;
  for (Vec3& xi : x)
    if (xi[1] < p.particle_spacing) xi[1] = 0.1 * p.particle_spacing;
  s.setFluidParticles(x);
  const Outcome o = runToT1(s);
  if (o.completed) {
    double yMin = 1.0;
    for (const Vec3& xi : s.state().x) yMin = std::min(yMin, xi[1]);
    EXPECT_GT(yMin, 0.0);  // pushed out of the wall, not through it
  } else {
    EXPECT_FALSE(o.message.empty());
  }
}

TEST_P(Extremes, ParticleStartedInsideTheWallStopsAtOnce) {
  SphParams p = scene(GetParam());
  SphSolver s(p);
  std::vector<Vec3> x = s.state().x;
  x[5] = Vec3(0.3, -0.5 * p.particle_spacing, 0.0);  // on a wall particle below y = 0
  s.setFluidParticles(x);
  const Outcome o = runToT1(s);
  ASSERT_FALSE(o.completed);
  EXPECT_EQ(o.reason, "left domain");
  EXPECT_NE(o.message.find("y_min"), std::string::npos) << o.message;
  EXPECT_EQ(s.stepCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(Models, Extremes, ::testing::Values("A", "B"));

}  // namespace
}  // namespace fluidviz::sph

namespace fluidviz::sph {
namespace {

// A fluid particle started almost on top of a boundary particle (0.01 dx from a particle of a
// solid obstacle): the Lennard-Jones force (r0 / r)^12 is ~1e22 times its usual size, the
// automatic step would collapse, and the run stops at once naming the cause.
TEST(ExtremesB, ParticleOnTopOfAnObstacleParticleStopsWithCollapsedStep) {
  SphParams p = test::damBreak2D("B", 0.5, 20);
  p.obstacles = {{{1.5, 0.0, 0.0}, {1.6, 0.2, 0.0}}};
  SphSolver s(p);
  std::vector<Vec3> x = s.state().x;
  const BoundaryParticles& b = s.boundaryParticles();
  std::size_t k = 0;
  while (b.surfaces[b.surface[k]].kind != BoundarySurface::Kind::Box) ++k;
  x[0] = b.positions[k] + Vec3(0.01 * p.particle_spacing, 0.0, 0.0);
  s.setFluidParticles(x);
  try {
    s.step();
    ADD_FAILURE() << "no InstabilityError";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.reason(), "time step collapsed");
    EXPECT_EQ(e.particle(), 0);
    EXPECT_NE(std::string(e.what()).find("overlapping"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::isfinite(test::largestMagnitude(s.fluid())));
}

}  // namespace
}  // namespace fluidviz::sph
