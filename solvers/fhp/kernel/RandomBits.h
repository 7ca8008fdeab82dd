#pragma once
// Random bits of the lattice gas as pure functions of (seed, time step, row, word or node): the
// optimised and the reference stepper draw exactly the same bits whatever the thread count or
// the traversal order, so they can be compared bit for bit and a run is reproducible.
// Mixing: SplitMix64's finaliser (Steele, Lea & Flood 2014) applied to a combined counter.
#include <cstdint>

namespace fluidviz::fhp {

constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

constexpr std::uint64_t counterHash(std::uint64_t seed, std::uint64_t step, std::uint64_t row,
                                    std::uint64_t column, std::uint64_t stream) {
  return mix64(mix64(mix64(mix64(seed ^ (stream << 56)) ^ step) ^ row) ^ column);
}

/// Chirality bits of the 64 nodes x = 64 w .. 64 w + 63 of row y at step t (bit x % 64).
constexpr std::uint64_t chiralityWord(std::uint64_t seed, std::uint64_t t, int y, int w) {
  return counterHash(seed, t, static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(w), 0);
}

constexpr int chiralityBit(std::uint64_t seed, std::uint64_t t, int x, int y) {
  return static_cast<int>((chiralityWord(seed, t, y, x / 64) >> (x % 64)) & 1u);
}

/// Threshold of an event of probability p in [0, 1] for `eventHappens`.
constexpr std::uint64_t probabilityThreshold(double p) {
  if (p <= 0.0) return 0;
  if (p >= 1.0) return ~0ull;
  return static_cast<std::uint64_t>(p * 18446744073709551616.0);  // p 2^64
}

/// True with probability threshold / 2^64 for node (x, y) at step t (the body-force flip).
constexpr bool eventHappens(std::uint64_t seed, std::uint64_t t, int x, int y,
                            std::uint64_t threshold) {
  return threshold != 0 &&
         counterHash(seed, t, static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(x), 1) <
             threshold;
}

}  // namespace fluidviz::fhp
