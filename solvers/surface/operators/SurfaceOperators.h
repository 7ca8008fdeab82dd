#pragma once
// Discrete differential operators on a triangle mesh with piecewise-linear (P1) vertex functions:
// the cotangent Laplace-Beltrami operator (Pinkall & Polthier 1993; Meyer, Desbrun, Schroeder &
// Barr 2003, "Discrete differential-geometry operators for triangulated 2-manifolds"), lumped
// masses, Gaussian curvature by angle defect, per-face gradients and vertex normals.
//
// Convention: the Laplace-Beltrami operator of a vertex function f is Delta f ~ -M^{-1} S f, with
// S the symmetric positive semi-definite cotangent stiffness matrix (the P1 finite-element
// stiffness, S_ij = -(cot alpha_ij + cot beta_ij) / 2 for the two angles opposite edge ij,
// S_ii = -sum_j S_ij, so S 1 = 0) and M the diagonal lumped mass matrix.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fieldviz/core/Params.h"
#include "solvers/surface/mesh/TriangleMesh.h"

namespace fluidviz::surface {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Lumped mass of a vertex: a third of the area of its faces (barycentric), or the mixed Voronoi
/// area of Meyer et al. 2003 (section 3.3, Fig. 4: the Voronoi cell inside non-obtuse faces,
/// half / a quarter of an obtuse face's area at its obtuse / other corners). Both sum to the
/// mesh's area.
enum class MassLumping { barycentric, mixed_voronoi };
constexpr std::array<Choice<MassLumping>, 2> paramChoices(MassLumping) {
  return {{{MassLumping::barycentric, "barycentric"}, {MassLumping::mixed_voronoi, "mixed_voronoi"}}};
}

/// What the operators need of each face, computed once: area, unit normal (from the
/// counter-clockwise order) and the constant gradients of the three hat functions,
/// grad phi_k = n x e_k / (2 A) with e_k the edge opposite corner k run counter-clockwise.
struct FaceGeometry {
  std::vector<double> area;
  std::vector<Eigen::Vector3d> normal;
  std::vector<std::array<Eigen::Vector3d, 3>> hatGradient;
};

FaceGeometry computeFaceGeometry(const TriangleMesh& mesh);

/// The cotangent stiffness matrix S (see the header comment).
SparseMatrix cotanStiffness(const TriangleMesh& mesh);

/// Diagonal of the lumped mass matrix.
Eigen::VectorXd lumpedMass(const TriangleMesh& mesh, MassLumping lumping);

/// Integrated Gaussian curvature per vertex, 2 pi - (sum of its corner angles) (closed meshes;
/// Meyer et al. 2003, section 5). Its sum is 2 pi chi exactly: the discrete Gauss-Bonnet theorem.
Eigen::VectorXd angleDefect(const TriangleMesh& mesh);

/// The constant gradient, on each face, of the P1 interpolant of the vertex values f (a vector in
/// the face's plane).
std::vector<Eigen::Vector3d> faceGradient(const FaceGeometry& geometry, const TriangleMesh& mesh,
                                          const Eigen::VectorXd& f);

/// Unit vertex normals: the corner normals weighted by Max's weights sin(angle) / (|e1| |e2|)
/// (Max 1999, J. Graphics Tools 4(2):1), exact for a mesh inscribed in a sphere.
std::vector<Eigen::Vector3d> vertexNormals(const TriangleMesh& mesh);

/// The diagonal sparse matrix of d (a lumped mass matrix).
SparseMatrix diagonalMatrix(const Eigen::VectorXd& d);

/// Sum of M_i f_i: the integral of f with the lumped mass.
double integrate(const Eigen::VectorXd& mass, const Eigen::VectorXd& f);

}  // namespace fluidviz::surface
