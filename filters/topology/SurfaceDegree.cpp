#include "filters/topology/SurfaceDegree.h"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <Eigen/Geometry>

namespace fluidviz::topology {

namespace {
/// Refinement goes on until the field turns by less than this along every edge: small enough
/// that no zero of the field can slip between the samples of a triangle unnoticed on the smooth
/// fields met here, far from the pi at which the spherical triangle would become ambiguous.
constexpr double kMaxEdgeTurn = std::numbers::pi / 8;
constexpr int kMaxSphereLevel = 6;   // 81920 triangles
constexpr int kMaxBoxDoublings = 3;  // 8x the starting divisions

/// Orients every triangle counter-clockwise seen from outside (normal away from `inside`).
void orientOutward(TriangleSurface& s, const Vec3& inside) {
  for (auto& t : s.triangles) {
    const Vec3& a = s.vertices[t[0]];
    const Vec3 n = (s.vertices[t[1]] - a).cross(s.vertices[t[2]] - a);
    if (n.dot((a + s.vertices[t[1]] + s.vertices[t[2]]) / 3 - inside) < 0) std::swap(t[1], t[2]);
  }
}

/// Splits every triangle in four; new vertices at the edge mid-points, pushed onto the unit
/// sphere. Shared edges get one mid-point (the mesh stays conforming).
void subdivideOnSphere(TriangleSurface& s) {
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto it = midpoint.find(key);
    if (it != midpoint.end()) return it->second;
    s.vertices.push_back((s.vertices[a] + s.vertices[b]).normalized());
    const int id = static_cast<int>(s.vertices.size()) - 1;
    midpoint.emplace(key, id);
    return id;
  };
  std::vector<std::array<int, 3>> finer;
  finer.reserve(4 * s.triangles.size());
  for (const auto& t : s.triangles) {
    const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
    finer.push_back({t[0], ab, ca});
    finer.push_back({t[1], bc, ab});
    finer.push_back({t[2], ca, bc});
    finer.push_back({ab, bc, ca});
  }
  s.triangles = std::move(finer);
}

TriangleSurface icosahedron() {
  const double t = std::numbers::phi;
  TriangleSurface s;
  s.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& v : s.vertices) v.normalize();
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  orientOutward(s, Vec3::Zero());
  return s;
}

double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

/// The unit icospheres of levels 0..kMaxSphereLevel, built once: every index sphere of a field
/// is one of them scaled and moved, and building them (the mid-point map) cost more than the
/// degree integrals themselves.
const TriangleSurface& unitIcosphere(int level) {
  static const std::vector<TriangleSurface> spheres = [] {
    std::vector<TriangleSurface> all{icosahedron()};
    for (int l = 1; l <= kMaxSphereLevel; ++l) {
      all.push_back(all.back());
      subdivideOnSphere(all.back());
    }
    return all;
  }();
  return spheres[level];
}
}  // namespace

TriangleSurface icosphere(int level) {
  if (level <= kMaxSphereLevel) return unitIcosphere(level);
  TriangleSurface s = unitIcosphere(kMaxSphereLevel);
  for (int l = kMaxSphereLevel; l < level; ++l) subdivideOnSphere(s);
  return s;
}

TriangleSurface boxSurface(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& divisions) {
  TriangleSurface s;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const int nb = divisions[b], nc = divisions[c];
    for (int side = 0; side < 2; ++side) {
      const int first = static_cast<int>(s.vertices.size());
      for (int jc = 0; jc <= nc; ++jc)
        for (int jb = 0; jb <= nb; ++jb) {
          Vec3 p;
          p[a] = side ? hi[a] : lo[a];
          p[b] = lo[b] + (hi[b] - lo[b]) * jb / nb;
          p[c] = lo[c] + (hi[c] - lo[c]) * jc / nc;
          s.vertices.push_back(p);
        }
      auto id = [&](int jb, int jc) { return first + jc * (nb + 1) + jb; };
      for (int jc = 0; jc < nc; ++jc)
        for (int jb = 0; jb < nb; ++jb) {
          s.triangles.push_back({id(jb, jc), id(jb + 1, jc), id(jb + 1, jc + 1)});
          s.triangles.push_back({id(jb, jc), id(jb + 1, jc + 1), id(jb, jc + 1)});
        }
    }
  }
  orientOutward(s, (lo + hi) / 2);
  return s;
}

double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 2.0 * std::atan2(a.dot(b.cross(c)), 1.0 + a.dot(b) + b.dot(c) + c.dot(a));
}

std::optional<DegreeMeasurement> degreeOnSurface(const FieldAt& field,
                                                 const TriangleSurface& surface) {
  std::vector<Vec3> unit;
  unit.reserve(surface.vertices.size());
  for (const Vec3& p : surface.vertices) {
    const Vec3 v = field(p);
    const double n = v.norm();
    if (!(n > 0.0) || !std::isfinite(n)) return std::nullopt;
    unit.push_back(v / n);
  }
  DegreeMeasurement m;
  m.triangles = static_cast<int>(surface.triangles.size());
  double total = 0.0;
  // The largest turn is the angle of the edge with the smallest dot product (unit vectors): one
  // atan2 instead of three per triangle.
  double smallestDot = 2.0;
  const Vec3 *turnA = nullptr, *turnB = nullptr;
  const auto edge = [&](const Vec3& a, const Vec3& b) {
    const double d = a.dot(b);
    if (d < smallestDot) smallestDot = d, turnA = &a, turnB = &b;
  };
  for (const auto& t : surface.triangles) {
    const Vec3 &a = unit[t[0]], &b = unit[t[1]], &c = unit[t[2]];
    total += solidAngle(a, b, c);
    edge(a, b);
    edge(b, c);
    edge(c, a);
  }
  if (turnA) m.max_edge_turn = angleBetween(*turnA, *turnB);
  m.degree = static_cast<int>(std::lround(total / (4 * std::numbers::pi)));
  m.resolved = m.max_edge_turn < kMaxEdgeTurn;
  return m;
}

std::optional<DegreeMeasurement> degreeOnSphere(const FieldAt& field, const Vec3& centre,
                                                double radius) {
  for (int level = 2;; ++level) {
    TriangleSurface s = unitIcosphere(level);
    for (Vec3& v : s.vertices) v = centre + radius * v;
    auto m = degreeOnSurface(field, s);
    if (!m || m->resolved || level == kMaxSphereLevel) return m;
  }
}

std::optional<DegreeMeasurement> degreeOnBox(const FieldAt& field, const Vec3& lo, const Vec3& hi,
                                             const std::array<int, 3>& divisions) {
  std::array<int, 3> d = divisions;
  for (int doubling = 0;; ++doubling) {
    auto m = degreeOnSurface(field, boxSurface(lo, hi, d));
    if (!m || m->resolved || doubling == kMaxBoxDoublings) return m;
    for (int& x : d) x *= 2;
  }
}

}  // namespace fluidviz::topology
