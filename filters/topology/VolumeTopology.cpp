#include "filters/topology/VolumeTopology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "filters/topology/CriticalPointClassifier3D.h"
#include "filters/topology/SurfaceDegree.h"

namespace fluidviz::topology {

namespace {
constexpr double kBarycentricSlack = 1e-10;    // a zero on a face still counts as inside
constexpr double kSameZero = 1e-6;             // cells: zeros of neighbouring tetrahedra merged

/// Single linkage in 3D with a hash grid of buckets of the radius' size; a union that would
/// make a group's bounding-box diagonal exceed max_diameter is refused (as ZeroClustering.h).
std::vector<std::vector<int>> singleLinkageGroups(const std::vector<Vec3>& points, double radius,
                                                  double max_diameter) {
  const int n = static_cast<int>(points.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<Eigen::AlignedBox3d> box;
  for (const Vec3& p : points) box.emplace_back(p, p);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  auto unite = [&](int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    const Eigen::AlignedBox3d merged = box[a].merged(box[b]);
    if (merged.diagonal().norm() > max_diameter) return;
    parent[std::max(a, b)] = std::min(a, b);
    box[std::min(a, b)] = merged;
  };
  const double bucket = std::max(radius, 1e-9);
  auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return (x * 73856093) ^ (y * 19349663) ^ (z * 83492791);
  };
  std::unordered_map<std::int64_t, std::vector<int>> buckets;
  for (int a = 0; a < n; ++a) {
    std::array<std::int64_t, 3> c;
    for (int d = 0; d < 3; ++d) c[d] = static_cast<std::int64_t>(std::floor(points[a][d] / bucket));
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          auto it = buckets.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == buckets.end()) continue;
          for (int b : it->second)
            if ((points[a] - points[b]).norm() <= radius) unite(a, b);
        }
    buckets[key(c[0], c[1], c[2])].push_back(a);
  }
  std::vector<int> groupOfRoot(n, -1);
  std::vector<std::vector<int>> groups;
  for (int a = 0; a < n; ++a) {
    const int r = find(a);
    if (groupOfRoot[r] < 0) {
      groupOfRoot[r] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[groupOfRoot[r]].push_back(a);
  }
  return groups;
}

/// A zero of the interpolant after merging the tetrahedra that share it.
struct MergedZero {
  Vec3 q;
  Mat3 jacobian_index;  ///< mean over the tetrahedra holding it
  std::array<int, 3> cell;
};

bool isZeroNode(const VolumeField& f, const Eigen::Vector3i& p) { return f.node(p).isZero(0.0); }

/// A node where v = 0 exactly next to another such node (any of its 26 neighbours) lies on a
/// region of zeros (a no-slip wall, a solid obstacle), not on an isolated critical point: the
/// tetrahedra touching it are skipped (the 3D form of the 2D rule for cells with a zero edge,
/// CriticalPointDetector.h). Tetrahedra with two zero vertices are singular anyway; this also
/// drops those with one, whose "zero" is the wall's corner.
bool onZeroRegion(const VolumeField& f, const Eigen::Vector3i& p) {
  if (!isZeroNode(f, p)) return false;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Eigen::Vector3i q = p + Eigen::Vector3i(dx, dy, dz);
        if ((dx || dy || dz) && (q.array() >= 0).all() && q.x() < f.n(0) && q.y() < f.n(1) &&
            q.z() < f.n(2) && isZeroNode(f, q))
          return true;
      }
  return false;
}

bool touchesZeroRegion(const VolumeField& f, const KuhnTetrahedron& t) {
  const Eigen::Vector3i base(t.cell[0], t.cell[1], t.cell[2]);
  for (const Eigen::Vector3i& c : t.corner)
    if (onZeroRegion(f, base + c)) return true;
  return false;
}

