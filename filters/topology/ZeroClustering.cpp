#include "filters/topology/ZeroClustering.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include <Eigen/Geometry>

namespace fluidviz::topology {

namespace {
/// Union-find whose sets know their bounding box; a union that would make the box's diagonal
/// exceed the limit is refused.
struct DisjointSets {
  std::vector<int> parent;
  std::vector<Eigen::AlignedBox2d> box;
  double maxDiameter;
  DisjointSets(const std::vector<Vec2>& points, double max_diameter)
      : parent(points.size()), maxDiameter(max_diameter) {
    std::iota(parent.begin(), parent.end(), 0);
    for (const Vec2& p : points) box.emplace_back(p, p);
  }
  int find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    const Eigen::AlignedBox2d merged = box[a].merged(box[b]);
    if (merged.diagonal().norm() > maxDiameter) return;
    parent[std::max(a, b)] = std::min(a, b);
    box[std::min(a, b)] = merged;
  }
};

std::int64_t bucketKey(std::int64_t bx, std::int64_t by) { return (bx << 32) ^ (by & 0xffffffff); }
}  // namespace

std::vector<int> singleLinkageLabels(const std::vector<Vec2>& points, double radius,
                                     double max_diameter) {
  const int n = static_cast<int>(points.size());
  DisjointSets sets(points, max_diameter);
  const double bucket = std::max(radius, 1e-9);
  std::unordered_map<std::int64_t, std::vector<int>> buckets;
  auto cellOf = [&](const Vec2& p) {
    return std::array<std::int64_t, 2>{static_cast<std::int64_t>(std::floor(p.x() / bucket)),
                                       static_cast<std::int64_t>(std::floor(p.y() / bucket))};
  };
  for (int a = 0; a < n; ++a) {
    const auto c = cellOf(points[a]);
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        auto it = buckets.find(bucketKey(c[0] + dx, c[1] + dy));
        if (it == buckets.end()) continue;
        for (int b : it->second)
          if ((points[a] - points[b]).norm() <= radius) sets.unite(a, b);
      }
    buckets[bucketKey(c[0], c[1])].push_back(a);
  }
  std::vector<int> labels(n), labelOfRoot(n, -1);
  int next = 0;
  for (int a = 0; a < n; ++a) {
    const int r = sets.find(a);
    if (labelOfRoot[r] < 0) labelOfRoot[r] = next++;
    labels[a] = labelOfRoot[r];
  }
  return labels;
}

std::vector<std::vector<int>> groupsFromLabels(const std::vector<int>& labels) {
  int count = 0;
  for (int l : labels) count = std::max(count, l + 1);
  std::vector<std::vector<int>> groups(count);
  for (int a = 0; a < static_cast<int>(labels.size()); ++a) groups[labels[a]].push_back(a);
  return groups;
}

}  // namespace fluidviz::topology
