#include "solvers/surface/VorticityStream.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <string>

#include <Eigen/Geometry>

#include "solvers/surface/mesh/ManifoldCheck.h"

namespace fluidviz::surface {

namespace {

using Eigen::Vector3d;
using Eigen::VectorXd;

/// K per vertex: the settings' (the smooth surface's) or angle defect / lumped mass.
VectorXd vertexCurvature(const TriangleMesh& mesh, const VectorXd& mass,
                         const VorticityStreamSettings& s) {
  if (s.gaussianCurvature.size() == 0) return angleDefect(mesh).cwiseQuotient(mass);
  if (s.gaussianCurvature.size() != mesh.vertexCount())
    throw std::invalid_argument("VorticityStream: gaussianCurvature needs one value per vertex");
  return s.gaussianCurvature;
}

/// The viscous matrix A of M d omega / dt = ... - nu A omega (see the header comment).
SparseMatrix viscousMatrix(const SparseMatrix& stiffness, const VectorXd& mass,
                           const VectorXd& curvature, ViscousOperator op) {
  if (op == ViscousOperator::laplacian) return stiffness;
  // + 2 K omega integrated over a vertex's cell: 2 M_i K_i (the angle defect by default).
  return stiffness - 2.0 * diagonalMatrix(mass.cwiseProduct(curvature));
}

}  // namespace

VorticityStream::VorticityStream(const TriangleMesh& mesh, const VorticityStreamSettings& settings)
    : mesh_(mesh), settings_(settings) {
  requireClosedManifold(mesh_);
  if (!(settings.viscosity >= 0.0) || !(settings.timeStep > 0.0))
    throw std::invalid_argument("VorticityStream needs viscosity >= 0 and a time step > 0");
  faces_ = computeFaceGeometry(mesh_);
  mass_ = lumpedMass(mesh_, settings.lumping);
  stiffness_ = cotanStiffness(mesh_);
  const std::vector<Vector3d> normals = vertexNormals(mesh_);
  coriolis_.resize(mesh_.vertexCount());
  for (int i = 0; i < mesh_.vertexCount(); ++i)
    coriolis_[i] = 2.0 * settings.rotationRate * normals[i].z();

  const VectorXd curvature = vertexCurvature(mesh_, mass_, settings);
  if (settings.viscousOperator == ViscousOperator::deformation) {
    curvatureGradient_ = faceGradient(faces_, mesh_, curvature);
    faceCurvature_.resize(mesh_.faceCount());
    for (int t = 0; t < mesh_.faceCount(); ++t) {
      const auto& f = mesh_.faces[t];
      faceCurvature_[t] = (curvature[f[0]] + curvature[f[1]] + curvature[f[2]]) / 3.0;
    }
  }
  const SparseMatrix half =
      (0.5 * settings.timeStep * settings.viscosity) *
      viscousMatrix(stiffness_, mass_, curvature, settings.viscousOperator);
  const SparseMatrix m = diagonalMatrix(mass_);
  explicitPart_ = m - half;
  implicitPart_.compute(m + half);
  // S's null space is the constants: pinning the last vertex makes the rest non-singular, and a
  // right-hand side of zero sum then satisfies the dropped row too.
  const Eigen::Index n = mesh_.vertexCount();
  poisson_.compute(SparseMatrix(stiffness_.topLeftCorner(n - 1, n - 1)));
  if (implicitPart_.info() != Eigen::Success || poisson_.info() != Eigen::Success)
    throw std::runtime_error("VorticityStream: a sparse factorisation failed");
  if (!settings.bodyForce.empty() && settings.bodyForce.size() != mesh_.faces.size())
    throw std::invalid_argument("VorticityStream: bodyForce needs one vector per face");
  forcing_ = settings.bodyForce.empty() ? VectorXd::Zero(mesh_.vertexCount())
                                        : weakCurl(settings.bodyForce);
  omega_ = VectorXd::Zero(mesh_.vertexCount());
  psi_ = omega_;
  lastIncrement_ = omega_;
}

VectorXd VorticityStream::weakCurl(const std::vector<Vector3d>& field) const {
  VectorXd c = VectorXd::Zero(mesh_.vertexCount());
  for (std::size_t t = 0; t < mesh_.faces.size(); ++t)
    for (int k = 0; k < 3; ++k)
      c[mesh_.faces[t][k]] +=
          faces_.area[t] * field[t].dot(faces_.hatGradient[t][k].cross(faces_.normal[t]));
  return c;
}

VectorXd VorticityStream::removeMean(const VectorXd& f) const {
  return f.array() - mass_.dot(f) / mass_.sum();
}

void VorticityStream::setVorticity(const VectorXd& omega) {
  if (omega.size() != mesh_.vertexCount())
    throw std::invalid_argument("setVorticity: one value per vertex expected");
  omega_ = removeMean(omega);
  psi_ = streamFunctionOf(omega_);
  lastIncrement_ = VectorXd::Zero(omega_.size());
}

VectorXd VorticityStream::streamFunctionOf(const VectorXd& omega) const {
  const Eigen::Index n = mesh_.vertexCount();
  const VectorXd rhs = mass_.cwiseProduct(removeMean(omega));
  VectorXd psi(n);
  psi.head(n - 1) = poisson_.solve(rhs.head(n - 1));
  psi[n - 1] = 0.0;
  return removeMean(psi);
}

VectorXd VorticityStream::galerkinJacobian(const VectorXd& psi, const VectorXd& q) const {
  VectorXd b = VectorXd::Zero(mesh_.vertexCount());
  for (std::size_t t = 0; t < mesh_.faces.size(); ++t) {
    const auto& f = mesh_.faces[t];
    const auto& h = faces_.hatGradient[t];
    const Vector3d gradPsi = psi[f[0]] * h[0] + psi[f[1]] * h[1] + psi[f[2]] * h[2];
    const Vector3d gradQ = q[f[0]] * h[0] + q[f[1]] * h[1] + q[f[2]] * h[2];
    const double share = faces_.area[t] / 3.0 * faces_.normal[t].dot(gradPsi.cross(gradQ));
    for (int v : f) b[v] += share;
  }
  return b;
}

VectorXd VorticityStream::curvatureGradientTerm(const VectorXd& psi) const {
  VectorXd g = VectorXd::Zero(mesh_.vertexCount());
  if (curvatureGradient_.empty()) return g;
  for (std::size_t t = 0; t < mesh_.faces.size(); ++t) {
    const auto& f = mesh_.faces[t];
    const auto& h = faces_.hatGradient[t];
    const Vector3d gradPsi = psi[f[0]] * h[0] + psi[f[1]] * h[1] + psi[f[2]] * h[2];
    const double share = -2.0 * faces_.area[t] / 3.0 * curvatureGradient_[t].dot(gradPsi);
    for (int v : f) g[v] += share;
  }
  return g;
}

void VorticityStream::setHarmonicFields(std::vector<std::vector<Vector3d>> fields) {
  for (const auto& h : fields)
    if (h.size() != mesh_.faces.size())
      throw std::invalid_argument("VorticityStream: a harmonic field needs one vector per face");
  harmonic_ = std::move(fields);
  const int k = static_cast<int>(harmonic_.size());
  gram_ = Eigen::MatrixXd::Zero(k, k);
  for (std::size_t t = 0; t < mesh_.faces.size(); ++t)
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) gram_(i, j) += faces_.area[t] * harmonic_[i][t].dot(harmonic_[j][t]);
  harmonicCoefficients_ = VectorXd::Zero(k);
  lastHarmonicIncrement_ = VectorXd::Zero(k);
}

