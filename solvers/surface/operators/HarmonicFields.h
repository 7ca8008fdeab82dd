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

/// A basis of the 2 g harmonic fields of any closed oriented mesh (none on a sphere): one per
/// edge left over by a tree-cotree decomposition (Eppstein 2003, "Dynamic generators of
/// topologically embedded graphs"; Erickson & Whittlesey 2005): a spanning tree of the vertices,
/// a spanning tree of the faces across the other edges; each remaining edge closes a dual loop
/// around a handle, and the closed 1-form that counts crossings of that loop (+1 per crossing,
/// so its sum around every face is zero) plays the role of grad theta above.
std::vector<std::vector<Eigen::Vector3d>> harmonicBasis(const TriangleMesh& mesh,
                                                        const FaceGeometry& faces);

/// The torus' two angles in turns: around the z axis (u / 2 pi) and around the tube
/// (v / 2 pi), for a torus of major radius R about the z axis (makeTorus).
std::vector<Eigen::VectorXd> torusAngleTurns(const TriangleMesh& mesh, double majorRadius);

}  // namespace fluidviz::surface
