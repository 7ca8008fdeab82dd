#pragma once
// Precomputed boundary data of the pull scheme. Every fluid node is either
//  - bulk: all 9 neighbours n - c_q are fluid nodes inside the box (no wrap), so the kernel pulls
//    with fixed offsets and no per-direction branch; consecutive bulk nodes of a row form a
//    BulkRun, or
//  - boundary: at least one link crosses a side (wall, moving wall, periodic wrap) or ends in a
//    solid body; its 9 PullLinks (source index + moving-wall momentum) are stored explicitly.
// Solid nodes (centre inside a SolidBody) are in neither list and are never updated.
//
// Links through a corner (a diagonal crossing two sides at their common point) see the sum of the
// two sides' tangential velocities: with one side at rest that is the moving side's velocity,
// which keeps the Ladd momentum terms of a sliding lid summing to zero (exact mass conservation).
#include <array>
#include <cstdint>
#include <vector>

#include "solvers/lbm/LatticeD2Q9.h"
#include "solvers/lbm/PullLink.h"
#include "solvers/lbm/SolidBody.h"
#include "solvers/lbm/UnitConversion.h"

namespace fluidviz::lbm {

/// One side of the box in lattice units.
struct SideCondition {
  enum class Type { Wall, MovingWall, Periodic };
  Type type = Type::Wall;
  double ux = 0.0;  ///< lattice velocity of a moving wall
  double uy = 0.0;
};

struct BoxSides {
  SideCondition xMin, xMax, yMin, yMax;
  /// From the scene parameters (wall velocities converted with u.dt / u.dx).
  static BoxSides fromParams(const WallsParams& w, const LatticeUnits& u);
};

struct BulkRun {
  std::int64_t begin;  ///< first node (flat index j nx + i)
  std::int64_t end;    ///< one past the last node, same row
};

struct BoundaryNode {
  std::int64_t node;                               ///< flat index j nx + i
  std::array<PullLink, LatticeD2Q9::Q> links;  ///< where each incoming population comes from
};

/// Work of one row: index ranges into runs() and boundaryNodes().
struct RowPlan {
  std::int64_t runBegin, runEnd;
  std::int64_t boundaryBegin, boundaryEnd;
};

class BoundaryLinkTable {
 public:
  using L = LatticeD2Q9;

  /// stride: doubles between population planes (PopulationArrays::stride()).
  BoundaryLinkTable(const LatticeUnits& units, const BoxSides& sides,
                    const std::vector<SolidBody>& bodies, std::int64_t stride);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  std::int64_t stride() const { return stride_; }
  /// Offset n - (n - c_q) of the neighbour a bulk node pulls population q from: cx + cy nx.
  std::int64_t bulkOffset(int q) const { return L::cx[q] + std::int64_t(L::cy[q]) * nx_; }

  /// Index of the body owning each node (x fastest), -1 for fluid nodes.
  const std::vector<std::int16_t>& solidOwner() const { return solidOwner_; }
  bool isSolid(std::int64_t node) const { return solidOwner_[node] >= 0; }
  const std::vector<RowPlan>& rows() const { return rows_; }
  const std::vector<BulkRun>& runs() const { return runs_; }
  const std::vector<BoundaryNode>& boundaryNodes() const { return boundary_; }
  std::int64_t fluidNodeCount() const { return fluidNodes_; }

 private:
  /// The pull rule of population q at fluid node (i, j); `plain` = ordinary bulk neighbour.
  PullLink linkOf(int i, int j, int q, bool& plain) const;
  PullLink sideLink(std::int64_t node, int q, bool crossesX, bool crossesY, int si, int sj) const;
  PullLink bodyLink(std::int64_t node, int si, int sj, int q, int body) const;
  void markSolidNodes(const std::vector<SolidBody>& bodies);
  void buildRows();

  int nx_, ny_;
  std::int64_t stride_;
  double dx_, velocityScale_;  ///< m per cell, lattice velocity per m/s
  BoxSides sides_;
  const std::vector<SolidBody>* bodies_ = nullptr;  ///< only during construction
  std::vector<std::int16_t> solidOwner_;
  std::vector<RowPlan> rows_;
  std::vector<BulkRun> runs_;
  std::vector<BoundaryNode> boundary_;
  std::int64_t fluidNodes_ = 0;
};

}  // namespace fluidviz::lbm
