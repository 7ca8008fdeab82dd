// Determinism of the SPH solver (issue 8): the same parameters and thread count give bit-identical
// particles, and so do 1 and 2 threads (tolerance 0): every particle sums over its own neighbour
// list, whose order follows the cell order of the search whatever the thread partition, and no
// loop reduces across particles with threads. 10000 fluid particles (over kParallelMinItems =
// 8192, so the loops do run on 2 threads), model B with two rollers (moving boundary particles,
// XSPH, density diffusion, Adami wall pressure). saveState/restoreState continue bit-identically,
// also across thread counts, and refuse a state of another layout.
#include <omp.h>

#include <gtest/gtest.h>

#include "solvers/sph/SphSolver.h"

namespace fluidviz::sph {
namespace {

SphParams rollerBox(double dx) {
  SphParams p;
  p.dimension = 2;
  p.model = fluidviz::sph::SphModel::weakly_compressible;
  p.kernel = fluidviz::sph::SphKernel::wendland_c2;
  p.particle_spacing = dx;
  p.smoothing_length_ratio = 1.5;
  p.speed_of_sound = 1.5;
  p.viscosity = 0.01;
  p.gravity = {0, -1, 0};
  p.domain_lower = {0, 0, 0};
  p.domain_upper = {1, 1, 0};
  p.initial_pressure = fluidviz::sph::InitialPressure::zero;
  p.fluid_blocks = {{{0, 0, 0}, {1, 1, 0}}};
  SphRollerParams a, b;
  a.center = {0.3, 0.5};
  b.center = {0.7, 0.5};
  a.radius = b.radius = 0.1;
  a.angular_velocity = 2;
  b.angular_velocity = -2;
  p.rollers = {a, b};
  p.end_time = 100;
  return p;
}

// Positions, velocities and densities after `steps` steps on `threads` threads.
std::vector<double> particlesAfter(SphSolver& s, int steps, int threads) {
  omp_set_num_threads(threads);
  for (int k = 0; k < steps; ++k) s.step();
  std::vector<double> values;
  for (std::size_t i = 0; i < s.fluidCount(); ++i) {
    const FluidState& f = s.state();
    values.insert(values.end(), {f.x[i][0], f.x[i][1], f.v[i][0], f.v[i][1], f.rho[i]});
  }
  return values;
}

class SphDeterminism : public ::testing::Test {
 protected:
  void TearDown() override { omp_set_num_threads(omp_get_num_procs()); }
};

TEST_F(SphDeterminism, OneAndTwoThreadsAndRepeatsGiveBitIdenticalParticles) {
  const SphParams p = rollerBox(0.0095);
  SphSolver a(p), b(p), c(p);
  ASSERT_GT(a.fluidCount(), 8192u) << "large enough for the parallel loops";
  const std::vector<double> twoA = particlesAfter(a, 6, 2);
  const std::vector<double> twoB = particlesAfter(b, 6, 2);
  const std::vector<double> one = particlesAfter(c, 6, 1);
  EXPECT_TRUE(twoA == twoB) << "same thread count";
  double diff = 0;
  for (std::size_t n = 0; n < one.size(); ++n) diff = std::max(diff, std::abs(one[n] - twoA[n]));
  EXPECT_EQ(diff, 0.0) << "1 vs 2 threads";
  EXPECT_EQ(a.time(), c.time());
}

TEST_F(SphDeterminism, RestoredStateContinuesBitIdentically) {
  const SphParams p = rollerBox(0.0095);
  SphSolver first(p);
  particlesAfter(first, 3, 2);
  StateWriter saved;
  first.saveState(saved);
  const std::vector<double> continued = particlesAfter(first, 6, 2);

  SphSolver second(p);
  StateReader reader(saved.bytes());
  second.restoreState(reader);
  EXPECT_EQ(reader.remaining(), 0u);
  EXPECT_EQ(second.stepCount(), 3);
  EXPECT_TRUE(particlesAfter(second, 6, 1) == continued);
  EXPECT_EQ(second.time(), first.time());
  EXPECT_TRUE(second.boundary().positions == first.boundary().positions) << "rollers turned";
}

TEST_F(SphDeterminism, RestoreRefusesAnotherLayout) {
  StateWriter saved;
  SphSolver(rollerBox(0.05)).saveState(saved);
  SphParams other = rollerBox(0.05);
  other.rollers.pop_back();
  StateReader reader(saved.bytes());
  SphSolver fewerWalls(other);
  EXPECT_THROW(fewerWalls.restoreState(reader), StateFormatError);
  StateReader truncated(std::vector<std::uint8_t>(saved.bytes().begin(),
                                                  saved.bytes().begin() + 200));
  SphSolver same(rollerBox(0.05));
  try {
    same.restoreState(truncated);
    FAIL() << "restored a truncated state";
  } catch (const StateFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds the"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidviz::sph
