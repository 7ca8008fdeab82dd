#include "solvers/surface/operators/HarmonicFields.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <map>
#include <queue>
#include <set>
#include <utility>

#include <Eigen/SparseCholesky>

namespace fluidviz::surface {

namespace {

/// The P1 gradient on face t of the angle, unwrapped relative to the face's first corner.
Eigen::Vector3d unwrappedGradient(const FaceGeometry& faces, const std::array<int, 3>& f,
                                  std::size_t t, const Eigen::VectorXd& turns) {
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (int k = 1; k < 3; ++k) {
    double d = turns[f[k]] - turns[f[0]];
    d -= std::round(d);  // the nearest representative: a face spans well under half a turn
    g += d * faces.hatGradient[t][k];
  }
  return g;
}

/// h = (g - grad p) x n for a face field g of a closed 1-form: S p = <g, grad phi_i>.
std::vector<Eigen::Vector3d> harmonicPart(const TriangleMesh& mesh, const FaceGeometry& faces,
                                          std::vector<Eigen::Vector3d> g) {
  const int n = mesh.vertexCount();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (std::size_t t = 0; t < mesh.faces.size(); ++t) {
    for (int k = 0; k < 3; ++k)
      rhs[mesh.faces[t][k]] += faces.area[t] * g[t].dot(faces.hatGradient[t][k]);
  }
  // S p = rhs with the last vertex pinned (rhs sums to zero: the hat gradients of a face do).
  const SparseMatrix s = cotanStiffness(mesh);
  Eigen::SimplicialLDLT<SparseMatrix> solver(s.topLeftCorner(n - 1, n - 1));
  if (solver.info() != Eigen::Success) throw std::runtime_error("harmonicField: factorisation failed");
  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  p.head(n - 1) = solver.solve(rhs.head(n - 1));
  const std::vector<Eigen::Vector3d> gradP = faceGradient(faces, mesh, p);
  for (std::size_t t = 0; t < g.size(); ++t) g[t] = (g[t] - gradP[t]).cross(faces.normal[t]);
  return g;
}

using EdgeKey = std::pair<int, int>;  // (low, high) vertex

struct EdgeFaces {
  int left = -1;   ///< the face running the edge from low to high (on its left)
  int right = -1;  ///< the face running it from high to low
};

std::map<EdgeKey, EdgeFaces> edgeFaces(const TriangleMesh& mesh) {
  std::map<EdgeKey, EdgeFaces> edges;
  for (int t = 0; t < mesh.faceCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces[t][k], b = mesh.faces[t][(k + 1) % 3];
      EdgeFaces& e = edges[{std::min(a, b), std::max(a, b)}];
      (a < b ? e.left : e.right) = t;
    }
  return edges;
}

/// Edges of a breadth-first spanning tree of the vertices.
std::set<EdgeKey> vertexTree(const TriangleMesh& mesh, const std::map<EdgeKey, EdgeFaces>& edges) {
  std::vector<std::vector<int>> neighbours(mesh.vertices.size());
  for (const auto& [key, e] : edges) {
    neighbours[key.first].push_back(key.second);
    neighbours[key.second].push_back(key.first);
  }
  std::set<EdgeKey> tree;
  std::vector<char> seen(mesh.vertices.size(), 0);
  std::queue<int> queue;
  queue.push(0);
  seen[0] = 1;
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    for (int w : neighbours[v])
      if (!seen[w]) {
        seen[w] = 1;
        tree.insert({std::min(v, w), std::max(v, w)});
        queue.push(w);
      }
  }
  return tree;
}

}  // namespace

std::vector<Eigen::Vector3d> harmonicField(const TriangleMesh& mesh, const FaceGeometry& faces,
                                           const Eigen::VectorXd& turns) {
  std::vector<Eigen::Vector3d> g(mesh.faces.size());
  for (std::size_t t = 0; t < mesh.faces.size(); ++t)
    g[t] = unwrappedGradient(faces, mesh.faces[t], t, turns);
  return harmonicPart(mesh, faces, std::move(g));
}

