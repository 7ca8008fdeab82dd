#pragma once
// Precomputed boundary data of the pull scheme, for a 2D (nz = 1) or 3D lattice L. Nodes are
// numbered n = (k ny + j) nx + i; a "row" is one (j, k) line of nx nodes. Every fluid node is
//  - in a run: a stretch of consecutive nodes of a row that all pull population q from the same
//    relative position, source = pattern.source[q] + n, plus the same moving-wall momentum
//    pattern.delta[q]. Pattern 0 is the bulk (all neighbours n - c_q inside, delta 0); the nodes
//    of a row next to a flat side (wall, moving wall, periodic wrap) share another pattern, so
//    they are vectorised like the bulk (without this, the boundary rows of a 128^3 D3Q19 box --
//    5 % of its nodes -- took 40 % of a step). The kernel pulls with fixed offsets and no
//    per-direction branch; or
//  - a boundary node: a link ends in a solid body, is replaced by a Bouzidi interpolation, or
//    the node lies on an open (Zou-He) side; its Q PullLinks (source index + moving-wall
//    momentum) are stored explicitly, plus the interpolated links and the open side.
// Solid nodes (centre inside a SolidBody) are in neither list and are never updated.
//
#include <array>
#include <cstdint>
#include <vector>

#include "solvers/lbm/boundaries/BouzidiInterpolatedBounceBack.h"
#include "solvers/lbm/boundaries/BoxSides.h"
#include "solvers/lbm/boundaries/SolidBody.h"
#include "solvers/lbm/boundaries/ZouHeVelocityInlet.h"
#include "solvers/lbm/kernel/PullLink.h"
#include "solvers/lbm/lattice/UnitConversion.h"

namespace fluidviz::lbm {

struct BulkRun {
  std::int64_t begin;    ///< first node (flat index)
  std::int64_t end;      ///< one past the last node, same row
  std::int32_t pattern;  ///< index into runPatterns(); 0 = bulk
};

/// The pull rule shared by the nodes of a run: f_q(n) = post[source[q] + n] + delta[q].
template <int Q>
struct RunPattern {
  std::array<std::int64_t, Q> source{};
  std::array<double, Q> delta{};
  bool hasDelta = false;  ///< any delta != 0 (moving wall)
  /// Bit q: link q reads another population's plane (bounce-back). Its source is the wall
  /// node's own outgoing value, which no bulk load of nearby rows brings into the cache.
  std::uint32_t reflected = 0;
};

template <int Q>
struct BoundaryNode {
  std::int64_t node;                ///< flat index (k ny + j) nx + i
  std::array<PullLink, Q> links;    ///< where each incoming population comes from
  std::int32_t interpolatedBegin = 0;  ///< range in interpolatedLinks() replacing some links
  std::int32_t interpolatedEnd = 0;
  std::int8_t openSide = -1;  ///< side index (BoxSides) of the Zou-He side the node lies on, or -1
  double inletFactor = 1.0;   ///< velocity inlet: the side's profile here (inletProfileFactor)
};

/// A link from a boundary node into a solid body: population q of node boundaryNodes()[boundary]
/// comes back from the body (bounce-back or Bouzidi). The momentum-exchange force sums over these
/// (LbmSolverImpl::bodyForces); the kernel never reads them.
struct BodyLink {
  std::int32_t boundary;  ///< index into boundaryNodes()
  std::int16_t body;      ///< index of the body
  std::int8_t q;          ///< incoming population; the link points along -c_q into the body
};

/// Work of one row: index ranges into runs() and boundaryNodes().
struct RowPlan {
  std::int64_t runBegin, runEnd;
  std::int64_t boundaryBegin, boundaryEnd;
};

/// The part of the lattice a table covers. The serial solver's table covers it whole
/// (wholeLattice). A rank of an MPI run (issue 18, solvers/lbm/parallel/HaloPlan.h) covers its
/// block plus a ghost layer: nodes keep local indices (so the kernel is unchanged) while every
/// geometric decision -- solid nodes, which side of the box a link crosses, open sides, inlet
/// profiles, Bouzidi wall fractions -- uses the global node, local + offset, wrapped across
/// periodic sides. Ghost nodes (outside [ownedLo, ownedHi)) are in no run and no boundary list:
/// never updated, only pulled from, like a periodic neighbour in serial.
struct TableExtent {
  std::array<int, 3> localDims{1, 1, 1};
  std::array<int, 3> globalDims{1, 1, 1};
  std::array<int, 3> offset{0, 0, 0};  ///< global index of local node (0, 0, 0), before wrapping
  std::array<int, 3> ownedLo{0, 0, 0};  ///< local index of the first owned node per axis
  std::array<int, 3> ownedHi{1, 1, 1};  ///< one past the last owned node
  static TableExtent wholeLattice(int nx, int ny, int nz) {
    return {{nx, ny, nz}, {nx, ny, nz}, {0, 0, 0}, {0, 0, 0}, {nx, ny, nz}};
  }
};

template <class L>
class BoundaryLinkTable {
 public:
  using Node = BoundaryNode<L::Q>;

