#pragma once
// Plain one-byte-per-node lattice gas and its readable reference step: the specification the
// multi-spin stepper (BitLattice) is compared with bit for bit in tests.
#include <cstdint>
#include <vector>

#include "solvers/fhp/kernel/MovingWall.h"
#include "solvers/fhp/kernel/StepRules.h"

namespace fluidviz::fhp {

struct NodeLattice {
  int nx = 0, ny = 0;
  std::vector<std::uint8_t> states;  ///< bit i: particle along c_i (bit 6: rest); x fastest
  std::vector<std::uint8_t> solid;   ///< 1: solid node (bounce-back)
  std::vector<std::uint8_t> slip;    ///< 1 at a solid node: specular reflection instead
  std::uint64_t time = 0;            ///< steps done
  std::vector<WallNodeMotion> moving;  ///< solid nodes of moving walls (MovingWall.h)

  NodeLattice(int nx, int ny);
  std::uint8_t& at(int x, int y) { return states[static_cast<std::size_t>(y) * nx + x]; }
  std::uint8_t at(int x, int y) const { return states[static_cast<std::size_t>(y) * nx + x]; }
};

/// One step: collision at every node (table lookup with the node's chirality bit, then the force
/// flip, at fluid nodes; bounce-back at solid nodes, specular reflection at solid slip nodes; then
/// the biased turns at the moving wall nodes), then propagation
/// n_i(r + c_i, t + 1) = n_i(r, t) with periodic wrap in x and y.
void referenceStep(NodeLattice& lattice, const CollisionTable& table, const StepRules& rules);

}  // namespace fluidviz::fhp
