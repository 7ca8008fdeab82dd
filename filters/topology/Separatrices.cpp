#include "filters/topology/Separatrices.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fluidviz::topology {

namespace {
using streamlines::StepInfo;
using streamlines::StreamlineTracer;
using streamlines::TerminationReason;

/// The slice as a 2D field for the tracer (a 2D field is used as it is).
VectorField planarCopy(const VectorField& field, int slice) {
  VectorField out{field.name, field.grid, {}};
  out.grid.dims[2] = 1;
  out.grid.origin[2] = field.grid.origin[2] + slice * field.grid.spacing[2];
  out.values.reserve(out.grid.nodeCount());
  for (int j = 0; j < field.grid.dims[1]; ++j)
    for (int i = 0; i < field.grid.dims[0]; ++i) {
      const Vec3& v = field.values[field.grid.index(i, j, slice)];
      out.values.emplace_back(v.x(), v.y(), 0.0);
    }
  return out;
}

/// Critical points bucketed by cell for "which point is within r cells" queries.
class PointLocator {
 public:
  PointLocator(const Grid& g, const std::vector<CriticalPoint>& points, double radius)
      : grid_(g), radius_(radius), size_(std::max(radius, 1.0)) {
    nx_ = static_cast<int>((g.dims[0] - 1) / size_) + 1;
    ny_ = static_cast<int>((g.dims[1] - 1) / size_) + 1;
    buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (int k = 0; k < static_cast<int>(points.size()); ++k) {
      cells_.push_back(toCells(points[k].position));
      buckets_[bucket(cells_.back())].push_back(k);
    }
  }
  Vec2 toCells(const Vec3& p) const {
    return {(p.x() - grid_.origin[0]) / grid_.spacing[0],
            (p.y() - grid_.origin[1]) / grid_.spacing[1]};
  }
  /// Nearest point within `r` cells of world position p, skipping `skip`; -1 if none.
  int nearest(const Vec3& p, double r, int skip = -1) const {
    const Vec2 q = toCells(p);
    int best = -1;
    double bestD = r;
    const int reach = static_cast<int>(std::ceil(r / size_));
    const int bi = static_cast<int>(std::floor(q.x() / size_));
    const int bj = static_cast<int>(std::floor(q.y() / size_));
    for (int j = std::max(0, bj - reach); j <= std::min(ny_ - 1, bj + reach); ++j)
      for (int i = std::max(0, bi - reach); i <= std::min(nx_ - 1, bi + reach); ++i)
        for (int k : buckets_[static_cast<std::size_t>(j) * nx_ + i]) {
          const double d = (cells_[k] - q).norm();
          if (k != skip && d <= bestD) {
            best = k;
            bestD = d;
          }
        }
    return best;
  }
  double radius() const { return radius_; }

