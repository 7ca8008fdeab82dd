#pragma once
// Precomputed boundary data of the pull scheme, for a 2D (nz = 1) or 3D lattice L. Nodes are
// numbered n = (k ny + j) nx + i; a "row" is one (j, k) line of nx nodes. Every fluid node is
//  - bulk: all Q neighbours n - c_q are fluid nodes inside the box (no wrap), so the kernel pulls
//    with fixed offsets and no per-direction branch; consecutive bulk nodes of a row form a
//    BulkRun, or
//  - boundary: at least one link crosses a side (wall, moving wall, periodic wrap, open side) or
//    ends in a solid body; its Q PullLinks (source index + moving-wall momentum) are stored
//    explicitly, plus the links a Bouzidi interpolation replaces and the open side (Zou-He) the
//    node lies on, if any.
// Solid nodes (centre inside a SolidBody) are in neither list and are never updated.
//
// Links through an edge or corner (crossing two or three sides at once) see the sum of the sides'
// tangential velocities: with one side at rest that is the moving side's velocity, which keeps
// the Ladd momentum terms of a sliding lid summing to zero (exact mass conservation). On an open
// side the links from outside are placeholders (halfway bounce-back) that the Zou-He closure
// replaces; they keep every source used exactly once, which initialise() relies on.
#include <array>
#include <cstdint>
#include <vector>

#include "solvers/lbm/BouzidiInterpolatedBounceBack.h"
#include "solvers/lbm/PullLink.h"
#include "solvers/lbm/SolidBody.h"
#include "solvers/lbm/UnitConversion.h"
#include "solvers/lbm/ZouHeVelocityInlet.h"

namespace fluidviz::lbm {

/// One side of the box in lattice units.
struct SideCondition {
  enum class Type { Wall, MovingWall, Periodic, VelocityInlet, Pressure };
  Type type = Type::Wall;
  std::array<double, 3> velocity{0.0, 0.0, 0.0};  ///< lattice velocity (moving wall, inlet)
  double density = 1.0;                           ///< lattice density (pressure side)
  bool isOpen() const { return type == Type::VelocityInlet || type == Type::Pressure; }
};

/// The six sides, indexed 2 axis + (0 for min, 1 for max): x_min, x_max, y_min, y_max, z_min,
/// z_max. A 2D lattice never crosses the z sides.
struct BoxSides {
  std::array<SideCondition, 6> side;
  const SideCondition& lower(int axis) const { return side[2 * axis]; }
  bool periodic(int axis) const { return side[2 * axis].type == SideCondition::Type::Periodic; }
  /// From the scene parameters (velocities converted with u.dt / u.dx, pressures to densities).
  static BoxSides fromParams(const WallsParams& w, const LatticeUnits& u);
};

struct BulkRun {
  std::int64_t begin;  ///< first node (flat index)
  std::int64_t end;    ///< one past the last node, same row
};

template <int Q>
struct BoundaryNode {
  std::int64_t node;                ///< flat index (k ny + j) nx + i
  std::array<PullLink, Q> links;    ///< where each incoming population comes from
  std::int32_t interpolatedBegin = 0;  ///< range in interpolatedLinks() replacing some links
  std::int32_t interpolatedEnd = 0;
  std::int8_t openSide = -1;  ///< side index (BoxSides) of the Zou-He side the node lies on, or -1
};

/// Work of one row: index ranges into runs() and boundaryNodes().
struct RowPlan {
  std::int64_t runBegin, runEnd;
  std::int64_t boundaryBegin, boundaryEnd;
};

template <class L>
class BoundaryLinkTable {
 public:
  using Node = BoundaryNode<L::Q>;

  /// stride: values between population planes (PopulationArrays::stride()).
  BoundaryLinkTable(const LatticeUnits& units, const BoxSides& sides,
                    const std::vector<SolidBody>& bodies, std::int64_t stride);

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
  const std::vector<Node>& boundaryNodes() const { return boundary_; }
  const std::vector<InterpolatedLink>& interpolatedLinks() const { return interpolated_; }
  std::int64_t fluidNodeCount() const { return fluidNodes_; }

 private:
  /// The pull rule of population q at fluid node (i, j, k); `plain` = ordinary bulk neighbour.
  PullLink linkOf(int i, int j, int k, int q, bool& plain, Node& node);
  PullLink sideLink(std::int64_t node, int q, const int (&crossing)[3]) const;
  PullLink bodyLink(std::int64_t node, const int (&fluid)[3], const int (&solid)[3], int q,
                    int body, Node& boundaryNode);
  /// True if no link of (i, j, k) crosses a side or ends in a solid node (then it is bulk,
  /// unless it lies on an open side, which needs a side to be crossed anyway).
  bool interiorWithFluidNeighbours(int i, int j, int k) const;
  void markSolidNodes(const std::vector<SolidBody>& bodies);
  void buildRows();

  int nx_, ny_, nz_;
  std::int64_t stride_;
  double dx_, velocityScale_;  ///< m per cell, lattice velocity per m/s
  BoxSides sides_;
  const std::vector<SolidBody>* bodies_ = nullptr;  ///< only during construction
  std::vector<std::int16_t> solidOwner_;
  std::vector<RowPlan> rows_;
  std::vector<BulkRun> runs_;
  std::vector<Node> boundary_;
  std::vector<InterpolatedLink> interpolated_;
  std::int64_t fluidNodes_ = 0;
};

}  // namespace fluidviz::lbm
