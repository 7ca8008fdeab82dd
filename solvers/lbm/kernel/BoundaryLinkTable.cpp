#include "solvers/lbm/kernel/BoundaryLinkTable.h"

#include <stdexcept>

#include "solvers/lbm/boundaries/BounceBackWall.h"
#include "solvers/lbm/boundaries/MovingWallBounceBack.h"
#include "solvers/lbm/boundaries/PeriodicBoundary.h"
#include "solvers/lbm/lattice/LatticeD2Q9.h"
#include "solvers/lbm/lattice/LatticeD3Q19.h"

namespace fluidviz::lbm {

template <class L>
BoundaryLinkTable<L>::BoundaryLinkTable(const LatticeUnits& units, const BoxSides& sides,
                                        const std::vector<SolidBody>& bodies, std::int64_t stride)
    : BoundaryLinkTable(units, sides, bodies, stride,
                        TableExtent::wholeLattice(units.nx, units.ny, L::D == 3 ? units.nz : 1)) {}

template <class L>
BoundaryLinkTable<L>::BoundaryLinkTable(const LatticeUnits& units, const BoxSides& sides,
                                        const std::vector<SolidBody>& bodies, std::int64_t stride,
                                        const TableExtent& extent)
    : nx_(extent.localDims[0]),
      ny_(extent.localDims[1]),
      nz_(extent.localDims[2]),
      extent_(extent),
      stride_(stride),
      dx_(units.dx),
      velocityScale_(units.dt / units.dx),
      sides_(sides) {
  if (bodies.size() > 32000) throw std::invalid_argument("BoundaryLinkTable: too many bodies");
  const std::array<int, 3> global{units.nx, units.ny, L::D == 3 ? units.nz : 1};
  if (extent.globalDims != global)
    throw std::invalid_argument("BoundaryLinkTable: the extent's global dims are not the lattice's");
  bodies_ = &bodies;
  markSolidNodes(bodies);
  buildRows();
  bodies_ = nullptr;
}

template <class L>
int BoundaryLinkTable<L>::globalAlong(int a, int local) const {
  const int n = extent_.globalDims[a], g = local + extent_.offset[a];
  return sides_.periodic(a) ? (g % n + n) % n : g;
}

template <class L>
bool BoundaryLinkTable<L>::owned(int i, int j, int k) const {
  const int n[3] = {i, j, k};
  for (int a = 0; a < 3; ++a)
    if (n[a] < extent_.ownedLo[a] || n[a] >= extent_.ownedHi[a]) return false;
  return true;
}

template <class L>
bool BoundaryLinkTable<L>::sourceOf(const int (&n)[3], int q, int (&source)[3],
                                    int (&crossing)[3]) const {
  const int c[3] = {L::cx[q], L::cy[q], L::cz[q]};
  const int local[3] = {nx_, ny_, nz_};
  bool crosses = false;
  for (int a = 0; a < 3; ++a) {
    const int g = globalAlong(a, n[a]) - c[a];
    crossing[a] = 0;
    if ((g < 0 || g >= extent_.globalDims[a]) && !sides_.periodic(a)) {
      crossing[a] = g < 0 ? -1 : 1;
      crosses = true;
    }
    // Out of the local array only across a periodic side of a table without ghosts (serial).
    source[a] = wrapPeriodic(n[a] - c[a], local[a]);
  }
  return !crosses;
}

template <class L>
void BoundaryLinkTable<L>::markSolidNodes(const std::vector<SolidBody>& bodies) {
  const std::size_t layer = static_cast<std::size_t>(nx_) * ny_;
  solidOwner_.assign(layer * nz_, -1);
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const Vec2 p((globalAlong(0, i) + 0.5) * dx_, (globalAlong(1, j) + 0.5) * dx_);
      for (std::size_t b = 0; b < bodies.size(); ++b)
        if (bodies[b].contains(p)) {
          solidOwner_[std::size_t(j) * nx_ + i] = static_cast<std::int16_t>(b);
          break;
        }
    }
  for (int k = 1; k < nz_; ++k)  // bodies are extruded along z
    std::copy_n(solidOwner_.begin(), layer, solidOwner_.begin() + k * layer);
}

