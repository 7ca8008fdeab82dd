#pragma once
// Monaghan's artificial viscosity (acts only between approaching particles):
//   Pi_ij = (-alpha cbar_ij mu_ij + beta mu_ij^2) / rhobar_ij   if v_ij . x_ij < 0, else 0,
//   mu_ij = h v_ij . x_ij / (r_ij^2 + eta^2),  eta^2 = 0.01 h^2,
//   a_i = - sum_j m_j Pi_ij grad_i W_ij.
// alpha gives a shear and bulk viscosity nu ~ alpha h c / (2 (d + 2)) (Monaghan 2005, sec. 4.5).
//
// References:
//   J. J. Monaghan, "Smoothed particle hydrodynamics", Annu. Rev. Astron. Astrophys. 30 (1992)
//   543-574, sec. 4 (artificial viscosity); J. J. Monaghan, R. A. Gingold, J. Comput. Phys. 52 (1983)
//   374-389. J. J. Monaghan, Rep. Prog. Phys. 68 (2005) 1703-1759.
#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct ArtificialViscosityMonaghan1992 {
  double alpha = 0.0, beta = 0.0;  ///< dimensionless
  double h = 0.0;                  ///< m, smoothing length
  double eta2 = 0.0;               ///< m^2, 0.01 h^2

  /// Acceleration of i from j.
  Vec3 acceleration(double mj, const Vec3& xij, double r2, const Vec3& vij, double cbar,
                    double rhobar, const Vec3& gradW) const {
    const double vx = vij.dot(xij);
    if (vx >= 0.0) return Vec3::Zero();
    const double mu = h * vx / (r2 + eta2);
    const double pi = (-alpha * cbar * mu + beta * mu * mu) / rhobar;
    return -mj * pi * gradW;
  }
};

}  // namespace fluidviz::sph
