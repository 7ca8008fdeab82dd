#include "filters/topology/Separatrices3D.h"

#include <cmath>
#include <optional>

#include <Eigen/Eigenvalues>

namespace fluidviz::topology {

namespace {
using streamlines::StepInfo;
using streamlines::StreamlineTracer;
using streamlines::TerminationReason;

struct Seed3D {
  int origin;
  Vec3 direction;
  bool outgoing;
  Vec3 seed;
};
}  // namespace

bool isMorseSaddle(CriticalPointType3D t) {
  return t == CriticalPointType3D::Saddle1 || t == CriticalPointType3D::Saddle2 ||
         t == CriticalPointType3D::SpiralSaddle1 || t == CriticalPointType3D::SpiralSaddle2;
}

double cellsBetween(const Grid& g, const Vec3& a, const Vec3& b) {
  return Vec3((a.x() - b.x()) / g.spacing[0], (a.y() - b.y()) / g.spacing[1],
              (a.z() - b.z()) / g.spacing[2])
      .norm();
}

int nearestCriticalPoint(const Grid& g, const std::vector<CriticalPoint3D>& points, const Vec3& p,
                 double r, int skip) {
  int best = -1;
  double bestD = r;
  for (int k = 0; k < static_cast<int>(points.size()); ++k) {
    const double d = cellsBetween(g, points[k].position, p);
    if (k != skip && d <= bestD) best = k, bestD = d;
  }
  return best;
}

std::optional<std::pair<Vec3, bool>> saddleAxis(const CriticalPoint3D& p) {
  if (!p.morse || !isMorseSaddle(p.type)) return std::nullopt;
  const Eigen::EigenSolver<Mat3> solver(p.jacobian);
  int positive = 0;
  for (int k = 0; k < 3; ++k) positive += solver.eigenvalues()[k].real() > 0;
  const bool unstable = positive == 1;  // 1-saddles: the lone positive; 2-saddles: the negative
  for (int k = 0; k < 3; ++k) {
    const auto e = solver.eigenvalues()[k];
    if (e.imag() != 0.0 && std::abs(e.imag()) > 1e-12 * std::abs(e)) continue;
    if ((e.real() > 0) != unstable) continue;
    return std::make_pair(Vec3(solver.eigenvectors().col(k).real().normalized()), unstable);
  }
  return std::nullopt;
}

std::vector<Separatrix3D> computeSeparatrices3D(const VectorField& field,
                                                const std::vector<CriticalPoint3D>& points,
                                                const TopologyParams& params) {
  validateTopologyParams(params);
  const Grid& g = field.grid;
  std::vector<Seed3D> seeds;
  for (int k = 0; k < static_cast<int>(points.size()); ++k) {
    const auto axis = saddleAxis(points[k]);
    if (!axis) continue;
    for (double sign : {1.0, -1.0}) {
      const Vec3 d = sign * axis->first;
      const double cellsPerUnit = cellsBetween(g, d, Vec3::Zero());
      const Vec3 seed = points[k].position + d * (params.separatrix_offset / cellsPerUnit);
      if (g.contains(seed)) seeds.push_back({k, d, axis->second, seed});
    }
  }
  streamlines::StreamlineParams sp = params.separatrix_integration;
  sp.direction = streamlines::TraceDirection::forward;
  const StreamlineTracer forward(field, sp);
  sp.direction = streamlines::TraceDirection::backward;
  const StreamlineTracer backward(field, sp);
  const double r = params.separatrix_stop_radius;

  std::vector<Separatrix3D> out(seeds.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int s = 0; s < static_cast<int>(seeds.size()); ++s) {
    const Seed3D& seed = seeds[s];
    int hit = -1;
    const streamlines::StopRule stop = [&](const StepInfo& step) {
      const bool mayReturn = step.arc_length > 2 * (r + params.separatrix_offset);
      hit = nearestCriticalPoint(g, points, step.point, r, mayReturn ? -1 : seed.origin);
      return hit >= 0;
    };
    const streamlines::Streamline line = (seed.outgoing ? forward : backward).trace(seed.seed, stop);
    Separatrix3D& sep = out[s];
    sep.origin = seed.origin;
    sep.direction = seed.direction;
    sep.outgoing = seed.outgoing;
    sep.reason = line.reason();
    sep.points.push_back(points[seed.origin].position);
    if (seed.outgoing)
      sep.points.insert(sep.points.end(), line.points.begin(), line.points.end());
    else
      sep.points.insert(sep.points.end(), line.points.rbegin(), line.points.rend());
    sep.end = separatrixEnd(sep.reason);
    if (sep.reason == TerminationReason::stagnation)
      hit = nearestCriticalPoint(g, points, sep.points.back(), 2 * r, -1);
    if (sep.reason == TerminationReason::too_close || hit >= 0) {
      sep.end = SeparatrixEnd::CriticalPoint;
      sep.end_point = hit;
      sep.points.push_back(points[hit].position);
    }
  }
  return out;
}

}  // namespace fluidviz::topology
