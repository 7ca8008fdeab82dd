// Exhaustive checks of the FHP collision tables (Frisch et al. 1987, Complex Systems 1:649,
// section 2): for every state (64 for FHP-I, 128 for FHP-II/III) and both chiralities the
// collision conserves particle number and momentum exactly (integer momentum basis) and the
// table is a bijection (a permutation of the states, so the automaton is reversible and the
// equilibria are Fermi-Dirac); and each model makes exactly the collisions it is defined by.
#include <gtest/gtest.h>

#include <set>

#include "solvers/fhp/collision/CollisionTable.h"

namespace fluidviz::fhp {
namespace {

constexpr std::uint8_t bits(std::initializer_list<int> channels) {
  unsigned s = 0;
  for (int c : channels) s |= 1u << c;
  return static_cast<std::uint8_t>(s);
}

class CollisionTableTest : public ::testing::TestWithParam<Model> {};

TEST_P(CollisionTableTest, ConservesNumberAndMomentumAndIsABijection) {
  const Model model = GetParam();
  const CollisionTable table = buildCollisionTable(model);
  const int states = model == Model::fhp1 ? 64 : 128;
  for (int chirality = 0; chirality < 2; ++chirality) {
    std::set<int> images;
    for (int s = 0; s < states; ++s) {
      const auto in = static_cast<std::uint8_t>(s);
      const std::uint8_t out = table.after[chirality][s];
      EXPECT_LT(out, states) << "state " << s;
      EXPECT_EQ(particleCount(out), particleCount(in)) << "state " << s;
      EXPECT_EQ(momentumX2(out), momentumX2(in)) << "state " << s;
      EXPECT_EQ(momentumYInt(out), momentumYInt(in)) << "state " << s;
      images.insert(out);
    }
    EXPECT_EQ(static_cast<int>(images.size()), states) << "chirality " << chirality;
  }
}

INSTANTIATE_TEST_SUITE_P(AllModels, CollisionTableTest,
                         ::testing::Values(Model::fhp1, Model::fhp2, Model::fhp3));

int changedStates(const CollisionTable& t, int chirality) {
  int n = 0;
  for (int s = 0; s < 128; ++s) n += t.after[chirality][s] != s;
  return n;
}

TEST(CollisionTable, FhpIRotatesHeadOnPairsBothWaysAndSwapsTriples) {
  const CollisionTable t = buildCollisionTable(Model::fhp1);
  for (int i = 0; i < 3; ++i) {
    const auto pair = bits({i, i + 3});
    const auto plus60 = bits({(i + 1) % 6, (i + 4) % 6}), minus60 = bits({(i + 5) % 6, (i + 2) % 6});
    EXPECT_EQ(t.after[0][pair], plus60);
    EXPECT_EQ(t.after[1][pair], minus60);
  }
  EXPECT_EQ(t.after[0][bits({0, 2, 4})], bits({1, 3, 5}));
  EXPECT_EQ(t.after[1][bits({1, 3, 5})], bits({0, 2, 4}));
  // 3 pairs + 2 triples, nothing else (Frisch et al. 1987, FHP-I)
  EXPECT_EQ(changedStates(t, 0), 5);
  EXPECT_EQ(changedStates(t, 1), 5);
}

TEST(CollisionTable, FhpIIAddsRestParticleCollisionsAndSpectators) {
  const CollisionTable t = buildCollisionTable(Model::fhp2);
  for (int i = 0; i < 6; ++i) {  // c_i + rest <-> c_{i-1} + c_{i+1}
    const auto withRest = bits({i, 6}), pair = bits({(i + 5) % 6, (i + 1) % 6});
    EXPECT_EQ(t.after[0][withRest], pair) << i;
    EXPECT_EQ(t.after[1][pair], withRest) << i;
  }
  EXPECT_EQ(t.after[0][bits({0, 3, 6})], bits({1, 4, 6}));  // head-on pair, rest as spectator
  // 3 pairs and 2 triples, each with and without rest; 6 + 6 rest-particle states
  EXPECT_EQ(changedStates(t, 0), 22);
}

// Collision saturation: a state is changed exactly when another state has its number and momentum.
TEST(CollisionTable, FhpIIIChangesEveryStateThatSharesNumberAndMomentum) {
  const CollisionTable t = buildCollisionTable(Model::fhp3);
  for (int s = 0; s < 128; ++s) {
    const auto in = static_cast<std::uint8_t>(s);
    bool hasPartner = false;
    for (int o = 0; o < 128; ++o) {
      const auto other = static_cast<std::uint8_t>(o);
      hasPartner |= o != s && particleCount(other) == particleCount(in) &&
                    momentumX2(other) == momentumX2(in) && momentumYInt(other) == momentumYInt(in);
    }
    EXPECT_EQ(t.after[0][s] != s, hasPartner) << "state " << s;
    EXPECT_EQ(t.after[1][s] != s, hasPartner) << "state " << s;
  }
}

TEST(CollisionTable, BounceBackReversesMomentumAndKeepsRestParticle) {
  for (int s = 0; s < 128; ++s) {
    const auto in = static_cast<std::uint8_t>(s);
    EXPECT_EQ(momentumX2(bounceBack(in)), -momentumX2(in));
    EXPECT_EQ(momentumYInt(bounceBack(in)), -momentumYInt(in));
    EXPECT_EQ(particleCount(bounceBack(in)), particleCount(in));
    EXPECT_EQ(bounceBack(in) & 0x40, in & 0x40);
  }
}

}  // namespace
}  // namespace fluidviz::fhp
