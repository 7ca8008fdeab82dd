#include "filters/topology/TopologyAgreement.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace fluidviz::topology {

namespace {
Vec2 toCells(const Grid& g, const Vec3& p) {
  return {(p.x() - g.origin[0]) / g.spacing[0], (p.y() - g.origin[1]) / g.spacing[1]};
}

bool nearBoundary(const Grid& g, const Vec3& p, double margin) {
  const Vec2 q = toCells(g, p);
  return std::min({q.x(), q.y(), g.dims[0] - 1 - q.x(), g.dims[1] - 1 - q.y()}) < margin;
}
}  // namespace

bool TopologyAgreement::agree() const {
  if (!unmatched_velocity.empty() || !unmatched_stream_function.empty()) return false;
  return std::all_of(matches.begin(), matches.end(),
                     [](const ViewMatch& m) { return m.types_agree; });
}

bool correspondingTypes(const CriticalPoint& v, const ScalarCriticalPoint& s) {
  if (v.index != s.index) return false;
  switch (v.type) {
    case CriticalPointType::Centre: {
      const double vorticity = v.jacobian(1, 0) - v.jacobian(0, 1);
      return vorticity > 0 ? s.type == ScalarCriticalType::Maximum
                           : s.type == ScalarCriticalType::Minimum;
    }
    case CriticalPointType::Saddle: return s.type == ScalarCriticalType::Saddle;
    case CriticalPointType::MonkeySaddle:
      return s.type == ScalarCriticalType::DegenerateSaddle && s.index == -2;
    default: return !v.morse && !s.morse;
  }
}

TopologyAgreement compareVelocityAndStreamFunction(const std::vector<CriticalPoint>& velocity,
                                                   const std::vector<ScalarCriticalPoint>& psi,
                                                   const Grid& grid, double max_distance,
                                                   double boundary_margin) {
  std::vector<int> vs, ss;
  for (int a = 0; a < static_cast<int>(velocity.size()); ++a)
    if (!nearBoundary(grid, velocity[a].position, boundary_margin)) vs.push_back(a);
  for (int b = 0; b < static_cast<int>(psi.size()); ++b)
    if (!nearBoundary(grid, psi[b].position, boundary_margin)) ss.push_back(b);

  std::vector<std::tuple<double, int, int>> pairs;
  for (int a : vs)
    for (int b : ss) {
      const double d =
          (toCells(grid, velocity[a].position) - toCells(grid, psi[b].position)).norm();
      if (d <= max_distance) pairs.emplace_back(d, a, b);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> usedV(velocity.size(), false), usedS(psi.size(), false);
  TopologyAgreement r;
  for (const auto& [d, a, b] : pairs) {
    if (usedV[a] || usedS[b]) continue;
    usedV[a] = usedS[b] = true;
    r.matches.push_back({a, b, d, correspondingTypes(velocity[a], psi[b])});
  }
  for (int a : vs)
    if (!usedV[a]) r.unmatched_velocity.push_back(a);
  for (int b : ss)
    if (!usedS[b]) r.unmatched_stream_function.push_back(b);
  return r;
}

}  // namespace fluidviz::topology
