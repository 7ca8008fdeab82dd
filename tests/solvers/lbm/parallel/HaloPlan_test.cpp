// The halo plan of issue 18, exchanged in one process: each rank's owned nodes hold their global
// index; after every message is delivered (send box of the sender -> receive box of the rank
// whose tag matches), every ghost node must hold the global index of the node it mirrors
// (wrapped across periodic sides), for 1-4 ranks, 2D and 3D, uneven splits. Dropping one
// direction's messages must leave wrong ghosts (the check can see a missing direction).
#include "solvers/lbm/parallel/HaloPlan.h"

#include <gtest/gtest.h>

#include <vector>

namespace fluidviz::lbm {
namespace {

struct RankArray {
  LocalBlock block;
  std::vector<HaloLink> links;
  std::vector<std::int64_t> value;  // global index of the node, -1 = not filled
};

std::int64_t globalIndex(const std::array<int, 3>& g, const std::array<int, 3>& dims) {
  return (std::int64_t(g[2]) * dims[1] + g[1]) * dims[0] + g[0];
}

template <class F>
void forBox(const HaloBox& box, F&& f) {
  for (int k = box.begin[2]; k < box.end[2]; ++k)
    for (int j = box.begin[1]; j < box.end[1]; ++j)
      for (int i = box.begin[0]; i < box.end[0]; ++i) f(i, j, k);
}

std::vector<RankArray> filledRanks(const BlockDecomposition& d) {
  std::vector<RankArray> ranks(d.rankCount());
  for (int r = 0; r < d.rankCount(); ++r) {
    RankArray& a = ranks[r];
    a.block = localBlock(d, r);
    a.links = haloLinks(d, r);
    a.value.assign(a.block.nodeCount(), -1);
    HaloBox owned;
    for (int ax = 0; ax < 3; ++ax) {
      owned.begin[ax] = a.block.ghostLo[ax];
      owned.end[ax] = owned.begin[ax] + a.block.owned.end[ax] - a.block.owned.begin[ax];
    }
    forBox(owned, [&](int i, int j, int k) {
      a.value[a.block.index(i, j, k)] = globalIndex(a.block.globalOf({i, j, k}), d.globalDims);
    });
  }
  return ranks;
}

/// Delivers every message (as MPI would: the sender's send box in x-fastest order into the
/// receiver's receive box with the matching tag), except those tagged `dropTag`.
void exchange(std::vector<RankArray>& ranks, int dropTag = -1) {
  std::vector<std::vector<std::int64_t>> packed;  // per (rank, link), packed before any unpack
  for (RankArray& a : ranks)
    for (const HaloLink& l : a.links) {
      std::vector<std::int64_t> m;
      forBox(l.send, [&](int i, int j, int k) { m.push_back(a.value[a.block.index(i, j, k)]); });
      packed.push_back(std::move(m));
    }
  std::size_t message = 0;
  for (int r = 0; r < static_cast<int>(ranks.size()); ++r)
    for (const HaloLink& l : ranks[r].links) {
      const std::vector<std::int64_t>& m = packed[message++];
      if (l.sendTag == dropTag) continue;
      RankArray& to = ranks[l.neighbour];
      int matches = 0;
      for (const HaloLink& in : to.links) {
        if (in.neighbour != r || in.receiveTag != l.sendTag) continue;
        ++matches;
        ASSERT_EQ(in.receive.nodeCount(), static_cast<std::int64_t>(m.size()));
        std::size_t n = 0;
        forBox(in.receive, [&](int i, int j, int k) { to.value[to.block.index(i, j, k)] = m[n++]; });
      }
      ASSERT_EQ(matches, 1) << "message from rank " << r << " tag " << l.sendTag;
    }
}

/// Ghost nodes holding the wrong global index (or none).
int wrongGhosts(const std::vector<RankArray>& ranks, const std::array<int, 3>& dims) {
  int wrong = 0;
  for (const RankArray& a : ranks) {
    const std::array<int, 3> ld = a.block.dims();
    forBox(HaloBox{{0, 0, 0}, ld}, [&](int i, int j, int k) {
      if (a.value[a.block.index(i, j, k)] != globalIndex(a.block.globalOf({i, j, k}), dims))
        ++wrong;
    });
  }
  return wrong;
}

TEST(HaloPlan, EveryGhostNodeMirrorsItsGlobalNodeFor1To4Ranks2DAnd3D) {
  const std::array<std::array<int, 3>, 3> lattices{{{7, 5, 1}, {5, 4, 3}, {3, 7, 5}}};
  const std::array<std::array<bool, 3>, 3> sides{{{false, false, false}, {true, false, true},
                                                  {true, true, true}}};
  for (int ranks = 1; ranks <= 4; ++ranks)
    for (const auto& dims : lattices)
      for (auto periodic : sides) {
        if (dims[2] == 1) periodic[2] = false;
        const BlockDecomposition d = decomposeLattice(dims, ranks, periodic);
        std::vector<RankArray> a = filledRanks(d);
        exchange(a);
        EXPECT_EQ(wrongGhosts(a, dims), 0)
            << ranks << " ranks, " << dims[0] << "x" << dims[1] << "x" << dims[2];
      }
}

TEST(HaloPlan, GhostLayersOnlyWhereANeighbourExists) {
  BlockDecomposition d;
  d.globalDims = {6, 4, 1};
  d.ranksPerAxis = {2, 1, 1};
  d.periodic = {false, true, false};
  const LocalBlock left = localBlock(d, 0);
  EXPECT_EQ(left.ghostLo, (std::array<int, 3>{0, 1, 0}));  // x_min is a wall: no ghost
  EXPECT_EQ(left.ghostHi, (std::array<int, 3>{1, 1, 0}));
  EXPECT_EQ(left.dims(), (std::array<int, 3>{4, 6, 1}));
  // 2D: 8 directions at most; the x_min ones have no neighbour: 5 remain.
  EXPECT_EQ(haloLinks(d, 0).size(), 5u);
}

TEST(HaloPlan, DroppingOneDirectionLeavesWrongGhosts) {
  // Every direction, one at a time, 3D periodic on 4 ranks (2 x 2 split): some ghost must be
  // wrong, so the bit-identity tests of the solver can see a missing direction.
  const BlockDecomposition d = decomposeLattice({4, 5, 6}, 4, {true, true, true});
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        std::vector<RankArray> a = filledRanks(d);
        exchange(a, directionIndex({dx, dy, dz}));
        EXPECT_GT(wrongGhosts(a, d.globalDims), 0) << "direction " << dx << dy << dz;
      }
}

}  // namespace
}  // namespace fluidviz::lbm
