#include "solvers/lbm/BoundaryLinkTable.h"

#include <stdexcept>

#include "solvers/lbm/BounceBackWall.h"
#include "solvers/lbm/MovingWallBounceBack.h"
#include "solvers/lbm/PeriodicBoundary.h"

namespace fluidviz::lbm {

namespace {

SideCondition sideFromParams(const WallParams& w, const LatticeUnits& u) {
  SideCondition s;
  if (w.type == "periodic") s.type = SideCondition::Type::Periodic;
  if (w.type == "moving_wall") {
    s.type = SideCondition::Type::MovingWall;
    s.ux = u.toLatticeVelocity(w.velocity[0]);
    s.uy = u.toLatticeVelocity(w.velocity[1]);
  }
  return s;
}

}  // namespace

BoxSides BoxSides::fromParams(const WallsParams& w, const LatticeUnits& u) {
  return {sideFromParams(w.x_min, u), sideFromParams(w.x_max, u), sideFromParams(w.y_min, u),
          sideFromParams(w.y_max, u)};
}

BoundaryLinkTable::BoundaryLinkTable(const LatticeUnits& units, const BoxSides& sides,
                                     const std::vector<SolidBody>& bodies, std::int64_t stride)
    : nx_(units.nx),
      ny_(units.ny),
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

void BoundaryLinkTable::markSolidNodes(const std::vector<SolidBody>& bodies) {
  solidOwner_.assign(static_cast<std::size_t>(nx_) * ny_, -1);
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const Vec2 p((i + 0.5) * dx_, (j + 0.5) * dx_);
      for (std::size_t b = 0; b < bodies.size(); ++b)
        if (bodies[b].contains(p)) {
          solidOwner_[std::size_t(j) * nx_ + i] = static_cast<std::int16_t>(b);
          break;
        }
    }
}

PullLink BoundaryLinkTable::sideLink(std::int64_t node, int q, bool crossesX, bool crossesY, int si,
                                     int sj) const {
  double ux = 0.0, uy = 0.0;
  bool moving = false;
  auto add = [&](const SideCondition& s) {
    moving |= s.type == SideCondition::Type::MovingWall;
    ux += s.ux;
    uy += s.uy;
  };
  if (crossesX) add(si < 0 ? sides_.xMin : sides_.xMax);
  if (crossesY) add(sj < 0 ? sides_.yMin : sides_.yMax);
  return moving ? movingWallLink<L>(node, q, stride_, ux, uy) : bounceBackLink<L>(node, q, stride_);
}

PullLink BoundaryLinkTable::bodyLink(std::int64_t node, int si, int sj, int q, int body) const {
  // Wall velocity at the link mid-point, where halfway bounce-back puts the wall; taken from the
  // solid end (si, sj) + c_q / 2 so that a link wrapped by a periodic side stays in the body's
  // frame.
  const Vec2 mid((si + 0.5 + 0.5 * L::cx[q]) * dx_, (sj + 0.5 + 0.5 * L::cy[q]) * dx_);
  const Vec2 u = (*bodies_)[body].velocity(mid) * velocityScale_;
  return movingWallLink<L>(node, q, stride_, u.x(), u.y());
}

PullLink BoundaryLinkTable::linkOf(int i, int j, int q, bool& plain) const {
  const std::int64_t node = std::int64_t(j) * nx_ + i;
  int si = i - L::cx[q], sj = j - L::cy[q];
  bool crossesX = si < 0 || si >= nx_, crossesY = sj < 0 || sj >= ny_;
  plain = !crossesX && !crossesY;
  if (crossesX && sides_.xMin.type == SideCondition::Type::Periodic) {
    si = wrapPeriodic(si, nx_);
    crossesX = false;
  }
  if (crossesY && sides_.yMin.type == SideCondition::Type::Periodic) {
    sj = wrapPeriodic(sj, ny_);
    crossesY = false;
  }
  if (crossesX || crossesY) {
    plain = false;
    return sideLink(node, q, crossesX, crossesY, i - L::cx[q], j - L::cy[q]);
  }
  const std::int64_t source = std::int64_t(sj) * nx_ + si;
  if (solidOwner_[source] >= 0) {
    plain = false;
    return bodyLink(node, si, sj, q, solidOwner_[source]);
  }
  return {q * stride_ + source, 0.0};
}

void BoundaryLinkTable::buildRows() {
  rows_.resize(ny_);
  for (int j = 0; j < ny_; ++j) {
    RowPlan& row = rows_[j];
    row.runBegin = static_cast<std::int64_t>(runs_.size());
    row.boundaryBegin = static_cast<std::int64_t>(boundary_.size());
    bool inRun = false;
    for (int i = 0; i < nx_; ++i) {
      const std::int64_t node = std::int64_t(j) * nx_ + i;
      bool bulk = !isSolid(node);
      if (bulk) {
        ++fluidNodes_;
        BoundaryNode b{node, {}};
        for (int q = 0; q < L::Q; ++q) {
          bool plain = false;
          b.links[q] = linkOf(i, j, q, plain);
          bulk &= plain;
        }
        if (!bulk) boundary_.push_back(b);
      }
      if (bulk && !inRun) runs_.push_back({node, node + 1});
      if (bulk) runs_.back().end = node + 1;
      inRun = bulk;
    }
    row.runEnd = static_cast<std::int64_t>(runs_.size());
    row.boundaryEnd = static_cast<std::int64_t>(boundary_.size());
  }
}

}  // namespace fluidviz::lbm
