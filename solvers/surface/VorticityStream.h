#pragma once
// Incompressible flow on a closed triangle mesh in vorticity - stream-function form:
//
//   d omega / dt = J(psi, omega + f) + nu V omega + n . curl F,   Delta psi = -omega (mean 0),
//   u = grad psi x n (+ a harmonic part on surfaces of genus > 0, see setHarmonicFields),
//   J(a, b) = n . (grad a x grad b),
//
// so that u is tangent to the surface by construction, omega = n . curl u, and u . grad q =
// -J(psi, q). f = 2 Omega (n . z) is the Coriolis parameter of a frame turning at Omega about z.
// F is a steady tangential body force (per unit mass); its weak curl, int phi_i n . curl F =
// sum_T A_T F_T . (grad phi_i x n_T), is the forcing of the vorticity (for F = grad g x n, the
// velocity of a stream function g, it is exactly S g: the discrete curl of a discrete velocity).
// V is the viscous operator on vorticity:
//   deformation: V = Delta + 2 K, the curl of the deformation Laplacian Delta_H u + 2 K u (Ebin &
//     Marsden 1970, Ann. Math. 92:102; Taylor 1992, Comm. PDE 17:1407; Chan, Czubak & Disconzi
//     2017, J. Geom. Phys. 121:335): curl (2 K u) = 2 K omega + 2 n . (grad K x u)
//     = 2 K omega - 2 grad K . grad psi. On the sphere of radius R a vorticity mode of degree l
//     decays at nu (l (l + 1) - 2) / R^2 and rigid rotation (l = 1) does not decay, as a Killing
//     field must not.
//   laplacian: V = Delta, the Hodge Laplacian alone (the usual choice of spectral weather
//     models); a mode of degree l decays at nu l (l + 1) / R^2, and rigid rotation decays too.
//
// Space: P1 finite elements with lumped mass M and cotangent stiffness S (operators/):
// S psi = M omega, and the Galerkin Jacobian b_i = int phi_i J(psi_h, q_h) dA
// = sum over the faces T of i of (A_T / 3) n_T . (grad psi_T x grad q_T). On a regular mesh this
// is Arakawa's Jacobian (Jespersen 1974, J. Comput. Phys. 16:383); on any closed mesh
// sum_i b_i = 0, psi . b = 0 and q . b = 0 exactly (int J(a, b) = 0 for continuous piecewise
// smooth a, b), so circulation, kinetic energy 1/2 psi^T S psi and (potential) enstrophy
// 1/2 q^T M q are conserved by the semi-discrete inviscid equations.
//
// Time: the implicit midpoint rule, which conserves every quadratic invariant of the ODE
// exactly (Cooper 1987, IMA J. Numer. Anal. 7:1) and is Crank-Nicolson for the viscous term:
//   (M + dt nu A / 2) omega^{n+1} = (M - dt nu A / 2) omega^n + dt b(psi^*, omega^* + f),
// omega^* = (omega^n + omega^{n+1}) / 2, A = S (- 2 diag(M K) for deformation), solved
// by fixed-point iteration; both matrices are factorised once (SimplicialLDLT). The deformation
// operator's - 2 grad K . grad psi term (Galerkin: - 2 sum_T (A_T / 3) grad K_T . grad psi_T)
// joins b at the midpoint.
#include <array>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include "solvers/surface/operators/SurfaceOperators.h"

namespace fluidviz::surface {

enum class ViscousOperator { deformation, laplacian };
constexpr std::array<Choice<ViscousOperator>, 2> paramChoices(ViscousOperator) {
  return {{{ViscousOperator::deformation, "deformation"}, {ViscousOperator::laplacian, "laplacian"}}};
}

struct VorticityStreamSettings {
  double viscosity = 0.0;      ///< nu, length^2 / time
  double timeStep = 0.01;
  double rotationRate = 0.0;   ///< Omega of the frame about +z (Coriolis parameter 2 Omega n.z)
  ViscousOperator viscousOperator = ViscousOperator::deformation;
  MassLumping lumping = MassLumping::mixed_voronoi;
  /// Gaussian curvature K per vertex (1 / length^2) of the smooth surface the mesh samples, for
  /// the deformation operator's 2 K term; empty: the mesh's own, angle defect / lumped mass.
  /// The mesh's total curvature is 2 pi chi while its area falls short of the smooth surface's
  /// by O(h^2), which makes rigid rotation decay (or grow) at O(h^2) nu / R^2; the smooth
  /// surface's K (1 / R^2 on the sphere) keeps it steady (SurfaceParams: builtInCurvature).
  Eigen::VectorXd gaussianCurvature;
  /// Steady tangential body force per face (length / time^2); empty: none. Only its tangential
  /// part acts.
  std::vector<Eigen::Vector3d> bodyForce;
  int maxIterations = 60;            ///< fixed-point iterations of one step
  double iterationTolerance = 1e-12;  ///< relative max-norm change that ends them
};

class VorticityStream {
 public:
  VorticityStream(const TriangleMesh& mesh, const VorticityStreamSettings& settings);

