// The boundary link table of one rank's block (TableExtent, issue 18) against the serial table:
// every owned node must pull every population from the same global node and plane with the same
// momentum term, be a run node or a boundary node as in serial, and carry the same open side,
// inlet factor and Bouzidi links (sources mapped to global nodes). That is what makes the
// decomposed step bit-identical to the serial one. 1-4 ranks (uneven splits), D2Q9 and D3Q19,
// each boundary type: walls, moving walls, periodic, Zou-He (parabolic inlet), staircase and
// Bouzidi rollers cut by rank borders and by a periodic side.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "solvers/lbm/boundaries/BoxSides.h"
#include "solvers/lbm/boundaries/RotatingRoller.h"
#include "solvers/lbm/kernel/BoundaryLinkTable.h"
#include "solvers/lbm/lattice/LatticeD2Q9.h"
#include "solvers/lbm/lattice/LatticeD3Q19.h"
#include "solvers/lbm/parallel/HaloPlan.h"

namespace fluidviz::lbm {
namespace {

constexpr int kTableNx = 24, kTableNy = 20, kTableNz = 6;

LbmParams tableBox(bool threeD) {
  LbmParams p;
  p.lattice = threeD ? Lattice::D3Q19 : Lattice::D2Q9;
  p.domain_size = {1.0, double(kTableNy) / kTableNx};
  if (threeD) p.domain_depth = double(kTableNz) / kTableNx;
  p.resolution = kTableNx;
  p.end_time = 1e6;
  p.reynolds = 20;
  p.lattice_velocity = 0.05;
  return p;
}

void makePeriodic(WallParams& a, WallParams& b) { a.type = b.type = WallType::periodic; }

std::vector<std::pair<std::string, std::function<void(LbmParams&)>>> tableScenes() {
  return {
      {"MovingWalls",
       [](LbmParams& p) {
         p.walls.y_max.type = WallType::moving_wall;
         p.walls.y_max.velocity = {1.0, 0.0};
         p.walls.x_min.type = WallType::moving_wall;
         p.walls.x_min.velocity = {0.0, -0.5};
       }},
      {"PeriodicEverywhereAroundARoller",
       [](LbmParams& p) {
         makePeriodic(p.walls.x_min, p.walls.x_max);
         makePeriodic(p.walls.y_min, p.walls.y_max);
         makePeriodic(p.walls.z_min, p.walls.z_max);
         // Something must move (the time step follows from a reference speed): a roller in the
         // middle, cut by the rank borders of most splits.
         p.rollers.push_back({{0.5, 0.4}, 0.15, 5.0, RollerBoundary::staircase});
       }},
      {"ZouHeParabolicInletAndOutlet",
       [](LbmParams& p) {
         p.walls.x_min.type = WallType::velocity_inlet;
         p.walls.x_min.velocity = {1.0, 0.0};
         p.walls.x_min.profile = InletProfile::parabolic;
         p.walls.x_max.type = WallType::pressure_outlet;
       }},
      {"StaircaseRollerUnderMovingLid",
       [](LbmParams& p) {
         p.walls.y_max.type = WallType::moving_wall;
         p.walls.y_max.velocity = {0.5, 0.0};
         p.rollers.push_back({{0.45, 0.4}, 0.2, 5.0, RollerBoundary::staircase});
       }},
      {"BouzidiRollersAcrossPeriodicSide",
       [](LbmParams& p) {
         makePeriodic(p.walls.x_min, p.walls.x_max);
         p.rollers.push_back({{0.15, 0.42}, 0.15, 6.0, RollerBoundary::interpolated});
         p.rollers.push_back({{0.6, 0.4}, 0.21, -4.0, RollerBoundary::interpolated});
       }},
  };
}

/// One owned node's pull rule, sources as (plane, global node).
struct GlobalRule {
  bool boundary = false;
  std::vector<std::int64_t> plane, node;
  std::vector<double> delta;
  int openSide = -1;
  double inletFactor = 1.0;
  std::vector<double> interpolated;  // q, plane and global node of s1 and s2, w1, w2, delta
};

template <class L>
std::vector<GlobalRule> globalRules(const BoundaryLinkTable<L>& t, const std::array<int, 3>& gd,
                                    const std::function<std::array<int, 3>(std::int64_t)>& toGlobal) {
  std::vector<GlobalRule> rules(static_cast<std::size_t>(gd[0]) * gd[1] * gd[2]);
  auto global = [&](std::int64_t n) {
    const std::array<int, 3> g = toGlobal(n);
    return (std::int64_t(g[2]) * gd[1] + g[1]) * gd[0] + g[0];
  };
  auto add = [&](GlobalRule& r, std::int64_t source, double delta) {
    r.plane.push_back(source / t.stride());
    r.node.push_back(global(source % t.stride()));
    r.delta.push_back(delta);
  };
  for (const BulkRun& run : t.runs())
    for (std::int64_t n = run.begin; n < run.end; ++n) {
      GlobalRule& r = rules[global(n)];
      const RunPattern<L::Q>& p = t.runPatterns()[run.pattern];
      for (int q = 0; q < L::Q; ++q) add(r, p.source[q] + n, p.delta[q]);
    }
  for (const BoundaryNode<L::Q>& b : t.boundaryNodes()) {
    GlobalRule& r = rules[global(b.node)];
    r.boundary = true;
    for (int q = 0; q < L::Q; ++q) add(r, b.links[q].source, b.links[q].delta);
    r.openSide = b.openSide;
    r.inletFactor = b.inletFactor;
    for (std::int32_t k = b.interpolatedBegin; k < b.interpolatedEnd; ++k) {
      const InterpolatedLink& l = t.interpolatedLinks()[k];
      r.interpolated.insert(r.interpolated.end(),
                            {double(l.q), double(l.s1 / t.stride()), double(global(l.s1 % t.stride())),
                             double(l.s2 / t.stride()), double(global(l.s2 % t.stride())), l.w1,
                             l.w2, l.delta});
    }
  }
  return rules;
}

template <class L>
void expectBlockTablesMatchSerial(const std::string& name, LbmParams p) {
  const LatticeUnits u = computeLatticeUnits(p);
  const BoxSides sides = BoxSides::fromParams(p.walls, u);
  const std::vector<SolidBody> bodies = sceneBodies(p, {});
  const std::array<int, 3> gd{u.nx, u.ny, L::D == 3 ? u.nz : 1};
  const std::int64_t serialStride = std::int64_t(gd[0]) * gd[1] * gd[2];
  const BoundaryLinkTable<L> serial(u, sides, bodies, serialStride);
  const std::vector<GlobalRule> expected = globalRules<L>(serial, gd, [&](std::int64_t n) {
    return std::array<int, 3>{int(n % gd[0]), int(n / gd[0] % gd[1]), int(n / gd[0] / gd[1])};
  });
  for (int ranks = 1; ranks <= 4; ++ranks) {
    const BlockDecomposition d = decomposeLattice(
        gd, ranks, {sides.periodic(0), sides.periodic(1), L::D == 3 && sides.periodic(2)});
    std::vector<GlobalRule> got(expected.size());
    std::vector<int> seen(expected.size(), 0);
    std::int64_t fluid = 0;
    for (int r = 0; r < ranks; ++r) {
      const LocalBlock b = localBlock(d, r);
      TableExtent e;
      e.localDims = b.dims();
      e.globalDims = gd;
      for (int a = 0; a < 3; ++a) {
        e.offset[a] = b.owned.begin[a] - b.ghostLo[a];
        e.ownedLo[a] = b.ghostLo[a];
        e.ownedHi[a] = b.ghostLo[a] + b.owned.end[a] - b.owned.begin[a];
      }
      const BoundaryLinkTable<L> table(u, sides, bodies, b.nodeCount(), e);
      fluid += table.fluidNodeCount();
      const std::array<int, 3> ld = b.dims();
      const std::vector<GlobalRule> mine = globalRules<L>(table, gd, [&](std::int64_t n) {
        return b.globalOf({int(n % ld[0]), int(n / ld[0] % ld[1]), int(n / ld[0] / ld[1])});
      });
      for (std::size_t n = 0; n < mine.size(); ++n)
        if (!mine[n].plane.empty()) {
          got[n] = mine[n];
          ++seen[n];
        }
    }
    EXPECT_EQ(fluid, serial.fluidNodeCount()) << name << ", " << ranks << " ranks";
    int mismatches = 0;
    for (std::size_t n = 0; n < expected.size(); ++n) {
      const GlobalRule &e = expected[n], &g = got[n];
      const bool same = e.boundary == g.boundary && e.plane == g.plane && e.node == g.node &&
                        e.delta == g.delta && e.openSide == g.openSide &&
                        e.inletFactor == g.inletFactor && e.interpolated == g.interpolated &&
                        seen[n] == (e.plane.empty() ? 0 : 1);
      if (!same && ++mismatches <= 3)
        ADD_FAILURE() << name << ", " << L::name << ", " << ranks << " ranks: node " << n
                      << " pulls differently from serial";
    }
    EXPECT_EQ(mismatches, 0) << name << ", " << ranks << " ranks";
  }
}

TEST(BlockTable, EveryOwnedNodePullsAsInSerialD2Q9) {
  for (const auto& [name, setUp] : tableScenes()) {
    LbmParams p = tableBox(false);
    setUp(p);
    if (p.walls.z_min.type == WallType::periodic) p.walls.z_min.type = p.walls.z_max.type = WallType::wall;
    expectBlockTablesMatchSerial<LatticeD2Q9>(name, p);
  }
}

TEST(BlockTable, EveryOwnedNodePullsAsInSerialD3Q19) {
  for (const auto& [name, setUp] : tableScenes()) {
    LbmParams p = tableBox(true);
    setUp(p);
    expectBlockTablesMatchSerial<LatticeD3Q19>(name, p);
  }
}

}  // namespace
}  // namespace fluidviz::lbm
