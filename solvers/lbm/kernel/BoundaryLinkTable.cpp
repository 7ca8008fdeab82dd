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
    : nx_(units.nx),
      ny_(units.ny),
      nz_(L::D == 3 ? units.nz : 1),
      stride_(stride),
      dx_(units.dx),
      velocityScale_(units.dt / units.dx),
      sides_(sides) {
  if (bodies.size() > 32000) throw std::invalid_argument("BoundaryLinkTable: too many bodies");
  bodies_ = &bodies;
  markSolidNodes(bodies);
  buildRows();
  bodies_ = nullptr;
}

template <class L>
void BoundaryLinkTable<L>::markSolidNodes(const std::vector<SolidBody>& bodies) {
  const std::size_t layer = static_cast<std::size_t>(nx_) * ny_;
  solidOwner_.assign(layer * nz_, -1);
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const Vec2 p((i + 0.5) * dx_, (j + 0.5) * dx_);
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
                                        const int (&solid)[3], int q, int body,
                                        Node& boundaryNode) {
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
  // Second node x_f + c_q (away from the wall), if it is a fluid node.
  std::int64_t second = -1;
  int s[3] = {fluid[0] + c[0], fluid[1] + c[1], fluid[2] + c[2]};
  const int dims[3] = {nx_, ny_, nz_};
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    if (s[a] >= 0 && s[a] < dims[a]) continue;
    if (sides_.periodic(a))
      s[a] = wrapPeriodic(s[a], dims[a]);
    else
      inside = false;
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
  const int n[3] = {i, j, k}, c[3] = {L::cx[q], L::cy[q], L::cz[q]};
  const int dims[3] = {nx_, ny_, nz_};
  int s[3], crossing[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    s[a] = n[a] - c[a];
    crossing[a] = s[a] < 0 ? -1 : (s[a] >= dims[a] ? 1 : 0);
  }
  plain = crossing[0] == 0 && crossing[1] == 0 && crossing[2] == 0;
  bool crosses = false;
  for (int a = 0; a < 3; ++a) {
    if (crossing[a] != 0 && sides_.periodic(a)) {
      s[a] = wrapPeriodic(s[a], dims[a]);
      crossing[a] = 0;
    }
    crosses |= crossing[a] != 0;
  }
  const std::int64_t self = (std::int64_t(k) * ny_ + j) * nx_ + i;
  if (crosses) return sideLink(self, q, crossing);
  const std::int64_t source = (std::int64_t(s[2]) * ny_ + s[1]) * nx_ + s[0];
  if (solidOwner_[source] >= 0) {
    plain = false;
    // The node becomes boundary_.size(): a link into a body makes it a boundary node (buildRows).
    bodyLinks_.push_back({static_cast<std::int32_t>(boundary_.size()), solidOwner_[source],
                          static_cast<std::int8_t>(q)});
    return bodyLink(self, n, s, q, solidOwner_[source], node);
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
  const int dims[3] = {nx_, ny_, nz_};
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
        if (isSolid(node)) {
          // not a fluid node
        } else if (interiorWithFluidNeighbours(i, j, k)) {  // the common case, decided fast
          ++fluidNodes_;
          pattern = 0;
        } else {
          ++fluidNodes_;
          Node b{node, {}};
          b.interpolatedBegin = b.interpolatedEnd = static_cast<std::int32_t>(interpolated_.size());
          const int n[3] = {i, j, k};
          for (int a = 0; a < L::D; ++a) {
            if (n[a] == 0 && sides_.side[2 * a].isOpen()) b.openSide = static_cast<std::int8_t>(2 * a);
            if (n[a] == dims[a] - 1 && sides_.side[2 * a + 1].isOpen())
              b.openSide = static_cast<std::int8_t>(2 * a + 1);
          }
          if (b.openSide >= 0)
            b.inletFactor = inletProfileFactor(sides_.side[b.openSide], b.openSide / 2, n, dims);
          for (int q = 0; q < L::Q; ++q) {
            bool plain = false;
            b.links[q] = linkOf(i, j, k, q, plain, b);
          }
          // Links into bodies (and open sides, interpolations) differ node by node: explicit.
          bool touchesBody = b.interpolatedEnd > b.interpolatedBegin;
          for (int q = 0; q < L::Q && !touchesBody; ++q) {
            const int s3[3] = {i - L::cx[q], j - L::cy[q], k - L::cz[q]};
            bool crosses = false;
            int w[3];
            for (int a = 0; a < 3; ++a) {
              w[a] = s3[a];
              if (w[a] < 0 || w[a] >= dims[a]) {
                if (sides_.periodic(a))
                  w[a] = wrapPeriodic(w[a], dims[a]);
                else
                  crosses = true;
              }
            }
            if (!crosses && solidOwner_[(std::int64_t(w[2]) * ny_ + w[1]) * nx_ + w[0]] >= 0)
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
