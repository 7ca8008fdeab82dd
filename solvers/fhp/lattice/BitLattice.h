#pragma once
// Multi-spin coded FHP lattice gas: one bit per node and channel, 64 nodes of a row per 64-bit
// word, one plane of words per channel (Wolf-Gladrow 2000, section 3.3). Propagation moves whole
// words (a shift by one bit for the links with an x component, a row change for the others);
// collision transposes 8 nodes at a time into bytes, looks each byte up in the collision table
// and transposes back. Rows are distributed over OpenMP threads.
// The step is the reference step of NodeLattice.h, bit for bit (same random bits).
#include <cstdint>
#include <utility>
#include <vector>

#include "solvers/fhp/kernel/MovingWall.h"
#include "solvers/fhp/kernel/StepRules.h"
#include "solvers/fhp/lattice/NodeLattice.h"

namespace fluidviz::fhp {

class BitLattice {
 public:
  /// nx a multiple of 64 (>= 64), ny even (>= 2); all channels empty, no solid node.
  BitLattice(int nx, int ny);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int wordsPerRow() const { return nw_; }
  std::uint64_t time() const { return time_; }

  std::uint8_t node(int x, int y) const;
  void setNode(int x, int y, std::uint8_t state);
  bool isSolid(int x, int y) const;
  void setSolid(int x, int y, bool solid);
  /// A solid node with the slip bit reflects specularly (free slip) instead of bouncing back.
  bool isSlip(int x, int y) const;
  void setSlip(int x, int y, bool slip);

  /// Solid nodes of moving walls and rollers (MovingWall.h): after the bounce-back of the
  /// collision, their reflected particles are turned towards the wall velocity.
  void setWallMotion(std::vector<WallNodeMotion> nodes) { moving_ = std::move(nodes); }
  const std::vector<WallNodeMotion>& wallMotion() const { return moving_; }

  /// Word w of channel c's plane in row y (bit b: node x = 64 w + b).
  std::uint64_t word(int channel, int y, int w) const { return planes_[index(channel, y, w)]; }
  std::uint64_t solidWord(int y, int w) const { return solid_[static_cast<std::size_t>(y) * nw_ + w]; }

  /// Total number of particles (all channels, fluid and solid nodes).
  std::uint64_t particleCount() const;

  /// One step (collision, then propagation); returns the number of body-force flips made, each
  /// adding momentum 2 c_d (the force actually applied, which depends on the local occupation).
  std::uint64_t step(const CollisionTable& table, const StepRules& rules);

  NodeLattice toNodes() const;
  static BitLattice fromNodes(const NodeLattice& nodes);

  /// Raw state, for checkpoints: channel planes, solid plane, and the step count.
  const std::vector<std::uint64_t>& planes() const { return planes_; }
  const std::vector<std::uint64_t>& solidPlane() const { return solid_; }
  /// Restores the channel planes and the step count (the geometry is rebuilt from the scene).
  void restore(std::vector<std::uint64_t> planes, std::uint64_t time);

 private:
  std::size_t index(int c, int y, int w) const {
    return (static_cast<std::size_t>(c) * ny_ + y) * nw_ + w;
  }
  std::uint64_t collide(const CollisionTable& table, const StepRules& rules);
  void turnAtMovingWalls(const StepRules& rules);
  void propagate();

  int nx_, ny_, nw_;
  std::uint64_t time_ = 0;
  std::vector<std::uint64_t> planes_;  ///< kMaxChannels planes of ny x nw words
  std::vector<std::uint64_t> solid_;   ///< ny x nw words
  std::vector<std::uint64_t> slip_;    ///< ny x nw words (meaningful at solid nodes)
  std::vector<std::uint64_t> scratch_;
  std::vector<WallNodeMotion> moving_;
};

}  // namespace fluidviz::fhp