std::vector<TetrahedronZero> zerosOfAllTetrahedra(const VolumeField& field) {
  const int cx = field.n(0) - 1, cy = field.n(1) - 1, cz = field.n(2) - 1;
  std::vector<std::vector<TetrahedronZero>> slabs(cz);
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < cz; ++k)
    for (int j = 0; j < cy; ++j)
      for (int i = 0; i < cx; ++i) {
        // Quick rejection: each component of the linear interpolant lies between its extremes at
        // the cell's corners, so both signs must occur among them for every component.
        Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
        for (int c = 0; c < 8; ++c) {
          const Vec3 w = field.node(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2));
          lo = lo.cwiseMin(w);
          hi = hi.cwiseMax(w);
        }
        if ((lo.array() > 0.0).any() || (hi.array() < 0.0).any()) continue;
        for (const KuhnTetrahedron& t : kuhnTetrahedra({i, j, k}))
          if (auto z = zeroInTetrahedron(field, t); z && !touchesZeroRegion(field, t))
            slabs[k].push_back(*z);
      }
  std::vector<TetrahedronZero> all;
  for (auto& s : slabs) all.insert(all.end(), s.begin(), s.end());
  return all;
}

std::vector<MergedZero> mergeSharedZeros(const std::vector<TetrahedronZero>& raw) {
  std::vector<Vec3> positions;
  for (const auto& z : raw) positions.push_back(z.q);
  std::vector<MergedZero> out;
  for (const auto& group : singleLinkageGroups(positions, kSameZero, 1e300)) {
    MergedZero m{Vec3::Zero(), Mat3::Zero(), raw[group.front()].cell};
    for (int g : group) {
      m.q += raw[g].q;
      m.jacobian_index += raw[g].jacobian_index;
    }
    m.q /= double(group.size());
    m.jacobian_index /= double(group.size());
    out.push_back(m);
  }
  return out;
}

struct Cluster {
  std::vector<int> members;  // into the merged zeros
  Vec3 centre;
  double extent = 0.0;
  double sphere_radius = 0.0;  // 0: no sphere fits
};

Eigen::Matrix<double, 9, 1> jacobianVector(const VolumeField& f, const Vec3& q) {
  const Mat3 j = f.toWorldJacobian(f.jacobianFiniteDifference(q));
  return Eigen::Map<const Eigen::Matrix<double, 9, 1>>(j.data());
}

/// Centre of a cluster of several zeros: they surround a degenerate point, where the Jacobian
/// is singular and, for the fields met in practice, smallest. Gauss-Newton on the residual
/// J_fd(q) (derivatives by central differences of half a cell; the least-squares step of least
/// norm, so that it does not move along directions in which J does not change, e.g. z for
/// (x^2 - y^2, 2xy, z)). Central differences with a
/// one-cell step of the piecewise-linear interpolant are the interpolant of the nodes' central
/// differences, which are exact for a quadratic field, whose Jacobian is linear and interpolated
/// exactly: for quadratic leading terms this centre is the degenerate point itself. Stays within
/// `reach` cells of `start` (otherwise `start` is returned, as in 2D: IndexLoopPlacement.cpp).
Vec3 smallestJacobianPoint(const VolumeField& f, const Vec3& start, double reach) {
  Vec3 q = start;
  for (int it = 0; it < 8; ++it) {
    Eigen::Matrix<double, 9, 3> b;
    for (int a = 0; a < 3; ++a) {
      Vec3 e = Vec3::Zero();
      e[a] = 0.5;
      b.col(a) = jacobianVector(f, q + e) - jacobianVector(f, q - e);
    }
    if (!(b.norm() > 1e-300)) break;
    Eigen::JacobiSVD<Eigen::Matrix<double, 9, 3>> svd(b, Eigen::ComputeFullU | Eigen::ComputeFullV);
    svd.setThreshold(1e-8);  // no step along directions in which J does not change
    const Vec3 step = svd.solve(jacobianVector(f, q));
    if (!step.allFinite()) break;
    q -= step;
    if ((q - start).norm() > reach || f.distanceToBoundary(q) < 0) return start;
    if (step.norm() < 1e-10) break;
  }
  return q;
}

