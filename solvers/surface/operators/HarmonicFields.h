#pragma once
// Harmonic tangent fields of a closed surface of genus g (2 g of them: two on a torus): fields
// that are both divergence- and curl-free, the part of a flow no stream function carries (the
// Hodge decomposition). Discretely (face-constant fields): h = (grad theta - grad p) x n with
// theta a multivalued P1 "angle" (one turn around a handle; values given modulo 1 and unwrapped
// per face, so grad theta is single-valued and its tangential part along every edge continuous)
// and p the P1 function minimising |grad theta - grad p|, S p = <grad theta, grad phi_i>. Then
// h has a continuous normal flux across every edge and no divergence in any face (a
// divergence-free Raviart-Thomas field) and is L2-orthogonal to every grad psi x n, i.e. weakly
// curl-free (Polthier & Preuss 2003, "Identifying vector field singularities using a discrete
// Hodge decomposition").
#include <vector>

#include "solvers/surface/operators/SurfaceOperators.h"

namespace fluidviz::surface {

/// The harmonic field of the multivalued angle `turns` (vertex values modulo 1).
std::vector<Eigen::Vector3d> harmonicField(const TriangleMesh& mesh, const FaceGeometry& faces,
                                           const Eigen::VectorXd& turns);

/// The torus' two angles in turns: around the z axis (u / 2 pi) and around the tube
/// (v / 2 pi), for a torus of major radius R about the z axis (makeTorus).
std::vector<Eigen::VectorXd> torusAngleTurns(const TriangleMesh& mesh, double majorRadius);

}  // namespace fluidviz::surface
