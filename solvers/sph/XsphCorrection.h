#pragma once
// XSPH: particles move with a velocity smoothed over their neighbours, which keeps them
// ordered and prevents interpenetration without dissipating momentum:
//   dx_i/dt = v_i + epsilon sum_j (m_j / rhobar_ij) (v_j - v_i) W_ij.
//
// References:
//   J. J. Monaghan, "On the problem of penetration in particle methods", J. Comput. Phys. 82
//   (1989) 1-15. Monaghan 1992, sec. 2.5.
#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

struct XsphCorrection {
  /// Velocity correction of i from j (without epsilon); vji = v_j - v_i.
  static Vec3 term(double mj, double rhobar, const Vec3& vji, double W) {
    return (mj / rhobar * W) * vji;
  }
};

}  // namespace fluidviz::sph