  /// Adds harmonic fields (operators/HarmonicFields.h; two on a torus) to the flow:
  /// u = grad psi x n + sum_k a_k h_k. Euler's equations project onto them as
  /// G da/dt = -<q n x u, h_k> (G the fields' Gram matrix, q = omega + f; the Lamb form of the
  /// advection, whose gradient part is orthogonal to them), discretised as
  /// c_k - sum_j W_kj a_j with c_k = sum_T A_T mean(psi) h_k . grad q (= -int q grad psi . h_k
  /// by parts) and W_kj = sum_T A_T mean(q) (n x h_j) . h_k (antisymmetric), and omega is
  /// advected by them too: - sum_T (A_T / 3) h . grad q. Energy 1/2 psi^T S psi + 1/2 a^T G a and
  /// enstrophy stay exact invariants of the inviscid flow. Viscosity: the Hodge Laplacian leaves
  /// harmonic fields alone (laplacian operator: no viscous term on them); the deformation
  /// operator's 2 K u adds G da/dt += 2 nu <K u, h_k> and, to the vorticity, the weak curl of
  /// 2 nu K sum_k a_k h_k (K per face the mean of its vertices').
  void setHarmonicFields(std::vector<std::vector<Eigen::Vector3d>> fields);
  void setHarmonicCoefficients(const Eigen::VectorXd& a);
  /// G^{-1} <field, h_k>: the coefficients of a face field's harmonic part.
  Eigen::VectorXd harmonicPartOf(const std::vector<Eigen::Vector3d>& field) const;
  const Eigen::VectorXd& harmonicCoefficients() const { return harmonicCoefficients_; }

  /// Sets omega (vertex values) minus its mean, and the stream function from it.
  void setVorticity(const Eigen::VectorXd& omega);
  /// One time step; throws std::runtime_error if the fixed-point iteration does not converge
  /// (time step too long for the flow speed).
  void step();

  /// Solves Delta psi = -omega (S psi = M omega) for the psi of zero mean; the mean of omega,
  /// which no tangent field has on a closed surface, is removed first.
  Eigen::VectorXd streamFunctionOf(const Eigen::VectorXd& omega) const;
  /// The Galerkin Jacobian b (see the header comment) of psi and q.
  Eigen::VectorXd galerkinJacobian(const Eigen::VectorXd& psi, const Eigen::VectorXd& q) const;
  /// The weak curl int phi_i n . curl F of a face-constant tangential field F.
  Eigen::VectorXd weakCurl(const std::vector<Eigen::Vector3d>& field) const;
  /// The Galerkin form of - 2 grad K . grad psi, the deformation operator's curvature-gradient
  /// term (zero for the laplacian operator).
  Eigen::VectorXd curvatureGradientTerm(const Eigen::VectorXd& psi) const;

  /// u = grad psi x n on each face: in the face's plane to round-off.
  std::vector<Eigen::Vector3d> faceVelocity() const;
  /// The area-weighted mean of the face velocities around each vertex, projected onto the
  /// tangent plane of the vertex normal.
  std::vector<Eigen::Vector3d> vertexVelocity() const;

  double energy() const;       ///< 1/2 int |u|^2 = 1/2 psi^T S psi + 1/2 a^T G a
  double enstrophy() const;    ///< 1/2 int omega^2 = 1/2 omega^T M omega
  double circulation() const;  ///< int omega (zero on a closed surface)

  const Eigen::VectorXd& vorticity() const { return omega_; }
  const Eigen::VectorXd& streamFunction() const { return psi_; }
  const Eigen::VectorXd& mass() const { return mass_; }
  const TriangleMesh& mesh() const { return mesh_; }
  double time() const { return time_; }
  int lastIterations() const { return lastIterations_; }

 private:
  Eigen::VectorXd removeMean(const Eigen::VectorXd& f) const;
  Eigen::Vector3d harmonicVelocity(std::size_t face, const Eigen::VectorXd& a) const;
  /// - sum_T (A_T / 3) h . grad q: the advection of q by the harmonic part of coefficients a.
  Eigen::VectorXd harmonicAdvection(const Eigen::VectorXd& a, const Eigen::VectorXd& q) const;
  /// da/dt = G^{-1} (c - W a) (+ the deformation operator's term; see setHarmonicFields).
  Eigen::VectorXd harmonicRate(const Eigen::VectorXd& psi, const Eigen::VectorXd& q,
                               const Eigen::VectorXd& a) const;

  TriangleMesh mesh_;
  VorticityStreamSettings settings_;
  FaceGeometry faces_;
  Eigen::VectorXd mass_;
  Eigen::VectorXd coriolis_;
  Eigen::VectorXd forcing_;  ///< weak curl of the body force (zero without one)
  std::vector<Eigen::Vector3d> curvatureGradient_;  ///< grad K per face; empty for laplacian
  Eigen::VectorXd faceCurvature_;  ///< mean K per face (deformation operator)
  SparseMatrix stiffness_;
  SparseMatrix explicitPart_;  ///< M - dt nu A / 2
  Eigen::SimplicialLDLT<SparseMatrix> implicitPart_;  ///< M + dt nu A / 2
  Eigen::SimplicialLDLT<SparseMatrix> poisson_;  ///< S without its last row and column
  Eigen::VectorXd omega_, psi_;
  Eigen::VectorXd lastIncrement_;  ///< omega^n - omega^{n-1}: the iteration's starting guess
  std::vector<std::vector<Eigen::Vector3d>> harmonic_;  ///< h_k per face
  Eigen::MatrixXd gram_;                                ///< <h_j, h_k>
  Eigen::VectorXd harmonicCoefficients_ = Eigen::VectorXd::Zero(0);
  Eigen::VectorXd lastHarmonicIncrement_ = Eigen::VectorXd::Zero(0);
  double time_ = 0.0;
  int lastIterations_ = 0;
};

}  // namespace fluidviz::surface
