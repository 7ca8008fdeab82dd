#include "solvers/surface/mesh/ManifoldCheck.h"

#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>

namespace fluidviz::surface {

namespace {

/// Per undirected edge: how many faces use it, and how many of them run it from low to high.
struct EdgeUse {
  int faces = 0;
  int forward = 0;
};

double faceArea(const TriangleMesh& m, const std::array<int, 3>& f) {
  return 0.5 * (m.vertices[f[1]] - m.vertices[f[0]]).cross(m.vertices[f[2]] - m.vertices[f[0]]).norm();
}

bool hasObtuseAngle(const TriangleMesh& m, const std::array<int, 3>& f) {
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& p = m.vertices[f[k]];
    if ((m.vertices[f[(k + 1) % 3]] - p).dot(m.vertices[f[(k + 2) % 3]] - p) < 0.0) return true;
  }
  return false;
}

}  // namespace

ManifoldReport checkManifold(const TriangleMesh& mesh) {
  ManifoldReport r;
  r.vertices = mesh.vertexCount();
  r.faces = mesh.faceCount();
  std::vector<char> used(mesh.vertices.size(), 0);
  std::map<std::pair<int, int>, EdgeUse> edges;
  double totalArea = 0.0;
  std::vector<const std::array<int, 3>*> goodFaces;
  for (const auto& f : mesh.faces) {
    bool inRange = true;
    for (int v : f) inRange = inRange && v >= 0 && v < r.vertices;
    if (!inRange) {
      ++r.badIndices;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      used[a] = 1;
      EdgeUse& e = edges[{std::min(a, b), std::max(a, b)}];
      ++e.faces;
      e.forward += a < b;
    }
    totalArea += faceArea(mesh, f);
    goodFaces.push_back(&f);
  }
  const double meanArea = goodFaces.empty() ? 0.0 : totalArea / goodFaces.size();
  for (const auto* f : goodFaces) {
    const bool repeated = (*f)[0] == (*f)[1] || (*f)[1] == (*f)[2] || (*f)[2] == (*f)[0];
    if (repeated || faceArea(mesh, *f) < 1e-12 * meanArea)
      ++r.degenerateFaces;
    else if (hasObtuseAngle(mesh, *f))
      ++r.obtuseFaces;
  }
  r.edges = static_cast<int>(edges.size());
  for (const auto& [key, e] : edges) {
    if (e.faces == 1) ++r.boundaryEdges;
    if (e.faces >= 3) ++r.nonManifoldEdges;
    // Two consistently oriented faces run their shared edge in opposite directions.
    if (e.faces == 2 && e.forward != 1) ++r.inconsistentEdges;
  }
  for (char u : used) r.isolatedVertices += !u;
  r.eulerCharacteristic = r.vertices - r.edges + r.faces;
  return r;
}

std::string ManifoldReport::describe() const {
  std::ostringstream s;
  if (valid())
    s << (closed() ? "closed" : "bordered") << " 2-manifold";
  else
    s << "not a consistently oriented 2-manifold:";
  auto defect = [&](int n, const char* what) {
    if (n > 0) s << " " << n << " " << what << ";";
  };
  defect(badIndices, "faces with a vertex index outside the vertex list");
  defect(nonManifoldEdges, "non-manifold edges (3 or more faces)");
  defect(inconsistentEdges, "edges whose two faces disagree in orientation");
  defect(degenerateFaces, "degenerate triangles (repeated vertex or zero area)");
  defect(isolatedVertices, "vertices of no triangle");
  s << " V = " << vertices << ", E = " << edges << ", F = " << faces
    << ", chi = " << eulerCharacteristic << ", boundary edges " << boundaryEdges
    << ", obtuse triangles " << obtuseFaces;
  return s.str();
}

void requireClosedManifold(const TriangleMesh& mesh) {
  const ManifoldReport r = checkManifold(mesh);
  if (!r.valid() || !r.closed())
    throw std::invalid_argument("surface mesh: " + r.describe() +
                                (r.valid() ? " (the solvers need a closed surface)" : ""));
}

}  // namespace fluidviz::surface