/// Zeros that are Morse on their own stay single; the others are grouped by single linkage.
std::vector<Cluster> clusterZeros(const VolumeField& field, const std::vector<MergedZero>& zeros,
                                  const TopologyParams& params) {
  std::vector<Cluster> clusters;
  std::vector<int> degenerate;
  std::vector<Vec3> degeneratePositions;
  for (int z = 0; z < static_cast<int>(zeros.size()); ++z) {
    const Linearization3 lin = linearize(field.toWorldJacobian(zeros[z].jacobian_index));
    const double g = field.gradientScale(zeros[z].q, params.gradient_scale_radius);
    if (isNonDegenerate(lin, g, params.det_threshold)) {
      clusters.push_back({{z}, zeros[z].q});
    } else {
      degenerate.push_back(z);
      degeneratePositions.push_back(zeros[z].q);
    }
  }
  for (const auto& group : singleLinkageGroups(degeneratePositions, params.cluster_radius,
                                               3.0 * params.cluster_radius)) {
    Cluster c;
    c.centre = Vec3::Zero();
    double extent = 0.0;
    for (int g : group) {
      c.members.push_back(degenerate[g]);
      c.centre += zeros[degenerate[g]].q;
    }
    c.centre /= double(group.size());
    for (int m : c.members) extent = std::max(extent, (zeros[m].q - c.centre).norm());
    if (c.members.size() > 1) c.centre = smallestJacobianPoint(field, c.centre, extent + 0.5);
    clusters.push_back(c);
  }
  // In the order of the first zero found (cell k, j, i).
  std::sort(clusters.begin(), clusters.end(), [](const Cluster& a, const Cluster& b) {
    return *std::min_element(a.members.begin(), a.members.end()) <
           *std::min_element(b.members.begin(), b.members.end());
  });
  return clusters;
}

/// r = min(extent + loop_radius, extent + (d - extent) / 2, boundary distance), d the distance to
/// the nearest zero of another cluster; no sphere when r does not exceed the extent.
void placeSpheres(const VolumeField& field, const std::vector<MergedZero>& zeros,
                  std::vector<Cluster>& clusters, const TopologyParams& params) {
  std::vector<int> owner(zeros.size());
  for (int c = 0; c < static_cast<int>(clusters.size()); ++c)
    for (int m : clusters[c].members) owner[m] = c;
  for (int c = 0; c < static_cast<int>(clusters.size()); ++c) {
    Cluster& cl = clusters[c];
    for (int m : cl.members) cl.extent = std::max(cl.extent, (zeros[m].q - cl.centre).norm());
    double nearest = 1e300;
    for (int z = 0; z < static_cast<int>(zeros.size()); ++z)
      if (owner[z] != c) nearest = std::min(nearest, (zeros[z].q - cl.centre).norm());
    const double r = std::min({cl.extent + params.loop_radius,
                               cl.extent + (nearest - cl.extent) / 2,
                               field.distanceToBoundary(cl.centre)});
    cl.sphere_radius = r > cl.extent + 1e-3 ? r : 0.0;
  }
}

/// Degree on the cluster's sphere; if the field vanishes at a sample or is not finite there
/// (masked nodes), or turns too fast to be resolved (it nearly vanishes on the sphere), the
/// radius shrinks towards the extent. nullopt when no radius gives a resolved degree.
std::optional<std::pair<int, double>> measureIndex(const VolumeField& field, const Cluster& c) {
  const FieldAt at = [&field](const Vec3& q) { return field(q); };
  double r = c.sphere_radius;
  for (int attempt = 0; attempt < 8; ++attempt, r = c.extent + 0.9 * (r - c.extent))
    if (auto m = degreeOnSphere(at, c.centre, r); m && m->resolved)
      return std::make_pair(m->degree, r);
  return std::nullopt;
}

CriticalPoint3D analyzeCluster(const VolumeField& field, const std::vector<MergedZero>& zeros,
                               const Cluster& c, const TopologyParams& params) {
  CriticalPoint3D p;
  const bool isolated = c.members.size() == 1;
  const Vec3 q = c.centre;
  p.position = field.toWorld(q);
  p.cell = isolated ? zeros[c.members.front()].cell : field.cellOf(q);
  p.cluster_size = static_cast<int>(c.members.size());
  p.on_boundary = field.distanceToBoundary(q) <= kOnBoundaryCells;
  const Mat3 jIndex =
      isolated ? zeros[c.members.front()].jacobian_index : field.jacobianFiniteDifference(q);
  const Linearization3 lin = linearize(field.toWorldJacobian(jIndex));
  p.jacobian = lin.jacobian;
  p.det = lin.det;
  p.trace = lin.trace;
  p.eigenvalues = lin.eigenvalues;
  const double g = field.gradientScale(q, params.gradient_scale_radius);
  p.normalized_det = g > 0 ? lin.det / (g * g * g) : 0.0;
  const bool nonDegenerate = isNonDegenerate(lin, g, params.det_threshold);
  const int linearIndex = lin.det > 0 ? 1 : -1;

  std::optional<std::pair<int, double>> measured;
  if (c.sphere_radius > 0.0) measured = measureIndex(field, c);
  if (measured) {
    p.index_measured = true;
    p.index = measured->first;
    p.sphere_radius = measured->second;
  } else {
    p.index = nonDegenerate ? linearIndex : 0;
  }
  // A sphere fitted but no radius resolved the degree: v nearly vanishes around the point in a
  // way no sphere separates (a line or plane of zeros through it, as next to walls in measured
  // data): not an isolated zero whose linearisation could be trusted.
  const bool unresolved = c.sphere_radius > 0.0 && !measured;
  if (unresolved) p.index = 0;
  p.morse = nonDegenerate && isolated && p.index == linearIndex && !unresolved;
  if (p.morse)
    p.type = classifyMorse(lin, params.centre_tolerance);
  else
    p.type = measured ? CriticalPointType3D::Degenerate : CriticalPointType3D::Unknown;
  return p;
}
}  // namespace