void VorticityStream::setHarmonicCoefficients(const VectorXd& a) {
  if (a.size() != static_cast<Eigen::Index>(harmonic_.size()))
    throw std::invalid_argument("setHarmonicCoefficients: one coefficient per harmonic field");
  harmonicCoefficients_ = a;
  lastHarmonicIncrement_ = VectorXd::Zero(a.size());
}

VectorXd VorticityStream::harmonicPartOf(const std::vector<Vector3d>& field) const {
  VectorXd projection = VectorXd::Zero(static_cast<Eigen::Index>(harmonic_.size()));
  for (std::size_t t = 0; t < mesh_.faces.size(); ++t)
    for (std::size_t k = 0; k < harmonic_.size(); ++k)
      projection[k] += faces_.area[t] * field[t].dot(harmonic_[k][t]);
  return gram_.ldlt().solve(projection);
}

Vector3d VorticityStream::harmonicVelocity(std::size_t face, const VectorXd& a) const {
  Vector3d u = Vector3d::Zero();
  for (std::size_t k = 0; k < harmonic_.size(); ++k) u += a[k] * harmonic_[k][face];
  return u;
}

VectorXd VorticityStream::harmonicAdvection(const VectorXd& a, const VectorXd& q) const {
  VectorXd b = VectorXd::Zero(mesh_.vertexCount());
  for (std::size_t t = 0; t < mesh_.faces.size(); ++t) {
    const auto& f = mesh_.faces[t];
    const auto& h = faces_.hatGradient[t];
    const Vector3d gradQ = q[f[0]] * h[0] + q[f[1]] * h[1] + q[f[2]] * h[2];
    const double share = -faces_.area[t] / 3.0 * harmonicVelocity(t, a).dot(gradQ);
    for (int v : f) b[v] += share;
  }
  return b;
}

