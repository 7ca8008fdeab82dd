#include "filters/streamlines/EvenlySpacedStreamlines.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::streamlines {

namespace {

// Uniform background grid over the domain's xy box for "is any point within r" queries
// (Jobard & Lefer 1997, section 3.2). Cell size >= every query radius, so 3 x 3 cells suffice.
class PointGrid {
 public:
  struct Entry {
    double x, y;
    int line;
    double arc;  // signed arc length along its line from the seed, cells
  };

  PointGrid(double x0, double y0, double width, double height, double cell)
      : x0_(x0), y0_(y0), cell_(cell) {
    nx_ = std::max(1, static_cast<int>(std::ceil(width / cell)) + 1);
    ny_ = std::max(1, static_cast<int>(std::ceil(height / cell)) + 1);
    cells_.resize(static_cast<std::size_t>(nx_) * ny_);
  }

  void insert(const Entry& e) {
    const std::size_t c = cellOf(e.x, e.y);
    cells_[c].push_back(e);
    log_.push_back(c);
  }
  std::size_t logSize() const { return log_.size(); }
  /// Removes the entries inserted since the log had `size` entries (a rejected line).
  void rollback(std::size_t size) {
    while (log_.size() > size) {
      cells_[log_.back()].pop_back();
      log_.pop_back();
    }
  }

  template <class Pred>
  bool anyWithin(double x, double y, double r, Pred&& counts) const {
    const int ci = column(x), cj = row(y);
    const double r2 = r * r;
    for (int j = std::max(0, cj - 1); j <= std::min(ny_ - 1, cj + 1); ++j)
      for (int i = std::max(0, ci - 1); i <= std::min(nx_ - 1, ci + 1); ++i)
        for (const Entry& e : cells_[static_cast<std::size_t>(j) * nx_ + i]) {
          const double dx = e.x - x, dy = e.y - y;
          if (dx * dx + dy * dy < r2 && counts(e)) return true;
        }
    return false;
  }

 private:
  int column(double x) const {
    return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 1);
  }
  int row(double y) const {
    return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 1);
  }
  std::size_t cellOf(double x, double y) const {
    return static_cast<std::size_t>(row(y)) * nx_ + column(x);
  }

  double x0_, y0_, cell_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<Entry>> cells_;
  std::vector<std::size_t> log_;
};

class JobardLefer {
 public:
  JobardLefer(const VectorField& field, const EvenlySpacedParams& p, StreamlineParams integration)
      : field_(field),
        params_(p),
        tracer_(field, bothWays(std::move(integration))),
        cell_(std::min(field.grid.spacing[0], field.grid.spacing[1])),
        dSep_(p.separating_distance * cell_),
        dTest_(p.test_ratio * dSep_),
        lo_(field.grid.origin[0], field.grid.origin[1], 0.0),
        hi_(field.grid.upperCorner().x(), field.grid.upperCorner().y(), 0.0),
        points_(lo_.x(), lo_.y(), hi_.x() - lo_.x(), hi_.y() - lo_.y(), dSep_) {}

  std::vector<Streamline> run() {
    tryLine(Vec3(0.5 * (lo_.x() + hi_.x()), 0.5 * (lo_.y() + hi_.y()), field_.grid.origin[2]));
    while (lines_.size() < static_cast<std::size_t>(params_.max_lines)) {
      if (!queue_.empty()) {
        const std::size_t id = queue_.front();
        queue_.pop_front();
        seedAlongside(id);
      } else if (!scanForGap()) {
        break;
      }
    }
    return std::move(lines_);
  }

 private:
  static StreamlineParams bothWays(StreamlineParams p) {
    p.direction = TraceDirection::both;
    return p;
  }

  bool inside(const Vec3& p) const {
    return p.x() >= lo_.x() && p.x() <= hi_.x() && p.y() >= lo_.y() && p.y() <= hi_.y();
  }

  // Jobard & Lefer's seed condition: at least d_sep from every point of every line.
  bool validSeed(const Vec3& p) const {
    return inside(p) && !points_.anyWithin(p.x(), p.y(), dSep_, [](const auto&) { return true; });
  }

  bool tryLine(const Vec3& seed) {
    if (lines_.size() >= static_cast<std::size_t>(params_.max_lines) || !validSeed(seed))
      return false;
    const int id = static_cast<int>(lines_.size());
    const std::size_t mark = points_.logSize();
    // Own points more than `lag` cells of arc away count as obstacles (stops spirals); own
    // points within 1.5 d_test of the seed do not, so that a closed orbit can reach its seed
    // and end with closed_loop instead of leaving a gap.
    const double lag = 3.0 * params_.separating_distance;
    const double nearSeed = 1.5 * params_.test_ratio * params_.separating_distance;
    points_.insert({seed.x(), seed.y(), id, 0.0});
    const StopRule tooClose = [&](const StepInfo& s) {
      const double arc = (s.direction == Direction::forward ? 1.0 : -1.0) * s.arc_length;
      const bool blocked =
          points_.anyWithin(s.point.x(), s.point.y(), dTest_, [&](const PointGrid::Entry& e) {
            if (e.line != id) return true;
            return std::abs(e.arc - arc) > lag && std::abs(e.arc) > nearSeed;
          });
      if (!blocked) points_.insert({s.point.x(), s.point.y(), id, arc});
      return blocked;
    };
    Streamline line = tracer_.trace(seed, tooClose);
    if (line.points.size() < 2) {
      points_.rollback(mark);
      return false;
    }
    lines_.push_back(std::move(line));
    queue_.push_back(static_cast<std::size_t>(id));
    return true;
  }

  // Candidates at d_sep on both sides of every point of line `id`.
  void seedAlongside(std::size_t id) {
    const std::vector<Vec3> pts = lines_[id].points;  // copy: lines_ grows while we seed
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Vec3& a = pts[i == 0 ? 0 : i - 1];
      const Vec3& b = pts[std::min(i + 1, pts.size() - 1)];
      Vec3 t(b.x() - a.x(), b.y() - a.y(), 0.0);
      if (t.norm() == 0.0) continue;
      t.normalize();
      const Vec3 n(-t.y(), t.x(), 0.0);
      tryLine(pts[i] + dSep_ * n);
      tryLine(pts[i] - dSep_ * n);
    }
  }

  bool scanForGap() {
    const double h = 0.5 * dSep_;
    for (double y = lo_.y() + 0.5 * h; y <= hi_.y(); y += h)
      for (double x = lo_.x() + 0.5 * h; x <= hi_.x(); x += h)
        if (tryLine(Vec3(x, y, field_.grid.origin[2]))) return true;
    return false;
  }

  const VectorField& field_;
  EvenlySpacedParams params_;
  StreamlineTracer tracer_;
  double cell_, dSep_, dTest_;
  Vec3 lo_, hi_;  // xy corners of the domain (z unused)
  PointGrid points_;
  std::vector<Streamline> lines_;
  std::deque<std::size_t> queue_;
};

}  // namespace

std::vector<Streamline> evenlySpacedStreamlines(const VectorField& field,
                                                const EvenlySpacedParams& params,
                                                const StreamlineParams& integration) {
  params::checkRanges(params);
  if (!field.grid.is2D())
    throw std::invalid_argument("evenly spaced streamlines need a 2D field; '" + field.name +
                                "' has dims[2] = " + std::to_string(field.grid.dims[2]) +
                                " (must be 1)");
  return JobardLefer(field, params, integration).run();
}

}  // namespace fluidviz::streamlines
