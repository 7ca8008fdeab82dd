#include "solvers/fhp/lattice/BitLattice.h"

#include <array>
#include <bit>
#include <stdexcept>
#include <string>

#include "solvers/fhp/kernel/RandomBits.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {
namespace {

constexpr std::uint64_t kLowBitOfEachByte = 0x0101010101010101ull;

/// spread8[v]: byte j holds bit j of v (8 bits of a plane word -> 8 node bytes).
constexpr std::array<std::uint64_t, 256> makeSpreadTable() {
  std::array<std::uint64_t, 256> t{};
  for (unsigned v = 0; v < 256; ++v)
    for (unsigned j = 0; j < 8; ++j)
      if (v & (1u << j)) t[v] |= 1ull << (8 * j);
  return t;
}
constexpr std::array<std::uint64_t, 256> kSpread8 = makeSpreadTable();

/// Inverse of kSpread8 for a word holding bits only at positions 8 j: the product places bit 8 j
/// at 56 + j and every other partial product below bit 56 or beyond bit 63, without carries.
constexpr unsigned gather8(std::uint64_t lowBits) {
  return static_cast<unsigned>((lowBits * 0x0102040810204080ull) >> 56);
}

constexpr std::array<std::uint8_t, 128> makeBounceTable() {
  std::array<std::uint8_t, 128> t{};
  for (int s = 0; s < 128; ++s) {
    const unsigned moving = s & 0x3F;
    t[s] = static_cast<std::uint8_t>((((moving << 3) | (moving >> 3)) & 0x3F) | (s & 0x40));
  }
  return t;
}
constexpr std::array<std::uint8_t, 128> kBounce = makeBounceTable();

std::array<std::uint8_t, 128> makeMirrorTable() {
  std::array<std::uint8_t, 128> t{};
  for (int s = 0; s < 128; ++s) t[s] = specularReflectionY(static_cast<std::uint8_t>(s));
  return t;
}
const std::array<std::uint8_t, 128> kMirrorY = makeMirrorTable();

/// Row `src` moved by dx nodes into `dst` (dst[x] = src[x - dx]), periodic over nw words.
void shiftRow(const std::uint64_t* src, std::uint64_t* dst, int nw, int dx) {
  if (dx == 0) {
    for (int w = 0; w < nw; ++w) dst[w] = src[w];
  } else if (dx == 1) {
    for (int w = 0; w < nw; ++w) dst[w] = (src[w] << 1) | (src[(w + nw - 1) % nw] >> 63);
  } else {
    for (int w = 0; w < nw; ++w) dst[w] = (src[w] >> 1) | (src[(w + 1) % nw] << 63);
  }
}

}  // namespace

BitLattice::BitLattice(int nx, int ny) : nx_(nx), ny_(ny), nw_(nx / 64) {
  if (nx < 64 || nx % 64 != 0)
    throw std::invalid_argument("FHP lattice: nx = " + std::to_string(nx) +
                                " must be a positive multiple of 64 (64 nodes per word)");
  if (ny < 2 || ny % 2 != 0)
    throw std::invalid_argument("FHP lattice: ny = " + std::to_string(ny) +
                                " must be even and >= 2 (odd rows are shifted; rows wrap)");
  planes_.assign(static_cast<std::size_t>(kMaxChannels) * ny_ * nw_, 0);
  scratch_.assign(planes_.size(), 0);
  solid_.assign(static_cast<std::size_t>(ny_) * nw_, 0);
  slip_.assign(solid_.size(), 0);
}

std::uint8_t BitLattice::node(int x, int y) const {
  std::uint8_t s = 0;
  for (int c = 0; c < kMaxChannels; ++c)
    if ((planes_[index(c, y, x / 64)] >> (x % 64)) & 1u) s |= static_cast<std::uint8_t>(1u << c);
  return s;
}

void BitLattice::setNode(int x, int y, std::uint8_t state) {
  const std::uint64_t bit = 1ull << (x % 64);
  for (int c = 0; c < kMaxChannels; ++c) {
    std::uint64_t& w = planes_[index(c, y, x / 64)];
    w = (state & (1u << c)) ? (w | bit) : (w & ~bit);
  }
}

bool BitLattice::isSolid(int x, int y) const { return (solidWord(y, x / 64) >> (x % 64)) & 1u; }

void BitLattice::setSolid(int x, int y, bool solid) {
  std::uint64_t& w = solid_[static_cast<std::size_t>(y) * nw_ + x / 64];
  const std::uint64_t bit = 1ull << (x % 64);
  w = solid ? (w | bit) : (w & ~bit);
}

bool BitLattice::isSlip(int x, int y) const {
  return (slip_[static_cast<std::size_t>(y) * nw_ + x / 64] >> (x % 64)) & 1u;
}

void BitLattice::setSlip(int x, int y, bool slip) {
  std::uint64_t& w = slip_[static_cast<std::size_t>(y) * nw_ + x / 64];
  const std::uint64_t bit = 1ull << (x % 64);
  w = slip ? (w | bit) : (w & ~bit);
}

