// Determinism of the LBM solver (issue 8): the same parameters and thread count give bit-identical
// fields, and 1 and 2 threads give bit-identical fields too (tolerance 0): every node's update
// reads only the previous step's populations, and the kernel has no reduction or atomic, so the
// row partition cannot change any sum. The lattice is large enough (384^2 = 147456 nodes, over
// 2 x 65536) for the solver to use 2 threads; TRT with two Bouzidi rollers (interpolated walls)
// and a moving lid exercises every boundary rule of the kernel. saveState/restoreState continue
// bit-identically, also across thread counts.
#include <omp.h>

#include <cstring>

#include <gtest/gtest.h>

#include "solvers/lbm/LbmSolver.h"
#include "tests/support/LbmScenes.h"

namespace fluidviz::lbm {
namespace {

LbmParams twoRollerCavity() {
  LbmParams p = test::lidDrivenCavity(384, 100, 0.1);
  p.collision = fluidviz::lbm::Collision::trt;
  RollerParams a, b;
  a.center = {0.3, 0.4};
  b.center = {0.7, 0.4};
  a.radius = b.radius = 0.12;
  a.angular_velocity = 2.0;
  b.angular_velocity = -2.0;
  a.boundary = b.boundary = fluidviz::lbm::RollerBoundary::interpolated;
  p.rollers = {a, b};
  return p;
}

// Density and velocity of every node after `steps` steps on `threads` threads.
std::vector<double> fieldsAfter(const LbmParams& p, int steps, int threads) {
  omp_set_num_threads(threads);
  auto solver = createLbmSolver(p);
  solver->step(steps);
  const FieldSet f = solver->fields();
  std::vector<double> values = f.findScalar("density")->values;
  for (const Vec3& u : f.findVector("velocity")->values) values.insert(values.end(), {u[0], u[1]});
  return values;
}

bool bitIdentical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Largest |a - b| relative to the largest |b|.
double relativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0, scale = 0;
  for (std::size_t n = 0; n < a.size(); ++n) {
    diff = std::max(diff, std::abs(a[n] - b[n]));
    scale = std::max(scale, std::abs(b[n]));
  }
  return diff / scale;
}

class LbmDeterminism : public ::testing::Test {
 protected:
  void TearDown() override { omp_set_num_threads(omp_get_num_procs()); }
};

TEST_F(LbmDeterminism, SameThreadCountGivesBitIdenticalFields) {
  const LbmParams p = twoRollerCavity();
  EXPECT_TRUE(bitIdentical(fieldsAfter(p, 60, 2), fieldsAfter(p, 60, 2)));
}

TEST_F(LbmDeterminism, OneAndTwoThreadsGiveBitIdenticalFields) {
  const LbmParams p = twoRollerCavity();
  const std::vector<double> one = fieldsAfter(p, 60, 1), two = fieldsAfter(p, 60, 2);
  EXPECT_EQ(relativeDifference(two, one), 0.0);
  EXPECT_TRUE(bitIdentical(one, two));
}

TEST_F(LbmDeterminism, RestoredStateContinuesBitIdentically) {
  // Saved after 30 steps on 2 threads, restored into a new solver on 1 thread, 30 more steps.
  const LbmParams p = twoRollerCavity();
  omp_set_num_threads(2);
  auto first = createLbmSolver(p);
  first->step(30);
  first->maxVelocityChange();  // the steady-state reference is state too
  StateWriter saved;
  first->saveState(saved);
  first->step(30);
  const double changeFirst = first->maxVelocityChange();

  omp_set_num_threads(1);
  auto second = createLbmSolver(p);
  StateReader reader(saved.bytes());
  second->restoreState(reader);
  EXPECT_EQ(reader.remaining(), 0u);
  EXPECT_EQ(second->stepCount(), 30);
  second->step(30);
  EXPECT_EQ(second->maxVelocityChange(), changeFirst);
  const FieldSet a = first->fields(), b = second->fields();
  EXPECT_EQ(a.findScalar("density")->values, b.findScalar("density")->values);
  EXPECT_TRUE(a.findVector("velocity")->values == b.findVector("velocity")->values);
}

TEST_F(LbmDeterminism, RestoreRefusesAnotherLattice) {
  LbmParams small = test::lidDrivenCavity(32, 100, 0.1), other = small;
  other.resolution = 40;
  StateWriter saved;
  createLbmSolver(small)->saveState(saved);
  StateReader reader(saved.bytes());
  try {
    createLbmSolver(other)->restoreState(reader);
    FAIL() << "restored a 32^2 state into a 40^2 lattice";
  } catch (const StateFormatError& e) {
    EXPECT_STREQ(e.what(), "nx is 32 in the saved state but 40 here");
  }
  other = small;
  other.precision = fluidviz::lbm::Precision::float32;
  StateReader again(saved.bytes());
  try {
    createLbmSolver(other)->restoreState(again);
    FAIL() << "restored a double state into a float solver";
  } catch (const StateFormatError& e) {
    EXPECT_STREQ(e.what(), "the population size (bytes) is 8 in the saved state but 4 here");
  }
}

}  // namespace
}  // namespace fluidviz::lbm