template <class L>
PullLink BoundaryLinkTable<L>::sideLink(std::int64_t node, int q, const int (&crossing)[3]) const {
  double u[3] = {0.0, 0.0, 0.0};
  bool moving = false;
  for (int a = 0; a < 3; ++a) {
    if (crossing[a] == 0) continue;
    const SideCondition& s = sides_.side[2 * a + (crossing[a] > 0 ? 1 : 0)];
    if (s.type != SideCondition::Type::MovingWall) continue;  // rest, or an open side's placeholder
    moving = true;
    for (int b = 0; b < 3; ++b) u[b] += s.velocity[b];
  }
  return moving ? movingWallLink<L>(node, q, stride_, u[0], u[1], u[2])
                : bounceBackLink<L>(node, q, stride_);
}

template <class L>
PullLink BoundaryLinkTable<L>::bodyLink(std::int64_t node, const int (&fluid)[3],
                                        const int (&solid)[3], const int (&fluidLocal)[3], int q,
                                        int body, Node& boundaryNode) {
  const SolidBody& b = (*bodies_)[body];
  const int c[3] = {L::cx[q], L::cy[q], L::cz[q]};
  // Positions taken from the solid end so that a link wrapped by a periodic side stays in the
  // body's frame: the fluid end is solid + c_q.
  const Vec2 solidEnd((solid[0] + 0.5) * dx_, (solid[1] + 0.5) * dx_);
  const Vec2 fluidEnd = solidEnd + Vec2(c[0], c[1]) * dx_;
  // Staircase: wall velocity at the link mid-point, where halfway bounce-back puts the wall.
  const Vec2 uMid = b.velocity(0.5 * (solidEnd + fluidEnd)) * velocityScale_;
  const PullLink staircase = movingWallLink<L>(node, q, stride_, uMid.x(), uMid.y(), 0.0);
  if (!b.interpolated) return staircase;

  const double qw = wallFraction(b, fluidEnd, solidEnd);
  const Vec2 uWall = b.velocity(fluidEnd + qw * (solidEnd - fluidEnd)) * velocityScale_;
  // Second node x_f + c_q (away from the wall), if it is a fluid node: inside the box (global
  // index), then found locally (a ghost, or wrapped in a table without ghosts).
  std::int64_t second = -1;
  int s[3];
  const int local[3] = {nx_, ny_, nz_};
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    const int g = fluid[a] + c[a];
    if ((g < 0 || g >= extent_.globalDims[a]) && !sides_.periodic(a)) inside = false;
    s[a] = wrapPeriodic(fluidLocal[a] + c[a], local[a]);
  }
  if (inside) {
    const std::int64_t n2 = (std::int64_t(s[2]) * ny_ + s[1]) * nx_ + s[0];
    if (solidOwner_[n2] < 0) second = n2;
  }
  interpolated_.push_back(bouzidiLink(q, L::opposite[q], node, second, stride_, qw,
                                      movingWallDelta<L>(q, uWall.x(), uWall.y(), 0.0)));
  boundaryNode.interpolatedEnd = static_cast<std::int32_t>(interpolated_.size());
  return staircase;
}

template <class L>
PullLink BoundaryLinkTable<L>::linkOf(int i, int j, int k, int q, bool& plain, Node& node) {
  const int n[3] = {i, j, k};
  int s[3], crossing[3];
  const std::int64_t self = (std::int64_t(k) * ny_ + j) * nx_ + i;
  plain = sourceOf(n, q, s, crossing);
  if (!plain) return sideLink(self, q, crossing);
  const std::int64_t source = (std::int64_t(s[2]) * ny_ + s[1]) * nx_ + s[0];
  if (solidOwner_[source] >= 0) {
    plain = false;
    // The node becomes boundary_.size(): a link into a body makes it a boundary node (buildRows).
    bodyLinks_.push_back({static_cast<std::int32_t>(boundary_.size()), solidOwner_[source],
                          static_cast<std::int8_t>(q)});
    // Global positions of both ends: the solid one wrapped across a periodic side, so that the
    // link stays in the body's frame (bodyLink).
    const int fluid[3] = {globalAlong(0, i), globalAlong(1, j), globalAlong(2, k)};
    const int solid[3] = {globalAlong(0, s[0]), globalAlong(1, s[1]), globalAlong(2, s[2])};
    return bodyLink(self, fluid, solid, n, q, solidOwner_[source], node);
  }
  return {q * stride_ + source, 0.0};
}

template <class L>
bool BoundaryLinkTable<L>::interiorWithFluidNeighbours(int i, int j, int k) const {
  if (i < 1 || i > nx_ - 2 || j < 1 || j > ny_ - 2) return false;
  if (L::D == 3 && (k < 1 || k > nz_ - 2)) return false;
  const std::int64_t node = (std::int64_t(k) * ny_ + j) * nx_ + i;
  for (int q = 1; q < L::Q; ++q)
    if (solidOwner_[node - bulkOffset(q)] >= 0) return false;
  return true;
}

