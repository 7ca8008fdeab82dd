#pragma once
// Collision tables of the three FHP models, generated from the conservation laws rather than
// typed in (Frisch et al. 1987, Complex Systems 1:649, section 2; Wolf-Gladrow 2000, section 3.2).
//
// A node state is 7 bits: bit i (0..5) is a particle moving along c_i, bit 6 the rest particle.
// States that carry the same particle number and momentum form a class; a collision replaces a
// state by another member of its class. Each model says which states take part:
//   FHP-I   (6 bits, bit 6 ignored): two-body head-on pairs (class of 3: rotated by +-60 degrees)
//           and three-body symmetric triples (class of 2: swapped).
//   FHP-II  (7 bits): the FHP-I collisions with or without a rest particle as spectator, and a
//           moving particle meeting the rest particle <-> two particles at +-60 degrees to it.
//   FHP-III (7 bits): every class of two or more states (collision-saturated): each state that
//           shares number and momentum with another state is changed.
// Within a class the members are ordered by their bit pattern and the collision moves each state
// one place forward (chirality 0) or backward (chirality 1) around the cycle; the chirality is a
// random bit per node and step, so the two head-on outcomes (+60 and -60 degrees) are equally
// likely. Each table is therefore a bijection of the states onto themselves.
#include <array>
#include <cstdint>
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz::fhp {

enum class Model { fhp1, fhp2, fhp3 };
constexpr std::array<Choice<Model>, 3> paramChoices(Model) {
  return {{{Model::fhp1, "fhp1"}, {Model::fhp2, "fhp2"}, {Model::fhp3, "fhp3"}}};
}

/// 6 (FHP-I) or 7 (FHP-II, FHP-III) channels per node.
constexpr int channelCount(Model m) { return m == Model::fhp1 ? 6 : 7; }

struct CollisionTable {
  /// after[chirality][state]: the post-collision state of a fluid node.
  std::array<std::array<std::uint8_t, 128>, 2> after{};
};

/// Builds the table of `model`. For FHP-I the rest bit is never set and stays unchanged.
CollisionTable buildCollisionTable(Model model);

/// Particle number and momentum (2 c_x, 2 c_y / sqrt 3: integers) of a state.
int particleCount(std::uint8_t state);
int momentumX2(std::uint8_t state);
int momentumYInt(std::uint8_t state);

/// No-slip bounce-back at a solid node: every moving particle reversed, the rest particle kept.
std::uint8_t bounceBack(std::uint8_t state);

/// Free-slip (specular) reflection at a solid node of a wall along x: c_i -> c_(6-i), so the
/// normal momentum is reversed and the tangential momentum kept exactly (Wolf-Gladrow 2000,
/// section 3.2); a particle reflected there moves on along the wall.
std::uint8_t specularReflectionY(std::uint8_t state);

}  // namespace fluidviz::fhp