std::optional<TetrahedronZero> zeroInTetrahedron(const VolumeField& field,
                                                 const KuhnTetrahedron& tet) {
  const Eigen::Vector3i base(tet.cell[0], tet.cell[1], tet.cell[2]);
  std::array<Vec3, 4> w;
  for (int v = 0; v < 4; ++v) {
    w[v] = field.node(base + tet.corner[v]);
    if (!w[v].allFinite()) return std::nullopt;
  }
  // Interpolant w(lambda) = w0 + M mu, mu the barycentric coordinates of vertices 1..3.
  Mat3 m, e;
  for (int v = 1; v <= 3; ++v) {
    m.col(v - 1) = w[v] - w[0];
    e.col(v - 1) = (tet.corner[v] - tet.corner[0]).cast<double>();
  }
  // Singular, or so nearly singular (|det| below 1e-8 of the product of the column lengths, the
  // Hadamard bound) that the tetrahedron holds a line of near-zeros whose solved position is
  // round-off: no isolated zero here.
  const double det = m.determinant();
  const double hadamard = m.col(0).norm() * m.col(1).norm() * m.col(2).norm();
  if (!(std::abs(det) > 1e-8 * hadamard)) return std::nullopt;
  const Vec3 mu = m.inverse() * (-w[0]);
  const double lambda0 = 1.0 - mu.sum();
  if (lambda0 < -kBarycentricSlack || (mu.array() < -kBarycentricSlack).any()) return std::nullopt;
  TetrahedronZero z;
  z.q = base.cast<double>() + tet.corner[0].cast<double>() + e * mu;
  z.jacobian_index = m * e.inverse();  // dw/dq = dw/dmu * dmu/dq
  z.cell = tet.cell;
  return z;
}

std::vector<CriticalPoint3D> findCriticalPoints3D(const VolumeField& field,
                                                  const TopologyParams& params) {
  validateTopologyParams(params);
  const std::vector<MergedZero> zeros = mergeSharedZeros(zerosOfAllTetrahedra(field));
  std::vector<Cluster> clusters = clusterZeros(field, zeros, params);
  placeSpheres(field, zeros, clusters, params);
  std::vector<CriticalPoint3D> points(clusters.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int c = 0; c < static_cast<int>(clusters.size()); ++c)
    points[c] = analyzeCluster(field, zeros, clusters[c], params);
  return points;
}

std::vector<CriticalPoint3D> findCriticalPoints3D(const VectorField& field,
                                                  const TopologyParams& params) {
  validateTopologyParams(params);
  return findCriticalPoints3D(VolumeField(field), params);
}

std::optional<int> degreeOnNodeBox(const VolumeField& field, const std::array<int, 3>& lo,
                                   const std::array<int, 3>& hi) {
  const FieldAt at = [&field](const Vec3& q) { return field(q); };
  std::array<int, 3> divisions;
  for (int a = 0; a < 3; ++a) divisions[a] = std::max(hi[a] - lo[a], 1);
  auto m = degreeOnBox(at, Vec3(lo[0], lo[1], lo[2]), Vec3(hi[0], hi[1], hi[2]), divisions);
  if (!m) return std::nullopt;
  return m->degree;
}

}  // namespace fluidviz::topology