template <class L>
std::int32_t BoundaryLinkTable<L>::patternOf(const Node& b) {
  RunPattern<L::Q> p;
  for (int q = 0; q < L::Q; ++q) {
    p.source[q] = b.links[q].source - b.node;
    p.delta[q] = b.links[q].delta;
    p.hasDelta |= b.links[q].delta != 0.0;
    if (b.links[q].source / stride_ != q) p.reflected |= std::uint32_t(1) << q;
  }
  for (std::size_t k = 0; k < patterns_.size(); ++k)
    if (patterns_[k].source == p.source && patterns_[k].delta == p.delta)  // reflected follows from source
      return static_cast<std::int32_t>(k);
  patterns_.push_back(p);
  return static_cast<std::int32_t>(patterns_.size() - 1);
}

template <class L>
void BoundaryLinkTable<L>::buildRows() {
  rows_.resize(static_cast<std::size_t>(ny_) * nz_);
  const int globalDims[3] = {extent_.globalDims[0], extent_.globalDims[1], extent_.globalDims[2]};
  RunPattern<L::Q> bulk;  // pattern 0
  for (int q = 0; q < L::Q; ++q) bulk.source[q] = q * stride_ - bulkOffset(q);
  patterns_.assign(1, bulk);
  for (int k = 0; k < nz_; ++k)
    for (int j = 0; j < ny_; ++j) {
      RowPlan& row = rows_[std::size_t(k) * ny_ + j];
      row.runBegin = static_cast<std::int64_t>(runs_.size());
      row.boundaryBegin = static_cast<std::int64_t>(boundary_.size());
      std::int32_t current = -1;  // pattern of the run being extended, -1: none
      for (int i = 0; i < nx_; ++i) {
        const std::int64_t node = (std::int64_t(k) * ny_ + j) * nx_ + i;
        std::int32_t pattern = -1;
        if (isSolid(node) || !owned(i, j, k)) {
          // not a fluid node, or a ghost (never updated)
        } else if (interiorWithFluidNeighbours(i, j, k)) {  // the common case, decided fast
          ++fluidNodes_;
          pattern = 0;
        } else {
          ++fluidNodes_;
          Node b{node, {}};
          b.interpolatedBegin = b.interpolatedEnd = static_cast<std::int32_t>(interpolated_.size());
          const int n[3] = {i, j, k};
          const int g[3] = {globalAlong(0, i), globalAlong(1, j), globalAlong(2, k)};
          for (int a = 0; a < L::D; ++a) {
            if (g[a] == 0 && sides_.side[2 * a].isOpen()) b.openSide = static_cast<std::int8_t>(2 * a);
            if (g[a] == globalDims[a] - 1 && sides_.side[2 * a + 1].isOpen())
              b.openSide = static_cast<std::int8_t>(2 * a + 1);
          }
          if (b.openSide >= 0)
            b.inletFactor =
                inletProfileFactor(sides_.side[b.openSide], b.openSide / 2, g, globalDims);
          for (int q = 0; q < L::Q; ++q) {
            bool plain = false;
            b.links[q] = linkOf(i, j, k, q, plain, b);
          }
          // Links into bodies (and open sides, interpolations) differ node by node: explicit.
          bool touchesBody = b.interpolatedEnd > b.interpolatedBegin;
          for (int q = 0; q < L::Q && !touchesBody; ++q) {
            int w[3], crossing[3];
            if (sourceOf(n, q, w, crossing) &&
                solidOwner_[(std::int64_t(w[2]) * ny_ + w[1]) * nx_ + w[0]] >= 0)
              touchesBody = true;
          }
          if (touchesBody || b.openSide >= 0)
            boundary_.push_back(b);
          else
            pattern = patternOf(b);
        }
        if (pattern >= 0 && pattern == current) {
          runs_.back().end = node + 1;
        } else if (pattern >= 0) {
          runs_.push_back({node, node + 1, pattern});
        }
        current = pattern;
      }
      row.runEnd = static_cast<std::int64_t>(runs_.size());
      row.boundaryEnd = static_cast<std::int64_t>(boundary_.size());
    }
}

template class BoundaryLinkTable<LatticeD2Q9>;
template class BoundaryLinkTable<LatticeD3Q19>;

}  // namespace fluidviz::lbm
