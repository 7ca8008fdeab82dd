// The block decomposition of issue 18: blocks tile the lattice exactly, uneven splits differ by
// at most one node, neighbours are mutual and wrap only across periodic sides, and the chosen
// split has the least cut area (checked against hand-counted cases).
#include "solvers/lbm/parallel/BlockDecomposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluidviz::lbm {
namespace {

// Every node owned by exactly one rank, and ownerOf agrees with the blocks.
void expectTiling(const BlockDecomposition& d) {
  const auto& n = d.globalDims;
  std::vector<int> owner(static_cast<std::size_t>(n[0]) * n[1] * n[2], -1);
  for (int r = 0; r < d.rankCount(); ++r) {
    const BlockDecomposition::Block b = d.block(r);
    for (int k = b.begin[2]; k < b.end[2]; ++k)
      for (int j = b.begin[1]; j < b.end[1]; ++j)
        for (int i = b.begin[0]; i < b.end[0]; ++i) {
          int& o = owner[(static_cast<std::size_t>(k) * n[1] + j) * n[0] + i];
          EXPECT_EQ(o, -1) << "node (" << i << ", " << j << ", " << k << ") owned twice";
          o = r;
          EXPECT_EQ(d.ownerOf({i, j, k}), r);
        }
  }
  for (int o : owner) EXPECT_GE(o, 0);
}

TEST(BlockDecomposition, UnevenBlocksTileTheLatticeAndDifferByAtMostOneNode) {
  for (int ranks = 1; ranks <= 4; ++ranks) {
    for (const std::array<int, 3> dims : {std::array<int, 3>{13, 7, 1}, {7, 5, 6}, {5, 9, 11}}) {
      const BlockDecomposition d = decomposeLattice(dims, ranks, {false, true, false});
      ASSERT_EQ(d.rankCount(), ranks);
      expectTiling(d);
      for (int a = 0; a < 3; ++a) {
        int smallest = dims[a], largest = 0;
        for (int r = 0; r < ranks; ++r) {
          const BlockDecomposition::Block b = d.block(r);
          smallest = std::min(smallest, b.end[a] - b.begin[a]);
          largest = std::max(largest, b.end[a] - b.begin[a]);
        }
        EXPECT_GE(smallest, 1);
        EXPECT_LE(largest - smallest, 1) << "axis " << a << ", " << ranks << " ranks";
      }
    }
  }
}

TEST(BlockDecomposition, NeighboursAreMutualInAllD3Q19DirectionsAndWrapOnlyWhenPeriodic) {
  BlockDecomposition d;
  d.globalDims = {9, 8, 7};
  d.ranksPerAxis = {3, 2, 2};
  d.periodic = {true, false, true};
  expectTiling(d);
  for (int r = 0; r < d.rankCount(); ++r)
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int m = d.neighbour(r, {dx, dy, dz});
          const std::array<int, 3> c = d.coordsOf(r);
          const bool beyondY = (c[1] == 0 && dy < 0) || (c[1] == 1 && dy > 0);
          if (beyondY) {
            EXPECT_EQ(m, -1);  // y is a wall: no ghost from across it
            continue;
          }
          ASSERT_GE(m, 0);
          EXPECT_EQ(d.neighbour(m, {-dx, -dy, -dz}), r);
        }
  // x wraps: the last block of a row sees the first one; z has 2 blocks, so both z neighbours
  // of a rank are the same rank.
  EXPECT_EQ(d.neighbour(d.rankAt({2, 0, 0}), {1, 0, 0}), d.rankAt({0, 0, 0}));
  EXPECT_EQ(d.neighbour(d.rankAt({0, 1, 1}), {-1, 0, 1}), d.rankAt({2, 1, 0}));
  EXPECT_EQ(d.neighbour(0, {0, 0, 1}), d.neighbour(0, {0, 0, -1}));
  // One block along a periodic axis: the ghost comes from the rank itself.
  BlockDecomposition single;
  single.globalDims = {4, 4, 1};
  single.periodic = {true, true, false};
  EXPECT_EQ(single.neighbour(0, {1, -1, 0}), 0);
}

TEST(BlockDecomposition, ChoosesTheSplitWithTheLeastCutArea) {
  // Channel 64 x 16: cutting x 3 times costs 3 x 16 nodes, cutting y 3 times 3 x 64.
  EXPECT_EQ(decomposeLattice({64, 16, 1}, 4, {false, false, false}).ranksPerAxis,
            (std::array<int, 3>{4, 1, 1}));
  // Square 32 x 32, 4 ranks: 2 x 2 (2 cuts of 32) beats 4 x 1 (3 cuts of 32).
  EXPECT_EQ(decomposeLattice({32, 32, 1}, 4, {false, false, false}).ranksPerAxis,
            (std::array<int, 3>{2, 2, 1}));
  // Periodic x adds the wrap cut: 2 x 2 costs 2 x 32 + 1 x 32, 1 x 4 costs 3 x 32: tie, and ties
  // cut the slower axis, y.
  EXPECT_EQ(decomposeLattice({32, 32, 1}, 4, {true, false, false}).ranksPerAxis,
            (std::array<int, 3>{1, 4, 1}));
  // Cube, 2 ranks: all cuts equal, z is cut.
  EXPECT_EQ(decomposeLattice({8, 8, 8}, 2, {false, false, false}).ranksPerAxis,
            (std::array<int, 3>{1, 1, 2}));
  // 2D never splits z.
  EXPECT_EQ(decomposeLattice({5, 3, 1}, 3, {false, false, false}).ranksPerAxis[2], 1);
}

TEST(BlockDecomposition, RefusesMoreRanksThanNodesAndNonPositiveCounts) {
  EXPECT_THROW(decomposeLattice({2, 1, 1}, 3, {false, false, false}), std::invalid_argument);
  EXPECT_THROW(decomposeLattice({8, 8, 1}, 0, {false, false, false}), std::invalid_argument);
  try {
    decomposeLattice({2, 1, 1}, 5, {false, false, false});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("5 ranks"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidviz::lbm
