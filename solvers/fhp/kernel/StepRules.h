#pragma once
// What one time step of the lattice gas does, shared by the optimised and the reference stepper.
#include <cstdint>

#include "solvers/fhp/collision/CollisionTable.h"

namespace fluidviz::fhp {

struct StepRules {
  Model model = Model::fhp1;
  std::uint64_t seed = 1;
  /// Body force by random momentum flips (Wolf-Gladrow 2000, section 3.2.4): at each fluid node
  /// after collision, with this probability a particle moving along -c_d is turned to +c_d when
  /// that channel is empty, adding momentum 2 c_d. The mean force per node and step is
  /// 2 p d (1 - d) c_d for channel density d.
  double forceProbability = 0.0;
  int forceDirection = 0;  ///< d in 0..5
};

/// The node-level rule both steppers apply after the collision at a fluid node.
inline std::uint8_t applyForceFlip(std::uint8_t state, int direction) {
  const unsigned to = 1u << direction, from = 1u << ((direction + 3) % 6);
  if ((state & from) && !(state & to)) return static_cast<std::uint8_t>((state & ~from) | to);
  return state;
}

}  // namespace fluidviz::fhp
