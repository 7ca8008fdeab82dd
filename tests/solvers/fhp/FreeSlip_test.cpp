// Free-slip walls (specular reflection, Wolf-Gladrow 2000, section 3.2): the multi-spin stepper
// equals the reference with slip rows bit for bit; between slip walls the momentum along the
// walls is conserved exactly (every reflection keeps c_x), while between no-slip walls, which
// reverse it, the same flow loses it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "solvers/fhp/lattice/BitLattice.h"
#include "solvers/fhp/lattice/Initialisation.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {
namespace {

long long totalMomentumX2(const BitLattice& l) {
  long long m = 0;
  for (int y = 0; y < l.ny(); ++y)
    for (int x = 0; x < l.nx(); ++x) {
      const std::uint8_t s = l.node(x, y);
      for (int c = 0; c < kMovingChannels; ++c)
        if (s & (1u << c)) m += kCx2[c];
    }
  return m;
}

// Channel of ny rows between wall rows 0 and ny - 1 (slip or bounce-back), periodic in x,
// filled with a uniform flow of 0.2 links per step along x.
BitLattice channel(Model model, bool slip) {
  BitLattice l(128, 24);
  for (int y : {0, 23})
    for (int x = 0; x < l.nx(); ++x) {
      l.setSolid(x, y, true);
      l.setSlip(x, y, slip);
    }
  fillEquilibrium(l, model, 0.25, [](int, int) { return std::array<double, 2>{0.2, 0.0}; }, 3);
  return l;
}

TEST(FreeSlip, SpecularReflectionSwapsTheVerticalComponentOnly) {
  for (int s = 0; s < 128; ++s) {
    const auto state = static_cast<std::uint8_t>(s), out = specularReflectionY(state);
    EXPECT_EQ(momentumX2(out), momentumX2(state)) << s;
    EXPECT_EQ(momentumYInt(out), -momentumYInt(state)) << s;
    EXPECT_EQ(particleCount(out), particleCount(state)) << s;
    EXPECT_EQ(specularReflectionY(out), state) << s;  // an involution
  }
}

TEST(FreeSlip, MultiSpinStepperEqualsReferenceWithSlipRows) {
  for (Model model : {Model::fhp1, Model::fhp3}) {
    const CollisionTable table = buildCollisionTable(model);
    const StepRules rules{.model = model, .seed = 11, .forceProbability = 0.05, .forceDirection = 0};
    BitLattice fast = channel(model, true);
    fast.setSolid(40, 10, true);  // one bounce-back node inside as well
    NodeLattice reference = fast.toNodes();
    for (int t = 0; t < 30; ++t) {
      fast.step(table, rules);
      referenceStep(reference, table, rules);
    }
    const NodeLattice got = fast.toNodes();
    int differing = 0;
    for (std::size_t k = 0; k < got.states.size(); ++k)
      differing += got.states[k] != reference.states[k];
    EXPECT_EQ(differing, 0) << choiceName(model);
  }
}

TEST(FreeSlip, TangentialMomentumIsConservedExactlyBetweenSlipWalls) {
  for (Model model : {Model::fhp1, Model::fhp2, Model::fhp3}) {
    const CollisionTable table = buildCollisionTable(model);
    const StepRules rules{.model = model, .seed = 5};
    BitLattice slip = channel(model, true), noSlip = channel(model, false);
    const long long start = totalMomentumX2(slip), count = static_cast<long long>(slip.particleCount());
    ASSERT_EQ(totalMomentumX2(noSlip), start);
    ASSERT_GT(start, count / 10);  // a real flow: mean u > 0.05 links per step
    for (int t = 0; t < 100; ++t) {
      slip.step(table, rules);
      noSlip.step(table, rules);
    }
    EXPECT_EQ(totalMomentumX2(slip), start) << choiceName(model);
    EXPECT_EQ(static_cast<long long>(slip.particleCount()), count) << choiceName(model);
    // Bounce-back walls take momentum out: after 100 steps over a tenth of it is gone.
    EXPECT_LT(totalMomentumX2(noSlip), 0.9 * start) << choiceName(model) << ": "
        << totalMomentumX2(noSlip) << " of " << start;
  }
}

}  // namespace
}  // namespace fluidviz::fhp
