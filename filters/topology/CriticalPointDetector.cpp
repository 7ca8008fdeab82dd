#include "filters/topology/CriticalPointDetector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "filters/topology/ZeroClustering.h"

namespace fluidviz::topology {

namespace {

/// Square [s0, s0 + size] x [t0, t0 + size] in the cell's local coordinates.
struct SubRect {
  double s0, t0, size;
  Vec2 centre() const { return {s0 + size / 2, t0 + size / 2}; }
  std::array<Vec2, 4> corners() const {
    return {Vec2(s0, t0), Vec2(s0 + size, t0), Vec2(s0, t0 + size), Vec2(s0 + size, t0 + size)};
  }
};

bool straddlesZero(double a, double b, double c, double d) {
  return std::min({a, b, c, d}) <= 0.0 && std::max({a, b, c, d}) >= 0.0;
}

/// Both components may vanish in the rectangle (exact for bilinear functions per component).
bool mayContainZero(const std::array<Vec2, 4>& f) {
  return straddlesZero(f[0].x(), f[1].x(), f[2].x(), f[3].x()) &&
         straddlesZero(f[0].y(), f[1].y(), f[2].y(), f[3].y());
}

/// det J is affine in (s, t): a strict common sign at the corners means det J != 0 inside.
bool jacobianRegular(const BilinearPatch& p, const SubRect& r) {
  int positive = 0, negative = 0;
  for (const Vec2& c : r.corners()) {
    const double d = p.jacobian(c.x(), c.y()).determinant();
    positive += d > 0;
    negative += d < 0;
  }
  return positive == 4 || negative == 4;
}

/// Newton iteration x <- x - J(x)^-1 F(x) from the rectangle's centre. Returns the zero (clamped
/// into the rectangle) if it converges within it.
std::optional<Vec2> newtonInRect(const BilinearPatch& p, const SubRect& r,
                                 const TopologyParams& params) {
  Vec2 x = r.centre();
  for (int it = 0; it < params.newton_max_iterations; ++it) {
    const Mat2 j = p.jacobian(x.x(), x.y());
    const double det = j.determinant();
    if (!std::isfinite(det) || det == 0.0) return std::nullopt;
    const Vec2 step = j.inverse() * p(x.x(), x.y());
    if (!step.allFinite()) return std::nullopt;
    x -= step;
    if ((x - r.centre()).cwiseAbs().maxCoeff() > 1.5 * r.size) return std::nullopt;  // left
    if (step.norm() <= params.newton_tolerance) {
      const double slack = 1e-9;
      if (x.x() < r.s0 - slack || x.x() > r.s0 + r.size + slack || x.y() < r.t0 - slack ||
          x.y() > r.t0 + r.size + slack)
        return std::nullopt;
      return Vec2(std::clamp(x.x(), r.s0, r.s0 + r.size), std::clamp(x.y(), r.t0, r.t0 + r.size));
    }
  }
  return std::nullopt;
}

struct CellSearch {
  const BilinearPatch& patch;
  const TopologyParams& params;
  std::vector<std::pair<Vec2, bool>> zeros;  // local (s, t), approximate?

  void search(const SubRect& r, int depth) {
    std::array<Vec2, 4> f;
    const auto c = r.corners();
    for (int k = 0; k < 4; ++k) f[k] = patch(c[k].x(), c[k].y());
    if (!mayContainZero(f)) return;
    const bool unique = jacobianRegular(patch, r);
    if (unique || depth == params.subdivision_depth) {
      if (auto z = newtonInRect(patch, r, params)) {
        if (unique) {
          zeros.emplace_back(*z, false);
          return;
        }
        // Not unique: keep the Newton zero but still look for a second one below.
        zeros.emplace_back(*z, false);
        if (depth == params.subdivision_depth) return;
      } else if (depth == params.subdivision_depth) {
        // Degenerate zero (det J = 0 at the zero, where Newton stalls) or a near miss of the two
        // zero curves at 2^-depth resolution: report the centre, flagged approximate.
        if (!unique) zeros.emplace_back(r.centre(), true);
        return;
      }
    }
    const double h = r.size / 2;
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di) search({r.s0 + di * h, r.t0 + dj * h, h}, depth + 1);
  }
};

bool isZeroNode(const Vec2& w) { return w.x() == 0.0 && w.y() == 0.0; }

/// A cell edge whose two end nodes are exactly zero carries a segment of zeros (no-slip wall,
/// solid obstacle): not an isolated critical point.
bool hasZeroEdge(const PlanarField& f, int i, int j) {
  const bool z00 = isZeroNode(f.node(i, j)), z10 = isZeroNode(f.node(i + 1, j));
  const bool z01 = isZeroNode(f.node(i, j + 1)), z11 = isZeroNode(f.node(i + 1, j + 1));
  return (z00 && z10) || (z01 && z11) || (z00 && z01) || (z10 && z11);
}

}  // namespace

std::vector<InterpolantZero> findZerosInCell(const PlanarField& field, int i, int j,
                                             const TopologyParams& params) {
  const BilinearPatch patch = field.cellPatch(i, j);
  std::array<Vec2, 4> f{field.node(i, j), field.node(i + 1, j), field.node(i, j + 1),
                        field.node(i + 1, j + 1)};
  for (const Vec2& c : f)
    if (!c.allFinite()) return {};  // NaN/inf: no trustworthy zero here
  if (!mayContainZero(f) || hasZeroEdge(field, i, j)) return {};
  CellSearch s{patch, params, {}};
  s.search({0.0, 0.0, 1.0}, 0);
  std::vector<InterpolantZero> out;
  for (const auto& [st, approximate] : s.zeros)
    out.push_back({Vec2(i + st.x(), j + st.y()), {i, j}, approximate});
  return out;
}

std::vector<InterpolantZero> findInterpolantZeros(const PlanarField& field,
                                                  const TopologyParams& params) {
  const int cellsX = field.nx() - 1, cellsY = field.ny() - 1;
  std::vector<std::vector<InterpolantZero>> rows(cellsY);
#pragma omp parallel for schedule(dynamic, 8)
  for (int j = 0; j < cellsY; ++j)
    for (int i = 0; i < cellsX; ++i) {
      auto z = findZerosInCell(field, i, j, params);
      rows[j].insert(rows[j].end(), z.begin(), z.end());
    }
  std::vector<InterpolantZero> raw;
  for (auto& r : rows) raw.insert(raw.end(), r.begin(), r.end());

  // One zero found from several cells (shared node or edge), or several approximate zeros of
  // the deepest subdivision level around one degenerate zero: merge, keeping the first found
  // (lowest cell index) and preferring a Newton zero over an approximate one.
  const double mergeRadius = std::max(1e-6, 3.0 * std::ldexp(1.0, -params.subdivision_depth));
  std::vector<Vec2> positions;
  for (const auto& z : raw) positions.push_back(z.q);
  std::vector<InterpolantZero> merged;
  for (const auto& group : groupsFromLabels(singleLinkageLabels(positions, mergeRadius))) {
    InterpolantZero best = raw[group.front()];
    for (int m : group)
      if (best.approximate && !raw[m].approximate) best = raw[m];
    if (best.approximate) {  // centroid of the approximate zeros
      Vec2 sum = Vec2::Zero();
      for (int m : group) sum += raw[m].q;
      best.q = sum / static_cast<double>(group.size());
    }
    merged.push_back(best);
  }
  return merged;
}

}  // namespace fluidviz::topology
