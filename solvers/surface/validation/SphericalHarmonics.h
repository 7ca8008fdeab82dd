#pragma once
// Real spherical harmonics, the eigenfunctions of the Laplace-Beltrami operator on the sphere of
// radius R: Delta Y_l^m = -l (l + 1) / R^2 Y_l^m (e.g. Arfken & Weber, "Mathematical Methods for
// Physicists", section 12.6). The analytic references of the surface tests: diffusion decays
// Y_l at kappa l (l + 1) / R^2, and a vorticity field Y_l is steady under the Euler equations.
#include <Eigen/Core>

#include "solvers/surface/mesh/TriangleMesh.h"

namespace fluidviz::surface {

/// Associated Legendre function P_l^m(x), 0 <= m <= l, |x| <= 1, without the Condon-Shortley
/// phase, by the standard upward recurrence in l.
double associatedLegendre(int l, int m, double x);

/// Y_l^m at the direction of p (any length): P_l^|m|(cos theta) cos(m phi) for m >= 0,
/// P_l^|m|(cos theta) sin(|m| phi) for m < 0 (theta from +z, phi about z from +x). Unnormalised.
double realSphericalHarmonic(int l, int m, const Eigen::Vector3d& p);

/// Y_l^m sampled at the vertices of a mesh.
Eigen::VectorXd sampleSphericalHarmonic(const TriangleMesh& mesh, int l, int m);

}  // namespace fluidviz::surface