std::vector<std::vector<Eigen::Vector3d>> harmonicBasis(const TriangleMesh& mesh,
                                                        const FaceGeometry& faces) {
  const auto edges = edgeFaces(mesh);
  const std::set<EdgeKey> tree = vertexTree(mesh, edges);
  // The dual tree: faces joined across edges outside the vertex tree; parent edge per face.
  std::vector<std::vector<std::pair<int, EdgeKey>>> across(mesh.faces.size());
  for (const auto& [key, e] : edges)
    if (!tree.count(key)) {
      across[e.left].push_back({e.right, key});
      across[e.right].push_back({e.left, key});
    }
  std::vector<int> parent(mesh.faces.size(), -2), depth(mesh.faces.size(), 0);
  std::vector<EdgeKey> parentEdge(mesh.faces.size());
  std::set<EdgeKey> cotree;
  std::queue<int> queue;
  queue.push(0);
  parent[0] = -1;
  while (!queue.empty()) {
    const int f = queue.front();
    queue.pop();
    for (const auto& [g, key] : across[f])
      if (parent[g] == -2) {
        parent[g] = f;
        parentEdge[g] = key;
        depth[g] = depth[f] + 1;
        cotree.insert(key);
        queue.push(g);
      }
  }
  std::vector<std::vector<Eigen::Vector3d>> basis;
  for (const auto& [key, e] : edges) {
    if (tree.count(key) || cotree.count(key)) continue;
    // The closed 1-form of the dual loop: left face -> right face across this edge, then back
    // through the dual tree. Crossing edge (lo, hi) from its left face to its right face counts
    // +1 on lo -> hi.
    std::map<EdgeKey, double> form;
    auto cross = [&](const EdgeKey& k, int from) {
      form[k] += edges.at(k).left == from ? 1.0 : -1.0;
    };
    cross(key, e.left);
    int a = e.right, b = e.left;  // walk a and b up to their common ancestor
    std::vector<std::pair<EdgeKey, int>> fromB;
    while (a != b) {
      if (depth[a] >= depth[b]) {
        cross(parentEdge[a], a);  // a -> parent(a)
        a = parent[a];
      } else {
        fromB.push_back({parentEdge[b], parent[b]});  // later: parent(b) -> b
        b = parent[b];
      }
    }
    for (auto it = fromB.rbegin(); it != fromB.rend(); ++it) cross(it->first, it->second);
    // Its face field: values 0 at the first corner and the form's sums along the face's edges.
    std::vector<Eigen::Vector3d> g(mesh.faces.size());
    for (std::size_t t = 0; t < mesh.faces.size(); ++t) {
      const auto& f = mesh.faces[t];
      double value = 0.0;
      g[t] = Eigen::Vector3d::Zero();
      for (int k = 1; k < 3; ++k) {
        const int p = f[k - 1], q = f[k];
        const auto it = form.find({std::min(p, q), std::max(p, q)});
        if (it != form.end()) value += p < q ? it->second : -it->second;
        g[t] += value * faces.hatGradient[t][k];
      }
    }
    basis.push_back(harmonicPart(mesh, faces, std::move(g)));
  }
  return basis;
}

std::vector<Eigen::VectorXd> torusAngleTurns(const TriangleMesh& mesh, double majorRadius) {
  const double turn = 2.0 * std::numbers::pi;
  Eigen::VectorXd around(mesh.vertexCount()), tube(mesh.vertexCount());
  for (int i = 0; i < mesh.vertexCount(); ++i) {
    const Eigen::Vector3d& x = mesh.vertices[i];
    around[i] = std::atan2(x.y(), x.x()) / turn;
    tube[i] = std::atan2(x.z(), std::hypot(x.x(), x.y()) - majorRadius) / turn;
  }
  return {around, tube};
}

}  // namespace fluidviz::surface
