#include "solvers/fhp/lattice/NodeLattice.h"

#include <stdexcept>

#include "solvers/fhp/kernel/RandomBits.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {

NodeLattice::NodeLattice(int nx_, int ny_) : nx(nx_), ny(ny_) {
  if (nx < 1 || ny < 2 || ny % 2 != 0)
    throw std::invalid_argument("FHP lattice: need nx >= 1 and an even ny >= 2 (periodic rows)");
  states.assign(static_cast<std::size_t>(nx) * ny, 0);
  solid.assign(states.size(), 0);
  slip.assign(states.size(), 0);
}

namespace {

void collideNode(NodeLattice& l, int x, int y, const CollisionTable& table, const StepRules& rules,
                 std::uint64_t threshold) {
  std::uint8_t& s = l.at(x, y);
  const std::size_t n = static_cast<std::size_t>(y) * l.nx + x;
  if (l.solid[n]) {
    s = l.slip[n] ? specularReflectionY(s) : bounceBack(s);
    return;
  }
  s = table.after[chiralityBit(rules.seed, l.time, x, y)][s];
  if (eventHappens(rules.seed, l.time, x, y, threshold)) s = applyForceFlip(s, rules.forceDirection);
}

}  // namespace

void referenceStep(NodeLattice& l, const CollisionTable& table, const StepRules& rules) {
  const std::uint64_t threshold = probabilityThreshold(rules.forceProbability);
  for (int y = 0; y < l.ny; ++y)
    for (int x = 0; x < l.nx; ++x) collideNode(l, x, y, table, rules, threshold);
  for (const WallNodeMotion& m : l.moving)
    l.at(m.x, m.y) = turnReflectedParticles(l.at(m.x, m.y), m, rules.seed, l.time);

  std::vector<std::uint8_t> next(l.states.size(), 0);
  for (int y = 0; y < l.ny; ++y) {
    for (int x = 0; x < l.nx; ++x) {
      const std::uint8_t s = l.at(x, y);
      next[static_cast<std::size_t>(y) * l.nx + x] |= s & (1u << kRestChannel);  // rest stays
      for (int i = 0; i < kMovingChannels; ++i) {
        if (!(s & (1u << i))) continue;
        const int tx = (x + neighbourDx(i, y % 2 == 1) + l.nx) % l.nx;
        const int ty = (y + kDy[i] + l.ny) % l.ny;
        next[static_cast<std::size_t>(ty) * l.nx + tx] |= static_cast<std::uint8_t>(1u << i);
      }
    }
  }
  l.states.swap(next);
  ++l.time;
}

}  // namespace fluidviz::fhp