VectorXd VorticityStream::harmonicRate(const VectorXd& psi, const VectorXd& q,
                                       const VectorXd& a) const {
  VectorXd rhs = VectorXd::Zero(static_cast<Eigen::Index>(harmonic_.size()));
  for (std::size_t t = 0; t < mesh_.faces.size(); ++t) {
    const auto& f = mesh_.faces[t];
    const auto& h = faces_.hatGradient[t];
    const Vector3d gradQ = q[f[0]] * h[0] + q[f[1]] * h[1] + q[f[2]] * h[2];
    const double meanPsi = (psi[f[0]] + psi[f[1]] + psi[f[2]]) / 3.0;
    const double meanQ = (q[f[0]] + q[f[1]] + q[f[2]]) / 3.0;
    const Vector3d turned = faces_.normal[t].cross(harmonicVelocity(t, a));
    // The deformation operator's 2 nu K u, u the whole velocity on the face.
    const Vector3d viscous =
        faceCurvature_.size() == 0
            ? Vector3d::Zero()
            : Vector3d(2.0 * settings_.viscosity * faceCurvature_[t] *
                       ((psi[f[0]] * h[0] + psi[f[1]] * h[1] + psi[f[2]] * h[2]).cross(faces_.normal[t]) +
                        harmonicVelocity(t, a)));
    for (std::size_t k = 0; k < harmonic_.size(); ++k)
      rhs[k] += faces_.area[t] * (meanPsi * harmonic_[k][t].dot(gradQ) -
                                  meanQ * turned.dot(harmonic_[k][t]) + viscous.dot(harmonic_[k][t]));
  }
  return gram_.ldlt().solve(rhs);
}

