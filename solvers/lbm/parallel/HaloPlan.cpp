#include "solvers/lbm/parallel/HaloPlan.h"

namespace fluidviz::lbm {

std::array<int, 3> LocalBlock::globalOf(const std::array<int, 3>& local) const {
  std::array<int, 3> g{};
  for (int a = 0; a < 3; ++a) {
    g[a] = local[a] - ghostLo[a] + owned.begin[a];
    if (periodic[a]) g[a] = (g[a] % globalDims[a] + globalDims[a]) % globalDims[a];
  }
  return g;
}

LocalBlock localBlock(const BlockDecomposition& d, int rank) {
  LocalBlock b;
  b.owned = d.block(rank);
  b.globalDims = d.globalDims;
  b.periodic = d.periodic;
  const int axes = d.globalDims[2] == 1 ? 2 : 3;
  for (int a = 0; a < axes; ++a) {
    std::array<int, 3> down{0, 0, 0}, up{0, 0, 0};
    down[a] = -1;
    up[a] = 1;
    b.ghostLo[a] = d.neighbour(rank, down) >= 0 ? 1 : 0;
    b.ghostHi[a] = d.neighbour(rank, up) >= 0 ? 1 : 0;
  }
  return b;
}

std::vector<HaloLink> haloLinks(const BlockDecomposition& d, int rank) {
  const LocalBlock b = localBlock(d, rank);
  const int zRange = d.globalDims[2] == 1 ? 0 : 1;
  std::vector<HaloLink> links;
  for (int dz = -zRange; dz <= zRange; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::array<int, 3> dir{dx, dy, dz};
        if (dir == std::array<int, 3>{0, 0, 0}) continue;
        const int neighbour = d.neighbour(rank, dir);
        if (neighbour < 0) continue;
        HaloLink l;
        l.direction = dir;
        l.neighbour = neighbour;
        for (int a = 0; a < 3; ++a) {
          const int lo = b.ghostLo[a], hi = lo + b.owned.end[a] - b.owned.begin[a];
          if (dir[a] == 0) {
            l.send.begin[a] = l.receive.begin[a] = lo;
            l.send.end[a] = l.receive.end[a] = hi;
          } else if (dir[a] > 0) {
            l.send.begin[a] = hi - 1, l.send.end[a] = hi;
            l.receive.begin[a] = hi, l.receive.end[a] = hi + 1;
          } else {
            l.send.begin[a] = lo, l.send.end[a] = lo + 1;
            l.receive.begin[a] = lo - 1, l.receive.end[a] = lo;
          }
        }
        l.sendTag = directionIndex(dir);
        l.receiveTag = directionIndex({-dx, -dy, -dz});
        links.push_back(l);
      }
  return links;
}

}  // namespace fluidviz::lbm
