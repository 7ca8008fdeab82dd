#include "solvers/surface/operators/HarmonicFields.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

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

}  // namespace

std::vector<Eigen::Vector3d> harmonicField(const TriangleMesh& mesh, const FaceGeometry& faces,
                                           const Eigen::VectorXd& turns) {
  const int n = mesh.vertexCount();
  std::vector<Eigen::Vector3d> g(mesh.faces.size());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (std::size_t t = 0; t < mesh.faces.size(); ++t) {
    g[t] = unwrappedGradient(faces, mesh.faces[t], t, turns);
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
