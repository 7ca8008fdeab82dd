#pragma once
// Body-force term of Guo, Zheng & Shi 2002 (Phys. Rev. E 65, 046308), "Discrete lattice effects
// on the forcing term in the lattice Boltzmann method". Added to the post-collision populations:
//   f_q* += (1 - omega / 2) S_q,   S_q = w_q [ (c_q - u) / cs2 + (c_q . u) c_q / cs2^2 ] . F
// with F = rho g the force density and u the half-force-shifted velocity (Equilibrium.h,
// nodeMoments). The (1 - omega/2) prefactor belongs to the collision operator (it differs for TRT),
// so it is applied by the caller.
namespace fluidviz::lbm {

/// S_q for a 2D lattice with cs2 = 1/3: w_q [3 (c_q - u) + 9 (c_q . u) c_q] . F.
template <class L>
inline double guoSourceTerm(int q, double ux, double uy, double fx, double fy) {
  const double cx = L::cx[q], cy = L::cy[q];
  const double cu = cx * ux + cy * uy;
  return L::w[q] *
         ((3.0 * (cx - ux) + 9.0 * cu * cx) * fx + (3.0 * (cy - uy) + 9.0 * cu * cy) * fy);
}

}  // namespace fluidviz::lbm