std::uint64_t BitLattice::particleCount() const {
  std::uint64_t n = 0;
  for (std::uint64_t w : planes_) n += static_cast<std::uint64_t>(std::popcount(w));
  return n;
}

std::uint64_t BitLattice::collide(const CollisionTable& table, const StepRules& rules) {
  const std::uint64_t threshold = probabilityThreshold(rules.forceProbability);
  const std::uint64_t t = time_;
  std::uint64_t flips = 0;
#pragma omp parallel for schedule(static) reduction(+ : flips)
  for (int y = 0; y < ny_; ++y) {
    for (int w = 0; w < nw_; ++w) {
      std::uint64_t in[kMaxChannels], out[kMaxChannels] = {};
      for (int c = 0; c < kMaxChannels; ++c) in[c] = planes_[index(c, y, w)];
      const std::uint64_t solid = solidWord(y, w);
      const std::uint64_t slip = slip_[static_cast<std::size_t>(y) * nw_ + w];
      const std::uint64_t chirality = chiralityWord(rules.seed, t, y, w);
      for (int m = 0; m < 8; ++m) {  // 8 nodes at a time, one byte each
        std::uint64_t bytes = 0;
        for (int c = 0; c < kMaxChannels; ++c) bytes |= kSpread8[(in[c] >> (8 * m)) & 0xFF] << c;
        std::uint64_t collided = 0;
        for (int j = 0; j < 8; ++j) {
          const int b = 8 * m + j;
          auto s = static_cast<std::uint8_t>((bytes >> (8 * j)) & 0x7F);
          if ((solid >> b) & 1u) {
            s = ((slip >> b) & 1u) ? kMirrorY[s] : kBounce[s];
          } else {
            s = table.after[(chirality >> b) & 1u][s];
            if (eventHappens(rules.seed, t, 64 * w + b, y, threshold)) {
              const std::uint8_t flipped = applyForceFlip(s, rules.forceDirection);
              flips += flipped != s;
              s = flipped;
            }
          }
          collided |= static_cast<std::uint64_t>(s) << (8 * j);
        }
        for (int c = 0; c < kMaxChannels; ++c)
          out[c] |= static_cast<std::uint64_t>(gather8((collided >> c) & kLowBitOfEachByte)) << (8 * m);
      }
      for (int c = 0; c < kMaxChannels; ++c) planes_[index(c, y, w)] = out[c];
    }
  }
  return flips;
}

// A few nodes per wall row or roller rim: node by node, after the collision pass has bounced them.
void BitLattice::turnAtMovingWalls(const StepRules& rules) {
  for (const WallNodeMotion& m : moving_)
    setNode(m.x, m.y, turnReflectedParticles(node(m.x, m.y), m, rules.seed, time_));
}

void BitLattice::propagate() {
#pragma omp parallel for schedule(static)
  for (int y = 0; y < ny_; ++y) {
    for (int c = 0; c < kMovingChannels; ++c) {
      const int ys = (y - kDy[c] + ny_) % ny_;  // row the particle comes from
      shiftRow(&planes_[index(c, ys, 0)], &scratch_[index(c, y, 0)], nw_,
               neighbourDx(c, ys % 2 == 1));
    }
    shiftRow(&planes_[index(kRestChannel, y, 0)], &scratch_[index(kRestChannel, y, 0)], nw_, 0);
  }
  planes_.swap(scratch_);
}

std::uint64_t BitLattice::step(const CollisionTable& table, const StepRules& rules) {
  const std::uint64_t flips = collide(table, rules);
  turnAtMovingWalls(rules);
  propagate();
  ++time_;
  return flips;
}

NodeLattice BitLattice::toNodes() const {
  NodeLattice n(nx_, ny_);
  n.time = time_;
  n.moving = moving_;
  for (int y = 0; y < ny_; ++y)
    for (int x = 0; x < nx_; ++x) {
      n.at(x, y) = node(x, y);
      n.solid[static_cast<std::size_t>(y) * nx_ + x] = isSolid(x, y) ? 1 : 0;
      n.slip[static_cast<std::size_t>(y) * nx_ + x] = isSlip(x, y) ? 1 : 0;
    }
  return n;
}

BitLattice BitLattice::fromNodes(const NodeLattice& n) {
  BitLattice b(n.nx, n.ny);
  b.time_ = n.time;
  b.moving_ = n.moving;
  for (int y = 0; y < n.ny; ++y)
    for (int x = 0; x < n.nx; ++x) {
      b.setNode(x, y, n.at(x, y));
      b.setSolid(x, y, n.solid[static_cast<std::size_t>(y) * n.nx + x] != 0);
      b.setSlip(x, y, n.slip[static_cast<std::size_t>(y) * n.nx + x] != 0);
    }
  return b;
}

void BitLattice::restore(std::vector<std::uint64_t> planes, std::uint64_t time) {
  if (planes.size() != planes_.size())
    throw std::invalid_argument("FHP lattice: saved state has the wrong size for " +
                                std::to_string(nx_) + " x " + std::to_string(ny_) + " nodes");
  planes_ = std::move(planes);
  time_ = time;
}

}  // namespace fluidviz::fhp
