#include "solvers/fhp/collision/CollisionTable.h"

#include <bit>
#include <map>
#include <tuple>
#include <vector>

#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {
namespace {

constexpr std::uint8_t kMovingMask = 0x3F;
constexpr std::uint8_t kRestBit = 1u << kRestChannel;

bool isHeadOnPair(std::uint8_t moving) {
  for (int i = 0; i < 3; ++i)
    if (moving == ((1u << i) | (1u << (i + 3)))) return true;
  return false;
}
bool isSymmetricTriple(std::uint8_t moving) { return moving == 0x15 || moving == 0x2A; }
/// Two particles at +-60 degrees to c_i (directions i - 1 and i + 1): momentum c_i.
bool isPairAt120Degrees(std::uint8_t moving) {
  for (int i = 0; i < kMovingChannels; ++i)
    if (moving == ((1u << ((i + 5) % 6)) | (1u << ((i + 1) % 6)))) return true;
  return false;
}

/// Which collision family a state belongs to under `model`; -1: it does not collide. States of
/// one family with equal number and momentum are exchanged by the collision.
int family(Model model, std::uint8_t state) {
  const std::uint8_t moving = state & kMovingMask;
  const bool rest = (state & kRestBit) != 0;
  const bool fhp1Pattern = isHeadOnPair(moving) || isSymmetricTriple(moving);
  switch (model) {
    case Model::fhp1:
      return (!rest && fhp1Pattern) ? 0 : -1;
    case Model::fhp2:
      if (fhp1Pattern) return rest ? 1 : 0;  // rest particle as spectator
      if (rest && std::popcount(moving) == 1) return 2;
      if (!rest && isPairAt120Degrees(moving)) return 2;
      return -1;
    case Model::fhp3:
      return 0;
  }
  return -1;
}

}  // namespace

int particleCount(std::uint8_t state) { return std::popcount(static_cast<unsigned>(state)); }

int momentumX2(std::uint8_t state) {
  int p = 0;
  for (int i = 0; i < kMaxChannels; ++i)
    if (state & (1u << i)) p += kCx2[i];
  return p;
}

int momentumYInt(std::uint8_t state) {
  int p = 0;
  for (int i = 0; i < kMaxChannels; ++i)
    if (state & (1u << i)) p += kCyInt[i];
  return p;
}

std::uint8_t bounceBack(std::uint8_t state) {
  const std::uint8_t moving = state & kMovingMask;
  const std::uint8_t reversed = static_cast<std::uint8_t>(((moving << 3) | (moving >> 3)) & kMovingMask);
  return static_cast<std::uint8_t>(reversed | (state & kRestBit));
}

std::uint8_t specularReflectionY(std::uint8_t state) {
  // c_i -> c_(6-i) mod 6: (cx, cy) -> (cx, -cy); channels 0, 3 and the rest particle stay.
  std::uint8_t out = state & static_cast<std::uint8_t>(0x09 | kRestBit);
  for (int i : {1, 2, 4, 5})
    if (state & (1u << i)) out |= static_cast<std::uint8_t>(1u << (6 - i));
  return out;
}

CollisionTable buildCollisionTable(Model model) {
  // Classes keyed by (family, number, momentum); std::map keeps members in ascending bit order.
  std::map<std::tuple<int, int, int, int>, std::vector<std::uint8_t>> classes;
  CollisionTable table;
  for (int s = 0; s < 128; ++s) {
    const auto state = static_cast<std::uint8_t>(s);
    table.after[0][s] = table.after[1][s] = state;
    const int f = family(model, state);
    if (f < 0) continue;
    classes[{f, particleCount(state), momentumX2(state), momentumYInt(state)}].push_back(state);
  }
  for (const auto& [key, members] : classes) {
    const std::size_t n = members.size();
    for (std::size_t k = 0; k < n; ++k) {
      table.after[0][members[k]] = members[(k + 1) % n];
      table.after[1][members[k]] = members[(k + n - 1) % n];
    }
  }
  return table;
}

}  // namespace fluidviz::fhp
