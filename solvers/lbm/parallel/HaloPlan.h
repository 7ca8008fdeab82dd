#pragma once
// Where each rank's ghost layer comes from (issue 18), as plain index boxes, no MPI: a rank
// stores its block of the lattice plus one ghost node on every side that has a neighbour
// (another rank, or itself across a periodic side); a side on a non-periodic border of the
// lattice has no ghost, since the boundary rules there (walls, Zou-He) never pull from outside.
// The pull scheme reads f*_q(x - c_q) one node away, so one layer suffices for every lattice
// direction; the edge and corner ghosts (D3Q19's c = (1, 1, 0), ...) come straight from the
// diagonal neighbour, so one round of messages fills the whole layer.
#include <array>
#include <cstdint>
#include <vector>

#include "solvers/lbm/parallel/BlockDecomposition.h"

namespace fluidviz::lbm {

/// Local nodes [begin, end) of a rank's array (ghosts included, x fastest).
struct HaloBox {
  std::array<int, 3> begin{0, 0, 0};
  std::array<int, 3> end{0, 0, 0};
  std::int64_t nodeCount() const {
    return std::int64_t(end[0] - begin[0]) * (end[1] - begin[1]) * (end[2] - begin[2]);
  }
};

/// One rank's block in local coordinates: owned nodes shifted by the ghost layer below them.
struct LocalBlock {
  BlockDecomposition::Block owned;   ///< global indices
  std::array<int, 3> ghostLo{0, 0, 0};  ///< 1 where the side below has a neighbour
  std::array<int, 3> ghostHi{0, 0, 0};
  std::array<int, 3> globalDims{1, 1, 1};
  std::array<bool, 3> periodic{false, false, false};

  std::array<int, 3> dims() const {
    return {owned.end[0] - owned.begin[0] + ghostLo[0] + ghostHi[0],
            owned.end[1] - owned.begin[1] + ghostLo[1] + ghostHi[1],
            owned.end[2] - owned.begin[2] + ghostLo[2] + ghostHi[2]};
  }
  std::int64_t nodeCount() const {
    const std::array<int, 3> d = dims();
    return std::int64_t(d[0]) * d[1] * d[2];
  }
  std::int64_t index(int i, int j, int k) const {
    const std::array<int, 3> d = dims();
    return (std::int64_t(k) * d[1] + j) * d[0] + i;
  }
  /// Global node of a local one; ghosts across a periodic side are wrapped.
  std::array<int, 3> globalOf(const std::array<int, 3>& local) const;
};

LocalBlock localBlock(const BlockDecomposition& d, int rank);

/// One message of the exchange: the owned nodes `send` go to the neighbour in `direction`, whose
/// ghost nodes there are filled; `receive` (ghost nodes) comes from the neighbour in the
/// direction itself. Tags are direction indices (directionIndex), so that two messages between
/// the same pair of ranks (2 blocks along a periodic axis, or a rank with itself) stay apart.
struct HaloLink {
  std::array<int, 3> direction{0, 0, 0};
  int neighbour = -1;
  HaloBox send, receive;
  int sendTag = 0;     ///< index of `direction`: the receiver sees it arrive from -direction
  int receiveTag = 0;  ///< index of -direction
};

/// 0..26 for components in {-1, 0, 1} (13 is the rest direction, never used).
inline int directionIndex(const std::array<int, 3>& d) {
  return (d[2] + 1) * 9 + (d[1] + 1) * 3 + (d[0] + 1);
}

/// The messages of one rank: every direction of the 8 (2D) or 26 (3D) neighbours that has a
/// neighbour. A 2D lattice (globalDims z = 1) never exchanges along z.
std::vector<HaloLink> haloLinks(const BlockDecomposition& d, int rank);

}  // namespace fluidviz::lbm
