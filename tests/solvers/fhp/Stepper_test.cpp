// The multi-spin stepper (BitLattice) against the readable reference (NodeLattice), bit for bit
// with the same random bits, for the three models with solids and body force; the propagation
// geometry of the triangular lattice; exact conservation of the particle number with walls and
// obstacles and of the momentum on a periodic lattice without solids or force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "solvers/fhp/lattice/BitLattice.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {
namespace {

NodeLattice randomLattice(int nx, int ny, int states, unsigned seed, bool solids) {
  NodeLattice n(nx, ny);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> state(0, states - 1), percent(0, 99);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      n.at(x, y) = static_cast<std::uint8_t>(state(rng));
      if (solids && (y == 0 || percent(rng) < 5)) n.solid[static_cast<std::size_t>(y) * nx + x] = 1;
    }
  return n;
}

class StepperTest : public ::testing::TestWithParam<Model> {};

TEST_P(StepperTest, MultiSpinStepperEqualsReferenceBitForBit) {
  const Model model = GetParam();
  const CollisionTable table = buildCollisionTable(model);
  const StepRules rules{.model = model, .seed = 77, .forceProbability = 0.1, .forceDirection = 1};
  NodeLattice reference = randomLattice(128, 14, model == Model::fhp1 ? 64 : 128, 5, true);
  BitLattice fast = BitLattice::fromNodes(reference);
  for (int t = 0; t < 25; ++t) {
    referenceStep(reference, table, rules);
    fast.step(table, rules);
  }
  const NodeLattice got = fast.toNodes();
  ASSERT_EQ(got.time, reference.time);
  int differing = 0;
  for (std::size_t k = 0; k < got.states.size(); ++k) differing += got.states[k] != reference.states[k];
  EXPECT_EQ(differing, 0);
}

TEST_P(StepperTest, ParticleNumberIsConservedExactlyWithWallsAndObstacles) {
  const Model model = GetParam();
  const CollisionTable table = buildCollisionTable(model);
  BitLattice lattice = BitLattice::fromNodes(randomLattice(192, 20, model == Model::fhp1 ? 64 : 128, 9, true));
  const std::uint64_t before = lattice.particleCount();
  for (int t = 0; t < 300; ++t) lattice.step(table, {.model = model, .seed = 3});
  EXPECT_EQ(lattice.particleCount(), before);
}

INSTANTIATE_TEST_SUITE_P(AllModels, StepperTest,
                         ::testing::Values(Model::fhp1, Model::fhp2, Model::fhp3));

TEST(Stepper, MomentumIsConservedExactlyOnAPeriodicLattice) {
  for (Model model : {Model::fhp1, Model::fhp2, Model::fhp3}) {
    const CollisionTable table = buildCollisionTable(model);
    BitLattice lattice = BitLattice::fromNodes(randomLattice(128, 16, model == Model::fhp1 ? 64 : 128, 11, false));
    auto momentum = [&] {
      long px = 0, py = 0;
      for (int y = 0; y < lattice.ny(); ++y)
        for (int x = 0; x < lattice.nx(); ++x) {
          px += momentumX2(lattice.node(x, y));
          py += momentumYInt(lattice.node(x, y));
        }
      return std::pair{px, py};
    };
    const auto before = momentum();
    for (int t = 0; t < 100; ++t) lattice.step(table, {.model = model, .seed = 4});
    EXPECT_EQ(momentum(), before);
  }
}

// A lone particle never collides; after two steps it has moved by exactly 2 c_i in the plane,
// whatever the parity of its starting row (the even/odd row offsets).
TEST(Stepper, LoneParticleMovesAlongItsLink) {
  const CollisionTable table = buildCollisionTable(Model::fhp3);
  for (int startRow : {4, 5})
    for (int i = 0; i < kMovingChannels; ++i) {
      BitLattice lattice(64, 12);
      lattice.setNode(20, startRow, static_cast<std::uint8_t>(1u << i));
      lattice.step(table, {.model = Model::fhp3});
      lattice.step(table, {.model = Model::fhp3});
      int found = 0;
      for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 64; ++x)
          if (lattice.node(x, y)) {
            ++found;
            EXPECT_EQ(lattice.node(x, y), 1u << i);
            const double px0 = 20 + 0.5 * (startRow % 2), py0 = startRow * kRowSpacing;
            EXPECT_NEAR(x + 0.5 * (y % 2) - px0, 2 * kCx[i], 1e-12) << i;
            EXPECT_NEAR(y * kRowSpacing - py0, 2 * kCy[i], 1e-12) << i;
          }
      EXPECT_EQ(found, 1);
    }
}

TEST(Stepper, RejectsLatticeSizesTheWordLayoutCannotHold) {
  EXPECT_THROW(BitLattice(100, 10), std::invalid_argument);
  EXPECT_THROW(BitLattice(128, 11), std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz::fhp
