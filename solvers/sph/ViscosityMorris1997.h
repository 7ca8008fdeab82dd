#pragma once
// Laminar viscosity of Morris, Fox & Zhu (1997): a first-derivative approximation of
// (1/rho) div(mu grad v) that conserves linear momentum:
//   a_i = sum_j m_j (mu_i + mu_j) / (rho_i rho_j) (x_ij . grad_i W_ij) / (r_ij^2 + eta^2) v_ij,
// with mu = rho0 nu here (mu_i + mu_j = 2 mu), eta^2 = 0.01 h^2.
//
// At walls the boundary particle j gets the fictitious velocity of Morris et al. (sec. 3.3),
// which makes the velocity vanish (relative to the wall) on the wall surface:
//   v_i - v_j = beta (v_i - v_wall),  beta = 1 + d_j / max(d_i, d_min),
// d_i, d_j the distances of i (fluid) and j (boundary) from the surface. Morris et al. and
// Adami et al. (2012) bound beta by 1.5 instead; with wall particles up to 2.5 dx deep that
// under-resolves the wall shear (a slip of 4% of the centre-line speed in start-up Poiseuille
// flow at L/dx = 20), so here only d_i is bounded, by d_min = dx/2 (the first fluid layer).
//
// References:
//   J. P. Morris, P. J. Fox, Y. Zhu, "Modeling low Reynolds number incompressible flows using
//   SPH", J. Comput. Phys. 136 (1997) 214-226, sec. 3.2 (viscous term), sec. 3.3 (boundaries).
//   S. Adami, X. Y. Hu, N. A. Adams, "A generalized wall boundary condition for smoothed
//   particle hydrodynamics", J. Comput. Phys. 231 (2012) 7057-7075.
#include <algorithm>

#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct ViscosityMorris1997 {
  /// Acceleration of i from j; twoMu = 2 mu (Pa s); eta2 = 0.01 h^2.
  static Vec3 acceleration(double mj, double twoMu, double rhoi, double rhoj, const Vec3& xij,
                           double r2, const Vec3& gradW, const Vec3& vij, double eta2) {
    return (mj * twoMu / (rhoi * rhoj) * xij.dot(gradW) / (r2 + eta2)) * vij;
  }
  /// Velocity difference v_i - v_j to use against boundary particle j (Morris sec. 3.3).
  static Vec3 wallVelocityDifference(const Vec3& vi, const Vec3& vWall, double di, double dj,
                                     double dMin) {
    return (1.0 + dj / std::max(di, dMin)) * (vi - vWall);
  }
};

}  // namespace fluidviz::sph
