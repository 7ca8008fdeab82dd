#pragma once
// Block decomposition of an LBM lattice over MPI ranks (issue 18): the lattice of nx x ny x nz
// nodes (nz = 1 in 2D) is cut into px x py x pz blocks, one per rank, rank = (cz py + cy) px + cx
// (x fastest, like the nodes). Along an axis of n nodes and p blocks, block c holds the nodes
// [c n / p, (c + 1) n / p): uneven splits differ by at most one node. Plain data and arithmetic,
// no MPI: the halo exchange (the ghost layer of every block, one node deep, filled from the
// neighbour across each of the lattice's directions, D3Q19 edges included) uses neighbour().
#include <array>

namespace fluidviz::lbm {

struct BlockDecomposition {
  std::array<int, 3> globalDims{1, 1, 1};    ///< nodes per axis, nz = 1 in 2D
  std::array<int, 3> ranksPerAxis{1, 1, 1};  ///< px, py, pz; their product is the rank count
  std::array<bool, 3> periodic{false, false, false};  ///< sides that wrap (BoxSides::periodic)

  /// The nodes [begin, end) of one rank, global indices.
  struct Block {
    std::array<int, 3> begin{0, 0, 0};
    std::array<int, 3> end{1, 1, 1};
    long long nodeCount() const {
      return static_cast<long long>(end[0] - begin[0]) * (end[1] - begin[1]) * (end[2] - begin[2]);
    }
  };

  int rankCount() const { return ranksPerAxis[0] * ranksPerAxis[1] * ranksPerAxis[2]; }
  /// Block coordinates (cx, cy, cz) of a rank.
  std::array<int, 3> coordsOf(int rank) const;
  /// Rank of block coordinates (each in [0, p_axis)).
  int rankAt(const std::array<int, 3>& coords) const;
  Block block(int rank) const;
  /// The rank whose block lies one step along `direction` (components -1, 0, 1; an edge or
  /// corner direction of D3Q19 is a diagonal one) from `rank`'s block: wraps across periodic
  /// sides (possibly back to `rank` itself), -1 beyond a non-periodic side of the lattice.
  int neighbour(int rank, const std::array<int, 3>& direction) const;
  /// The rank owning global node (i, j, k).
  int ownerOf(const std::array<int, 3>& node) const;
};

/// The split of `dims` over `ranks` that exchanges the fewest ghost nodes per step: among all
/// px py pz = ranks (pz = 1 if dims[2] == 1, p_axis <= dims[axis]) the one with the least cut
/// area, a cut being an inner block border or, across a periodic side, the wrap border (with
/// one block along a periodic axis the wrap is a copy within the rank, not a message). Ties go
/// to cutting the slowest axis (z, then y): its ghost layers are contiguous planes of the
/// populations, which pack without gathering. Throws std::invalid_argument if ranks < 1 or the
/// lattice has fewer nodes than ranks along every possible split.
BlockDecomposition decomposeLattice(const std::array<int, 3>& dims, int ranks,
                                    const std::array<bool, 3>& periodic);

}  // namespace fluidviz::lbm
