#include "solvers/lbm/parallel/BlockDecomposition.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace fluidviz::lbm {

std::array<int, 3> BlockDecomposition::coordsOf(int rank) const {
  const int px = ranksPerAxis[0], py = ranksPerAxis[1];
  return {rank % px, (rank / px) % py, rank / (px * py)};
}

int BlockDecomposition::rankAt(const std::array<int, 3>& c) const {
  return (c[2] * ranksPerAxis[1] + c[1]) * ranksPerAxis[0] + c[0];
}

BlockDecomposition::Block BlockDecomposition::block(int rank) const {
  const std::array<int, 3> c = coordsOf(rank);
  Block b;
  for (int a = 0; a < 3; ++a) {
    // 64-bit products: c n overflows int for lattices past 2^31 / ranks nodes per axis.
    const long long n = globalDims[a], p = ranksPerAxis[a];
    b.begin[a] = static_cast<int>(c[a] * n / p);
    b.end[a] = static_cast<int>((c[a] + 1) * n / p);
  }
  return b;
}

int BlockDecomposition::neighbour(int rank, const std::array<int, 3>& direction) const {
  std::array<int, 3> c = coordsOf(rank);
  for (int a = 0; a < 3; ++a) {
    c[a] += direction[a];
    const int p = ranksPerAxis[a];
    if (c[a] >= 0 && c[a] < p) continue;
    if (!periodic[a]) return -1;
    c[a] = (c[a] + p) % p;
  }
  return rankAt(c);
}

int BlockDecomposition::ownerOf(const std::array<int, 3>& node) const {
  std::array<int, 3> c{};
  for (int a = 0; a < 3; ++a) {
    // The block c with c n / p <= i < (c + 1) n / p: start from the even-split guess and step.
    const long long n = globalDims[a], p = ranksPerAxis[a], i = node[a];
    long long k = i * p / n;
    while (k > 0 && k * n / p > i) --k;
    while (k + 1 < p && (k + 1) * n / p <= i) ++k;
    c[a] = static_cast<int>(k);
  }
  return rankAt(c);
}

namespace {

/// Ghost nodes exchanged between ranks per step for a split p of dims: per axis, the number of
/// cuts (inner borders, plus the wrap border of a periodic axis split in two or more) times the
/// area of a cross-section.
long long cutArea(const std::array<int, 3>& dims, const std::array<int, 3>& p,
                  const std::array<bool, 3>& periodic) {
  long long area = 0;
  for (int a = 0; a < 3; ++a) {
    if (p[a] == 1) continue;
    const long long cuts = p[a] - 1 + (periodic[a] ? 1 : 0);
    const long long section = static_cast<long long>(dims[(a + 1) % 3]) * dims[(a + 2) % 3];
    area += cuts * section;
  }
  return area;
}

}  // namespace

BlockDecomposition decomposeLattice(const std::array<int, 3>& dims, int ranks,
                                    const std::array<bool, 3>& periodic) {
  if (ranks < 1)
    throw std::invalid_argument("decomposeLattice: rank count " + std::to_string(ranks) +
                                " is not positive");
  BlockDecomposition best;
  best.globalDims = dims;
  best.periodic = periodic;
  long long bestArea = std::numeric_limits<long long>::max();
  const int maxPz = dims[2] == 1 ? 1 : ranks;
  // z outermost, descending: the first split of least area found cuts z (then y) the most.
  for (int pz = maxPz; pz >= 1; --pz) {
    if (ranks % pz != 0 || pz > dims[2]) continue;
    for (int py = ranks / pz; py >= 1; --py) {
      if ((ranks / pz) % py != 0 || py > dims[1]) continue;
      const int px = ranks / pz / py;
      if (px > dims[0]) continue;
      const long long area = cutArea(dims, {px, py, pz}, periodic);
      if (area < bestArea) {
        bestArea = area;
        best.ranksPerAxis = {px, py, pz};
      }
    }
  }
  if (bestArea == std::numeric_limits<long long>::max())
    throw std::invalid_argument("decomposeLattice: a lattice of " + std::to_string(dims[0]) +
                                " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]) +
                                " nodes cannot be split over " + std::to_string(ranks) +
                                " ranks with at least one node per rank and axis");
  return best;
}

}  // namespace fluidviz::lbm
