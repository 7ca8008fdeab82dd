#include "filters/topology/IndexLoopPlacement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Geometry>

#include "filters/topology/CriticalPointClassifier.h"
#include "filters/topology/ZeroClustering.h"

namespace fluidviz::topology {

namespace {
constexpr double kMinLoopGap = 1e-6;  // cells between the loop and any zero

/// Uniform buckets over the domain for "zeros near a point" queries.
class ZeroBuckets {
 public:
  ZeroBuckets(const PlanarField& f, const std::vector<InterpolantZero>& zeros) : zeros_(zeros) {
    nx_ = static_cast<int>(std::ceil((f.nx() - 1) / kSize)) + 1;
    ny_ = static_cast<int>(std::ceil((f.ny() - 1) / kSize)) + 1;
    buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (int z = 0; z < static_cast<int>(zeros.size()); ++z)
      buckets_[bucketOf(zeros[z].q)].push_back(z);
  }
  /// Zeros within `radius` of p.
  const Vec2& position(int z) const { return zeros_[z].q; }
  template <class Visit>
  void forEachNear(const Vec2& p, double radius, Visit visit) const {
    const int i0 = std::max(0, static_cast<int>(std::floor((p.x() - radius) / kSize)));
    const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((p.x() + radius) / kSize)));
    const int j0 = std::max(0, static_cast<int>(std::floor((p.y() - radius) / kSize)));
    const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((p.y() + radius) / kSize)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        for (int z : buckets_[static_cast<std::size_t>(j) * nx_ + i])
          if ((zeros_[z].q - p).norm() <= radius) visit(z);
  }

 private:
  static constexpr double kSize = 4.0;  // cells
  std::size_t bucketOf(const Vec2& q) const {
    const int i = std::clamp(static_cast<int>(std::floor(q.x() / kSize)), 0, nx_ - 1);
    const int j = std::clamp(static_cast<int>(std::floor(q.y() / kSize)), 0, ny_ - 1);
    return static_cast<std::size_t>(j) * nx_ + i;
  }
  const std::vector<InterpolantZero>& zeros_;
  int nx_ = 0, ny_ = 0;
  std::vector<std::vector<int>> buckets_;
};

/// Jacobian (central differences) as a 4-vector.
Eigen::Vector4d jacobianVector(const PlanarField& f, const Vec2& q) {
  const Mat2 j = f.jacobianFiniteDifference(q);
  return {j(0, 0), j(1, 0), j(0, 1), j(1, 1)};
}

/// Point near `start` where |J_fd(q)|_F^2 is smallest: Gauss-Newton on the residual J_fd(q),
/// derivatives by central differences (half a cell). Stays within `reach` cells of `start`
/// (otherwise `start` is returned).
Vec2 smallestJacobianPoint(const PlanarField& f, const Vec2& start, double reach) {
  Vec2 q = start;
  for (int it = 0; it < 8; ++it) {
    Eigen::Matrix<double, 4, 2> b;
    for (int a = 0; a < 2; ++a) {
      Vec2 e = Vec2::Zero();
      e[a] = 0.5;
      b.col(a) = jacobianVector(f, q + e) - jacobianVector(f, q - e);
    }
    const Eigen::Matrix2d normal = b.transpose() * b;
    if (normal.determinant() <= 1e-300) break;
    const Vec2 step = normal.ldlt().solve(b.transpose() * jacobianVector(f, q));
    if (!step.allFinite()) break;
    q -= step;
    if ((q - start).norm() > reach || f.distanceToBoundary(q) < 0) return start;
    if (step.norm() < 1e-10) break;
  }
  return q;
}

/// Centre of a cluster: the zero itself for one zero. Several zeros surround a degenerate
/// point, where the Jacobian vanishes: the centre is the point of smallest Jacobian near their
/// centroid (for fields with a quadratic leading term, e.g. monkey saddle and dipole, central
/// differences of the interpolant with a one-cell step are exact, and so is this centre).
void computeCentreAndExtent(ZeroCluster& c, const std::vector<InterpolantZero>& zeros,
                            const PlanarField& field) {
  Vec2 sum = Vec2::Zero();
  for (int m : c.members) sum += zeros[m].q;
  c.centre = sum / static_cast<double>(c.members.size());
  c.extent = 0.0;
  for (int m : c.members) c.extent = std::max(c.extent, (zeros[m].q - c.centre).norm());
  if (c.members.size() > 1) c.centre = smallestJacobianPoint(field, c.centre, c.extent + 0.5);
  c.extent = 0.0;
  for (int m : c.members) c.extent = std::max(c.extent, (zeros[m].q - c.centre).norm());
}

