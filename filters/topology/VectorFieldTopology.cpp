#include "filters/topology/VectorFieldTopology.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "filters/topology/CriticalPointClassifier.h"
#include "filters/topology/CriticalPointDetector.h"
#include "filters/topology/IndexLoopPlacement.h"
#include "filters/topology/PoincareIndex.h"
#include "filters/topology/SectorAnalysis.h"
#include "filters/topology/WallPoints.h"

namespace fluidviz::topology {

namespace {

struct LoopMeasurement {
  double radius = 0.0;
  SectorDecomposition sectors;
  int winding = 0;
};

bool allFinite(const std::vector<LoopSample>& loop) {
  return std::all_of(loop.begin(), loop.end(), [](const LoopSample& s) { return s.w.allFinite(); });
}

/// Index and sectors on the cluster's loop; if the field happens to vanish exactly at a loop
/// sample, or the loop crosses masked (NaN) nodes, the radius is reduced (staying outside the
/// cluster's extent). No loop at all: the index is not measured, as on the domain boundary.
std::optional<LoopMeasurement> measureOnLoop(const PlanarField& field, const ZeroCluster& c,
                                             const TopologyParams& params) {
  double r = c.loop_radius;
  for (int attempt = 0; attempt < 8; ++attempt, r = c.extent + 0.9 * (r - c.extent)) {
    auto loop = sampleCircle(field, c.centre, r, params.loop_samples);
    if (!loop || !allFinite(*loop)) continue;
    LoopMeasurement m;
    m.radius = r;
    m.winding = windingNumber(*loop);
    m.sectors = analyzeSectors(field, c.centre, r, *loop, params.sector_hysteresis);
    return m;
  }
  return std::nullopt;
}

std::vector<RadialDirection> toWorldDirections(const PlanarField& field,
                                               const std::vector<SectorBoundary>& boundaries) {
  std::vector<RadialDirection> out;
  for (const SectorBoundary& b : boundaries)
    out.push_back({field.toWorldDirection(Vec2(std::cos(b.theta), std::sin(b.theta))),
                   b.outflow});
  return out;
}

/// Linearisation at q and its scale: the interpolant's exact Jacobian at an isolated zero,
/// central differences at the centre of a cluster of zeros (see CriticalPointClassifier.h);
/// also the interpolant's Jacobian in `cell`.
Linearization linearizeAt(const PlanarField& field, const Vec2& q, bool isolatedZero,
                          const std::array<int, 2>& cell, const TopologyParams& params,
                          CriticalPoint& p) {
  const Linearization lin =
      isolatedZero ? linearizeZero(field, q)
                   : linearize(field.toWorldJacobian(field.jacobianFiniteDifference(q)));
  p.jacobian = lin.jacobian;
  p.jacobian_interpolant = field.toWorldJacobian(field.jacobianInterpolant(q, cell));
  p.det = lin.det;
  p.trace = lin.trace;
  p.eigenvalues = lin.eigenvalues;
  const double g = field.gradientScale(q, params.gradient_scale_radius);
  p.normalized_det = g > 0 ? lin.det / (g * g) : 0.0;
  return lin;
}

/// Morse: the linearisation decides. Otherwise the index and sectors measured on the loop; no
/// loop and degenerate: Unknown.
void classify(const PlanarField& field, const Linearization& lin, bool nonDegenerate,
              const std::optional<LoopMeasurement>& loop, const TopologyParams& params,
              CriticalPoint& p) {
  const int linearIndex = lin.det > 0 ? 1 : -1;
  if (!loop) p.index = nonDegenerate ? linearIndex : 0;
  p.morse = nonDegenerate && p.cluster_size == 1 && p.index == linearIndex;
  if (p.morse) {
    p.type = classifyMorse(lin, params.centre_tolerance);
    if (p.type == CriticalPointType::Saddle) p.separatrix_directions = saddleEigenDirections(lin);
  } else if (loop) {
    p.type = classifyNonMorse(p.index, p.sectors);
    p.separatrix_directions = toWorldDirections(field, loop->sectors.hyperbolicBoundaries());
  } else {
    p.type = CriticalPointType::Unknown;
  }
}

CriticalPoint analyzeCluster(const PlanarField& field, const std::vector<InterpolantZero>& zeros,
                             const ZeroCluster& c, const TopologyParams& params) {
  CriticalPoint p;
  const Vec2 q = c.centre;
  p.position = field.toWorld(q);
  p.cell = field.cellOf(q);
  p.cluster_size = static_cast<int>(c.members.size());
  p.on_boundary = field.distanceToBoundary(q) <= kOnBoundaryCells;
  const bool isolatedZero = c.members.size() == 1;
  const auto cell = isolatedZero ? zeros[c.members.front()].cell : p.cell;
  const Linearization lin = linearizeAt(field, q, isolatedZero, cell, params, p);
  const double g = field.gradientScale(q, params.gradient_scale_radius);
  const bool nonDegenerate = isNonDegenerate(lin, g, params.det_threshold);

  std::optional<LoopMeasurement> loop;
  if (c.loopFits()) loop = measureOnLoop(field, c, params);
  if (loop) {
    p.index_measured = true;
    p.index = loop->winding;
    p.loop_radius = loop->radius;
    p.sectors = loop->sectors.counts;
    p.bendixson_holds = bendixsonHolds(p.index, p.sectors);
  }
  classify(field, lin, nonDegenerate, loop, params, p);
  return p;
}
}  // namespace

std::vector<CriticalPoint> findCriticalPoints(const PlanarField& field,
                                              const TopologyParams& params) {
  validateTopologyParams(params);
  const std::vector<InterpolantZero> zeros = findInterpolantZeros(field, params);
  const std::vector<ZeroCluster> clusters = clusterZerosAndPlaceLoops(field, zeros, params);
  std::vector<CriticalPoint> points(clusters.size());
#pragma omp parallel for schedule(dynamic, 4)
  for (int k = 0; k < static_cast<int>(clusters.size()); ++k)
    points[k] = analyzeCluster(field, zeros, clusters[k], params);
  return points;
}

std::vector<CriticalPoint> findCriticalPoints(const VectorField& field,
                                              const TopologyParams& params) {
  validateTopologyParams(params);
  return findCriticalPoints(PlanarField(field, params.slice_index), params);
}

std::vector<CriticalPoint> findCriticalPointsInFluid(const VectorField& analysed,
                                                     const PointMask& mask,
                                                     const TopologyParams& params,
                                                     const RestingWalls& walls) {
  std::vector<CriticalPoint> points = findCriticalPoints(analysed, params);
  if (!mask.empty())
    std::erase_if(points, [&](const CriticalPoint& p) {
      return !cellTouchesFluid(analysed.grid, mask, p.position);
    });
  if (!analysed.grid.is2D() || !walls.any()) return points;
  const PointMask layer = restingWallLayer(analysed.grid, mask, walls);
  std::erase_if(points,
                [&](const CriticalPoint& p) { return inWallLayer(analysed.grid, layer, p.position); });
  const std::vector<CriticalPoint> onWalls = findWallPoints(analysed, mask, walls);
  points.insert(points.end(), onWalls.begin(), onWalls.end());
  return points;
}

}  // namespace fluidviz::topology
