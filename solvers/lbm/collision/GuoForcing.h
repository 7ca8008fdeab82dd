#pragma once
// Body-force term of Guo, Zheng & Shi 2002 (Phys. Rev. E 65, 046308), "Discrete lattice effects
// on the forcing term in the lattice Boltzmann method". Added to the post-collision populations:
//   f_q* += (1 - omega / 2) S_q,   S_q = w_q [ (c_q - u) / cs2 + (c_q . u) c_q / cs2^2 ] . F
// with F = rho g the force density and u the half-force-shifted velocity (Equilibrium.h,
// nodeMoments). The prefactor belongs to the collision operator: BGK applies (1 - omega/2) to all
// of S_q; TRT (CollisionTRT.h) applies (1 - omega+/2) to the part of S_q even in c_q and
// (1 - omega-/2) to the odd part: Guo's (I - S/2) correction with the relaxation rate of each
// part (the same Chapman-Enskog argument, with the rate of the moment the term feeds).
namespace fluidviz::lbm {

/// S_q for a lattice with cs2 = 1/3: w_q [3 (c_q - u) + 9 (c_q . u) c_q] . F.
template <class L>
inline double guoSourceTerm(int q, double ux, double uy, double uz, double fx, double fy,
                            double fz) {
  const double cx = L::cx[q], cy = L::cy[q], cz = L::cz[q];
  const double cu = cx * ux + cy * uy + cz * uz;
  return L::w[q] * ((3.0 * (cx - ux) + 9.0 * cu * cx) * fx + (3.0 * (cy - uy) + 9.0 * cu * cy) * fy +
                    (3.0 * (cz - uz) + 9.0 * cu * cz) * fz);
}

}  // namespace fluidviz::lbm
