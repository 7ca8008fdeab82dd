#pragma once
// Colour-field surface tension of Mueller, Charypar & Gross (2003), model A:
//   c_S(x) = sum_j m_j / rho_j W_poly6(x - x_j)                   (eq. 15)
//   n = grad c_S,  kappa = - lap c_S / |n|                         (eqs. 16, 17)
//   f_i = - sigma lap c_S n / |n|   where |n| > threshold          (eq. 19, force density)
// The colour field includes the particle itself (its Laplacian at r = 0 is not zero).
//
// References:
//   M. Mueller, D. Charypar, M. Gross, Proc. SCA 2003, 154-159, sec. 4.4.
#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct SurfaceTensionMuller2003 {
  double sigma = 0.0;      ///< N/m (3D), N (2D)
  double threshold = 0.0;  ///< 1/m, minimum |n| (where the surface is)

  /// Force density from the accumulated colour gradient n and Laplacian lap c_S.
  Vec3 force(const Vec3& n, double lapColour) const {
    const double norm = n.norm();
    return norm > threshold ? Vec3((-sigma * lapColour / norm) * n) : Vec3::Zero();
  }
};

}  // namespace fluidviz::sph