void VorticityStream::step() {
  const double dt = settings_.timeStep;
  const VectorXd explicitRhs = explicitPart_ * omega_ + dt * forcing_;
  // Start from the previous step's increment extrapolated (a second-order guess saves about two
  // iterations; the converged result does not depend on it).
  VectorXd next = omega_ + lastIncrement_;
  const VectorXd& a = harmonicCoefficients_;
  VectorXd aNext = a + lastHarmonicIncrement_;
  lastIterations_ = 0;
  for (int it = 1; it <= settings_.maxIterations; ++it) {
    const VectorXd mid = 0.5 * (omega_ + next);
    const VectorXd psiMid = streamFunctionOf(mid);
    const VectorXd qMid = mid + coriolis_;
    VectorXd forcing = galerkinJacobian(psiMid, qMid);
    if (settings_.viscosity > 0.0) forcing += settings_.viscosity * curvatureGradientTerm(psiMid);
    VectorXd aUpdate = a;
    if (!harmonic_.empty()) {
      const VectorXd aMid = 0.5 * (a + aNext);
      forcing += harmonicAdvection(aMid, qMid);
      if (settings_.viscosity > 0.0 && faceCurvature_.size() > 0) {
        std::vector<Vector3d> stress(mesh_.faces.size());
        for (std::size_t t = 0; t < stress.size(); ++t)
          stress[t] = 2.0 * settings_.viscosity * faceCurvature_[t] * harmonicVelocity(t, aMid);
        forcing += weakCurl(stress);
      }
      aUpdate = a + dt * harmonicRate(psiMid, qMid, aMid);
    }
    // Inviscid, the implicit matrix is the diagonal M: a division instead of a back-solve.
    const VectorXd update = settings_.viscosity > 0.0
                                ? VectorXd(implicitPart_.solve(explicitRhs + dt * forcing))
                                : VectorXd((explicitRhs + dt * forcing).cwiseQuotient(mass_));
    const double change = std::max((update - next).lpNorm<Eigen::Infinity>(),
                                   harmonic_.empty() ? 0.0 : (aUpdate - aNext).lpNorm<Eigen::Infinity>());
    const double scale = std::max({update.lpNorm<Eigen::Infinity>(),
                                   harmonic_.empty() ? 0.0 : aUpdate.lpNorm<Eigen::Infinity>(), 1e-300});
    next = update;
    aNext = aUpdate;
    if (change <= settings_.iterationTolerance * scale) {
      lastIterations_ = it;
      break;
    }
  }
  if (lastIterations_ == 0)
    throw std::runtime_error("VorticityStream: the implicit midpoint iteration did not converge "
                             "in " + std::to_string(settings_.maxIterations) +
                             " iterations; shorten the time step (about edge length / speed)");
  // The deformation operator's 2 K term does not keep the mean of omega at zero on a mesh of
  // varying angle defect; a tangent field's vorticity has zero mean, so it is removed.
  next = removeMean(next);
  lastIncrement_ = next - omega_;
  omega_ = next;
  lastHarmonicIncrement_ = aNext - harmonicCoefficients_;
  harmonicCoefficients_ = aNext;
  psi_ = streamFunctionOf(omega_);
  time_ += dt;
}

std::vector<Vector3d> VorticityStream::faceVelocity() const {
  std::vector<Vector3d> u = faceGradient(faces_, mesh_, psi_);
  for (std::size_t t = 0; t < u.size(); ++t)
    u[t] = u[t].cross(faces_.normal[t]) + harmonicVelocity(t, harmonicCoefficients_);
  return u;
}

std::vector<Vector3d> VorticityStream::vertexVelocity() const {
  const std::vector<Vector3d> uf = faceVelocity();
  std::vector<Vector3d> u(mesh_.vertices.size(), Vector3d::Zero());
  std::vector<double> weight(mesh_.vertices.size(), 0.0);
  for (std::size_t t = 0; t < uf.size(); ++t)
    for (int v : mesh_.faces[t]) {
      u[v] += faces_.area[t] * uf[t];
      weight[v] += faces_.area[t];
    }
  const std::vector<Vector3d> normals = vertexNormals(mesh_);
  for (std::size_t i = 0; i < u.size(); ++i)
    u[i] = (u[i] - u[i].dot(normals[i]) * normals[i]) / weight[i];
  return u;
}

double VorticityStream::energy() const {
  const double harmonic = harmonic_.empty() ? 0.0 : harmonicCoefficients_.dot(gram_ * harmonicCoefficients_);
  return 0.5 * (psi_.dot(stiffness_ * psi_) + harmonic);
}
double VorticityStream::enstrophy() const { return 0.5 * omega_.dot(mass_.cwiseProduct(omega_)); }
double VorticityStream::circulation() const { return mass_.dot(omega_); }

}  // namespace fluidviz::surface
