#include "solvers/surface/operators/SurfaceOperators.h"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace fluidviz::surface {

namespace {

using Eigen::Vector3d;

/// Cotangent of the angle at corner p between the edges to a and b.
double cotangent(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d u = a - p, v = b - p;
  return u.dot(v) / u.cross(v).norm();
}

double cornerAngle(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d u = a - p, v = b - p;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// The mixed-Voronoi share of corner k of a face (Meyer et al. 2003, Fig. 4).
double mixedVoronoiShare(const std::array<Vector3d, 3>& x, int k, double area) {
  auto corner = [&](int c) { return x[c]; };
  for (int c = 0; c < 3; ++c) {
    const Vector3d u = corner((c + 1) % 3) - corner(c), v = corner((c + 2) % 3) - corner(c);
    if (u.dot(v) < 0.0) return c == k ? area / 2.0 : area / 4.0;  // obtuse at corner c
  }
  // Voronoi region of corner k: (|e_kj|^2 cot(angle at l) + |e_kl|^2 cot(angle at j)) / 8.
  const int j = (k + 1) % 3, l = (k + 2) % 3;
  return ((x[j] - x[k]).squaredNorm() * cotangent(x[l], x[k], x[j]) +
          (x[l] - x[k]).squaredNorm() * cotangent(x[j], x[k], x[l])) / 8.0;
}

std::array<Vector3d, 3> cornersOf(const TriangleMesh& m, const std::array<int, 3>& f) {
  return {m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]};
}

}  // namespace

FaceGeometry computeFaceGeometry(const TriangleMesh& mesh) {
  FaceGeometry g;
  const std::size_t nf = mesh.faces.size();
  g.area.resize(nf);
  g.normal.resize(nf);
  g.hatGradient.resize(nf);
  for (std::size_t t = 0; t < nf; ++t) {
    const auto x = cornersOf(mesh, mesh.faces[t]);
    const Vector3d c = (x[1] - x[0]).cross(x[2] - x[0]);
    g.area[t] = 0.5 * c.norm();
    g.normal[t] = c.normalized();
    for (int k = 0; k < 3; ++k)
      g.hatGradient[t][k] = g.normal[t].cross(x[(k + 2) % 3] - x[(k + 1) % 3]) / (2.0 * g.area[t]);
  }
  return g;
}

SparseMatrix cotanStiffness(const TriangleMesh& mesh) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * mesh.faces.size());
  for (const auto& f : mesh.faces) {
    const auto x = cornersOf(mesh, f);
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k faces the edge (i, j).
      const int i = f[(k + 1) % 3], j = f[(k + 2) % 3];
      const double w = 0.5 * cotangent(x[k], x[(k + 1) % 3], x[(k + 2) % 3]);
      entries.emplace_back(i, j, -w);
      entries.emplace_back(j, i, -w);
      entries.emplace_back(i, i, w);
      entries.emplace_back(j, j, w);
    }
  }
  SparseMatrix s(mesh.vertexCount(), mesh.vertexCount());
  s.setFromTriplets(entries.begin(), entries.end());
  return s;
}

Eigen::VectorXd lumpedMass(const TriangleMesh& mesh, MassLumping lumping) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(mesh.vertexCount());
  for (const auto& f : mesh.faces) {
    const auto x = cornersOf(mesh, f);
    const double area = 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
    for (int k = 0; k < 3; ++k)
      m[f[k]] += lumping == MassLumping::barycentric ? area / 3.0 : mixedVoronoiShare(x, k, area);
  }
  return m;
}

Eigen::VectorXd angleDefect(const TriangleMesh& mesh) {
  Eigen::VectorXd k = Eigen::VectorXd::Constant(mesh.vertexCount(), 2.0 * std::numbers::pi);
  for (const auto& f : mesh.faces) {
    const auto x = cornersOf(mesh, f);
    for (int c = 0; c < 3; ++c) k[f[c]] -= cornerAngle(x[c], x[(c + 1) % 3], x[(c + 2) % 3]);
  }
  return k;
}

std::vector<Eigen::Vector3d> faceGradient(const FaceGeometry& geometry, const TriangleMesh& mesh,
                                          const Eigen::VectorXd& f) {
  std::vector<Vector3d> g(mesh.faces.size());
  for (std::size_t t = 0; t < mesh.faces.size(); ++t) {
    const auto& face = mesh.faces[t];
    const auto& h = geometry.hatGradient[t];
    g[t] = f[face[0]] * h[0] + f[face[1]] * h[1] + f[face[2]] * h[2];
  }
  return g;
}

std::vector<Eigen::Vector3d> vertexNormals(const TriangleMesh& mesh) {
  std::vector<Vector3d> n(mesh.vertices.size(), Vector3d::Zero());
  for (const auto& f : mesh.faces) {
    const auto x = cornersOf(mesh, f);
    for (int c = 0; c < 3; ++c) {
      // Max 1999: the corner's normal e1 x e2 weighted by 1 / (|e1|^2 |e2|^2).
      const Vector3d e1 = x[(c + 1) % 3] - x[c], e2 = x[(c + 2) % 3] - x[c];
      n[f[c]] += e1.cross(e2) / (e1.squaredNorm() * e2.squaredNorm());
    }
  }
  for (Vector3d& v : n) v.normalize();
  return n;
}

SparseMatrix diagonalMatrix(const Eigen::VectorXd& d) {
  SparseMatrix m(d.size(), d.size());
  m.reserve(Eigen::VectorXi::Constant(d.size(), 1));
  for (Eigen::Index i = 0; i < d.size(); ++i) m.insert(i, i) = d[i];
  return m;
}

double integrate(const Eigen::VectorXd& mass, const Eigen::VectorXd& f) { return mass.dot(f); }

}  // namespace fluidviz::surface
