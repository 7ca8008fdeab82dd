#pragma once
// Tait equation of state of weakly compressible SPH:
//   p = B ((rho / rho0)^gamma - 1),   B = rho0 c0^2 / gamma,
// so that c^2 = dp/drho = c0^2 (rho/rho0)^(gamma-1). Choosing c0 >= 10 |v|max keeps density
// variations near 1% (Mach^2).
//
// References:
//   J. J. Monaghan, "Simulating free surface flows with SPH", J. Comput. Phys. 110 (1994)
//   399-406, sec. 3 (the equation of state, after Batchelor 1967).
//   G. K. Batchelor, "An introduction to fluid dynamics", Cambridge 1967, sec. 3.3
//   (Cole's form of the Tait equation for water).
#include <cmath>

namespace fluidviz::sph {

class EquationOfStateTait {
 public:
  /// rho0 (kg/m^3) > 0, c0 (m/s) > 0, gamma >= 1.
  EquationOfStateTait(double rho0, double c0, double gamma)
      : rho0_(rho0), c0_(c0), gamma_(gamma), B_(rho0 * c0 * c0 / gamma) {}
  double pressure(double rho) const { return B_ * (std::pow(rho / rho0_, gamma_) - 1.0); }
  /// Inverse: the density at pressure p (p > -B).
  double density(double p) const { return rho0_ * std::pow(1.0 + p / B_, 1.0 / gamma_); }
  double soundSpeed(double rho) const {
    return c0_ * std::pow(rho / rho0_, 0.5 * (gamma_ - 1.0));
  }
  double stiffness() const { return B_; }  ///< Pa

 private:
  double rho0_, c0_, gamma_, B_;
};

}  // namespace fluidviz::sph
