#include "solvers/surface/mesh/TriangleMesh.h"

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace fluidviz::surface {

namespace {

TriangleMesh icosahedron() {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh m;
  m.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return m;
}

/// Splits every face into four through its edge mid-points (one new vertex per edge).
TriangleMesh subdivide(const TriangleMesh& in) {
  TriangleMesh out;
  out.vertices = in.vertices;
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    auto [it, inserted] = midpoint.try_emplace(key, out.vertexCount());
    if (inserted) out.vertices.push_back(0.5 * (in.vertices[a] + in.vertices[b]));
    return it->second;
  };
  out.faces.reserve(4 * in.faces.size());
  for (const auto& [a, b, c] : in.faces) {
    const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.faces.push_back({a, ab, ca});
    out.faces.push_back({b, bc, ab});
    out.faces.push_back({c, ca, bc});
    out.faces.push_back({ab, bc, ca});
  }
  return out;
}

}  // namespace

TriangleMesh makeIcosphere(double radius, int level) {
  if (!(radius > 0.0)) throw std::invalid_argument("icosphere radius must be > 0");
  if (level < 0 || level > 8)
    throw std::invalid_argument("icosphere level " + std::to_string(level) + " outside [0, 8]");
  TriangleMesh m = icosahedron();
  for (int i = 0; i < level; ++i) m = subdivide(m);
  for (Eigen::Vector3d& v : m.vertices) v *= radius / v.norm();
  return m;
}

TriangleMesh makeTorus(double majorRadius, double minorRadius, int n, int m) {
  if (!(minorRadius > 0.0 && majorRadius > minorRadius))
    throw std::invalid_argument("torus radii need R > r > 0");
  if (n < 3 || m < 3) throw std::invalid_argument("torus needs n, m >= 3");
  TriangleMesh t;
  t.vertices.reserve(static_cast<std::size_t>(n) * m);
  for (int i = 0; i < n; ++i) {
    const double u = 2.0 * std::numbers::pi * i / n;
    for (int j = 0; j < m; ++j) {
      const double v = 2.0 * std::numbers::pi * j / m;
      const double rho = majorRadius + minorRadius * std::cos(v);
      t.vertices.emplace_back(rho * std::cos(u), rho * std::sin(u), minorRadius * std::sin(v));
    }
  }
  auto id = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  // d/du x d/dv points outwards for this parameterisation, so (i, j) -> (i+1, j) -> (i+1, j+1)
  // runs counter-clockwise seen from outside.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return t;
}

}  // namespace fluidviz::surface