  /// stride: values between population planes (PopulationArrays::stride()).
  BoundaryLinkTable(const LatticeUnits& units, const BoxSides& sides,
                    const std::vector<SolidBody>& bodies, std::int64_t stride);
  /// The table of one part of the lattice (TableExtent); extent.globalDims must be the units'.
  BoundaryLinkTable(const LatticeUnits& units, const BoxSides& sides,
                    const std::vector<SolidBody>& bodies, std::int64_t stride,
                    const TableExtent& extent);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  int rowCount() const { return ny_ * nz_; }
  std::int64_t stride() const { return stride_; }
  const BoxSides& sides() const { return sides_; }
  /// Offset n - (n - c_q) of the neighbour a bulk node pulls population q from.
  std::int64_t bulkOffset(int q) const {
    return L::cx[q] + std::int64_t(L::cy[q]) * nx_ + std::int64_t(L::cz[q]) * nx_ * ny_;
  }

  /// Index of the body owning each node (x fastest), -1 for fluid nodes.
  const std::vector<std::int16_t>& solidOwner() const { return solidOwner_; }
  bool isSolid(std::int64_t node) const { return solidOwner_[node] >= 0; }
  const std::vector<RowPlan>& rows() const { return rows_; }
  const std::vector<BulkRun>& runs() const { return runs_; }
  const std::vector<RunPattern<L::Q>>& runPatterns() const { return patterns_; }
  const std::vector<Node>& boundaryNodes() const { return boundary_; }
  const std::vector<InterpolatedLink>& interpolatedLinks() const { return interpolated_; }
  const std::vector<BodyLink>& bodyLinks() const { return bodyLinks_; }
  std::int64_t fluidNodeCount() const { return fluidNodes_; }  ///< owned fluid nodes
  const TableExtent& extent() const { return extent_; }

 private:
  /// Global index of local (i, j, k) along axis a, wrapped across a periodic side.
  int globalAlong(int a, int local) const;
  bool owned(int i, int j, int k) const;
  /// Where population q of local node n comes from: false if the link crosses a non-periodic
  /// side of the box (crossing[] then says which); else the local source node in `source` (a
  /// ghost, or in serial the node wrapped across a periodic side).
  bool sourceOf(const int (&n)[3], int q, int (&source)[3], int (&crossing)[3]) const;
  /// The pull rule of population q at fluid node (i, j, k); `plain` = ordinary bulk neighbour.
  PullLink linkOf(int i, int j, int k, int q, bool& plain, Node& node);
  PullLink sideLink(std::int64_t node, int q, const int (&crossing)[3]) const;
  /// fluid, solid: global ends of the link (solid wrapped); fluidLocal: the fluid end locally.
  PullLink bodyLink(std::int64_t node, const int (&fluid)[3], const int (&solid)[3],
                    const int (&fluidLocal)[3], int q, int body, Node& boundaryNode);
  /// True if no link of (i, j, k) crosses a side or ends in a solid node (then it is bulk,
  /// unless it lies on an open side, which needs a side to be crossed anyway).
  bool interiorWithFluidNeighbours(int i, int j, int k) const;
  void markSolidNodes(const std::vector<SolidBody>& bodies);
  /// Index of the pattern of these links (added if new).
  std::int32_t patternOf(const Node& b);
  void buildRows();

  int nx_, ny_, nz_;  ///< local dims (the whole lattice in serial)
  TableExtent extent_;
  std::int64_t stride_;
  double dx_, velocityScale_;  ///< m per cell, lattice velocity per m/s
  BoxSides sides_;
  const std::vector<SolidBody>* bodies_ = nullptr;  ///< only during construction
  std::vector<std::int16_t> solidOwner_;
  std::vector<RowPlan> rows_;
  std::vector<BulkRun> runs_;
  std::vector<RunPattern<L::Q>> patterns_;
  std::vector<Node> boundary_;
  std::vector<InterpolatedLink> interpolated_;
  std::vector<BodyLink> bodyLinks_;
  std::int64_t fluidNodes_ = 0;
};

}  // namespace fluidviz::lbm