 private:
  std::size_t bucket(const Vec2& q) const {
    const int i = std::clamp(static_cast<int>(std::floor(q.x() / size_)), 0, nx_ - 1);
    const int j = std::clamp(static_cast<int>(std::floor(q.y() / size_)), 0, ny_ - 1);
    return static_cast<std::size_t>(j) * nx_ + i;
  }
  const Grid& grid_;
  double radius_, size_;
  int nx_ = 0, ny_ = 0;
  std::vector<Vec2> cells_;
  std::vector<std::vector<int>> buckets_;
};

struct SeparatrixSeed {
  int origin;
  RadialDirection start;
  Vec3 seed;
  double offset;  // cells from the origin
};

/// World point `cells` cells from p along the world direction d (cells measured in index space).
Vec3 offsetAlong(const Grid& g, const Vec3& p, const Vec2& d, double cells) {
  const Vec2 inCells(d.x() / g.spacing[0], d.y() / g.spacing[1]);
  const Vec2 step = d * (cells / inCells.norm());
  return p + Vec3(step.x(), step.y(), 0.0);
}

std::vector<SeparatrixSeed> separatrixSeeds(const Grid& g, const std::vector<CriticalPoint>& points,
                                            const TopologyParams& params) {
  std::vector<SeparatrixSeed> seeds;
  for (int k = 0; k < static_cast<int>(points.size()); ++k) {
    const CriticalPoint& p = points[k];
    const double offset = p.morse ? params.separatrix_offset : p.loop_radius;
    for (const RadialDirection& d : p.separatrix_directions) {
      const Vec3 seed = offsetAlong(g, p.position, d.direction, offset);
      if (g.contains(seed)) seeds.push_back({k, d, seed, offset});
    }
  }
  return seeds;
}

Separatrix traceOne(const SeparatrixSeed& s, const std::vector<CriticalPoint>& points,
                    const StreamlineTracer& forward, const StreamlineTracer& backward,
                    const PointLocator& locator) {
  int hit = -1;
  const double r = locator.radius();
  const streamlines::StopRule stop = [&](const StepInfo& step) {
    const bool mayReturn = step.arc_length > 2 * (r + s.offset);
    hit = locator.nearest(step.point, r, mayReturn ? -1 : s.origin);
    return hit >= 0;
  };
  const streamlines::Streamline line =
      (s.start.outflow ? forward : backward).trace(s.seed, stop);
  Separatrix out;
  out.origin = s.origin;
  out.start = s.start;
  out.reason = line.reason();
  out.points.push_back(points[s.origin].position);
  if (s.start.outflow)
    out.points.insert(out.points.end(), line.points.begin(), line.points.end());
  else
    out.points.insert(out.points.end(), line.points.rbegin(), line.points.rend());
  out.end = separatrixEnd(out.reason);
  if (out.reason == TerminationReason::stagnation)
    hit = locator.nearest(out.points.back(), 2 * r);
  if (out.reason == TerminationReason::too_close || hit >= 0) {
    out.end = SeparatrixEnd::CriticalPoint;
    out.end_point = hit;
    out.points.push_back(points[hit].position);
  }
  return out;
}
}  // namespace

SeparatrixEnd separatrixEnd(TerminationReason r) {
  switch (r) {
    case TerminationReason::domain_exit: return SeparatrixEnd::Boundary;
    case TerminationReason::max_length:
    case TerminationReason::max_steps: return SeparatrixEnd::Length;
    case TerminationReason::stagnation: return SeparatrixEnd::Stagnation;
    case TerminationReason::nan_in_field: return SeparatrixEnd::Mask;
    default: return SeparatrixEnd::Other;
  }
}

std::string toString(SeparatrixEnd e) {
  switch (e) {
    case SeparatrixEnd::CriticalPoint: return "critical_point";
    case SeparatrixEnd::Boundary: return "boundary";
    case SeparatrixEnd::Length: return "length";
    case SeparatrixEnd::Stagnation: return "stagnation";
    case SeparatrixEnd::Other: return "other";
    case SeparatrixEnd::Mask: return "mask";
  }
  return "other";
}

std::vector<Separatrix> computeSeparatrices(const VectorField& field,
                                            const std::vector<CriticalPoint>& points,
                                            const TopologyParams& params) {
  validateTopologyParams(params);
  const bool is2D = field.grid.is2D();
  if (!is2D && (params.slice_index < 0 || params.slice_index >= field.grid.dims[2]))
    throw ParamError("slice_index", "is " + std::to_string(params.slice_index) +
                                        "; allowed: [0, " +
                                        std::to_string(field.grid.dims[2] - 1) + "]");
  const VectorField sliceCopy = is2D ? VectorField{} : planarCopy(field, params.slice_index);
  const VectorField& planar = is2D ? field : sliceCopy;

  streamlines::StreamlineParams sp = params.separatrix_integration;
  sp.direction = streamlines::TraceDirection::forward;
  const StreamlineTracer forward(planar, sp);
  sp.direction = streamlines::TraceDirection::backward;
  const StreamlineTracer backward(planar, sp);
  const PointLocator locator(planar.grid, points, params.separatrix_stop_radius);

  const std::vector<SeparatrixSeed> seeds = separatrixSeeds(planar.grid, points, params);
  std::vector<Separatrix> out(seeds.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < static_cast<int>(seeds.size()); ++k)
    out[k] = traceOne(seeds[k], points, forward, backward, locator);
  return out;
}

}  // namespace fluidviz::topology