/// Nearest zero of another cluster within `searchRadius` of the centre: (distance, its cluster);
/// (infinity, -1) if there is none.
std::pair<double, int> nearestForeignZero(const ZeroCluster& c, int self,
                                          const std::vector<int>& clusterOfZero,
                                          const ZeroBuckets& buckets, double searchRadius) {
  std::pair<double, int> best{std::numeric_limits<double>::infinity(), -1};
  buckets.forEachNear(c.centre, searchRadius, [&](int z) {
    if (clusterOfZero[z] == self) return;
    const double dz = (buckets.position(z) - c.centre).norm();
    if (dz < best.first) best = {dz, clusterOfZero[z]};
  });
  return best;
}

/// Cluster label of each zero (in order of first appearance). Only zeros that are not Morse
/// points on their own (isMorseZero) are linked, within cluster_radius: those are the pieces of
/// one degenerate point that the interpolant unfolds (a monkey saddle's spurious zeros, whose
/// det J vanishes with their distance). A Morse zero is its own cluster, however close another
/// zero lies (a genuine saddle and focus 1.3 cells apart stay two points, issue 15).
std::vector<int> degenerateZeroLabels(const PlanarField& field,
                                      const std::vector<InterpolantZero>& zeros,
                                      const TopologyParams& params) {
  std::vector<int> degenerate;
  std::vector<Vec2> positions;
  for (int z = 0; z < static_cast<int>(zeros.size()); ++z)
    if (!isMorseZero(field, zeros[z].q, params.gradient_scale_radius, params.det_threshold)) {
      degenerate.push_back(z);
      positions.push_back(zeros[z].q);
    }
  const std::vector<int> linked = singleLinkageLabels(
      positions, params.cluster_radius, maxClusterDiameter(params.cluster_radius));
  std::vector<int> labels(zeros.size()), labelOfLinked(degenerate.size(), -1);
  int next = 0;
  std::size_t d = 0;
  for (int z = 0; z < static_cast<int>(zeros.size()); ++z) {
    if (d < degenerate.size() && degenerate[d] == z) {
      int& l = labelOfLinked[linked[d++]];
      if (l < 0) l = next++;
      labels[z] = l;
    } else {
      labels[z] = next++;
    }
  }
  return labels;
}

/// Diagonal of the bounding box of two clusters' zeros.
double mergedDiameter(const ZeroCluster& a, const ZeroCluster& b,
                      const std::vector<InterpolantZero>& zeros) {
  Eigen::AlignedBox2d box;
  for (int m : a.members) box.extend(zeros[m].q);
  for (int m : b.members) box.extend(zeros[m].q);
  return box.diagonal().norm();
}
}  // namespace

std::vector<ZeroCluster> clusterZerosAndPlaceLoops(const PlanarField& field,
                                                   const std::vector<InterpolantZero>& zeros,
                                                   const TopologyParams& params) {
  const double maxDiameter = maxClusterDiameter(params.cluster_radius);
  std::vector<int> clusterOfZero = degenerateZeroLabels(field, zeros, params);
  std::vector<ZeroCluster> clusters;
  for (auto& members : groupsFromLabels(clusterOfZero)) {
    clusters.push_back({std::move(members), Vec2::Zero(), 0.0, 0.0});
    computeCentreAndExtent(clusters.back(), zeros, field);
  }
  const ZeroBuckets buckets(field, zeros);
  std::vector<bool> merged(clusters.size(), false);
  for (int ci = 0; ci < static_cast<int>(clusters.size()); ++ci) {
    if (merged[ci]) continue;
    ZeroCluster& c = clusters[ci];
    const auto [d, owner] = nearestForeignZero(c, ci, clusterOfZero, buckets,
                                               c.extent + params.loop_radius);
    if (d <= c.extent + kMinLoopGap &&
        mergedDiameter(c, clusters[owner], zeros) > maxDiameter) {
      c.loop_radius = 0.0;  // no circle separates them, and merging would exceed the limit
      continue;
    }
    if (d <= c.extent + kMinLoopGap) {  // no circle separates them: one cluster
      for (int m : clusters[owner].members) clusterOfZero[m] = ci;
      c.members.insert(c.members.end(), clusters[owner].members.begin(),
                       clusters[owner].members.end());
      std::sort(c.members.begin(), c.members.end());
      clusters[owner].members.clear();
      merged[owner] = true;
      computeCentreAndExtent(c, zeros, field);
      --ci;  // place this cluster's loop again
      continue;
    }
    const double b = field.distanceToBoundary(c.centre);
    double r = std::min(c.extent + params.loop_radius, b);
    if (std::isfinite(d)) r = std::min(r, c.extent + 0.5 * (d - c.extent));
    c.loop_radius = r > c.extent + kMinLoopGap ? r : 0.0;
  }
  std::vector<ZeroCluster> out;
  for (int ci = 0; ci < static_cast<int>(clusters.size()); ++ci)
    if (!merged[ci]) out.push_back(std::move(clusters[ci]));
  return out;
}

}  // namespace fluidviz::topology
