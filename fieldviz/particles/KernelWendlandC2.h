#pragma once
// Wendland C2 smoothing kernel, support radius 2h.
//
// References:
//   H. Wendland, "Piecewise polynomial, positive definite and compactly supported radial
//   functions of minimal degree", Adv. Comput. Math. 4 (1995) 389-396 (phi_{3,1}).
//   W. Dehnen, H. Aly, "Improving convergence in smoothed particle hydrodynamics simulations
//   without pairing instability", MNRAS 425 (2012) 1068-1082, Table 1 (normalisations).
//
//   W(r, h) = sigma_d / h^d (1 - q/2)^4 (2 q + 1),  0 <= q < 2,  q = r / h
//   sigma_2 = 7 / (4 pi),  sigma_3 = 21 / (16 pi)
#include <numbers>
#include <stdexcept>

#include "fieldviz/core/Grid.h"

namespace fluidviz::particles {

class KernelWendlandC2 {
 public:
  /// h: smoothing length (m), > 0; dimension: 2 or 3.
  KernelWendlandC2(double h, int dimension) : h_(h), invH_(1.0 / h) {
    if (!(h > 0) || (dimension != 2 && dimension != 3))
      throw std::invalid_argument("KernelWendlandC2: need h > 0 and dimension 2 or 3");
    const double pi = std::numbers::pi;
    const double sigma = dimension == 2 ? 7.0 / (4.0 * pi) : 21.0 / (16.0 * pi);
    norm_ = sigma / (dimension == 2 ? h * h : h * h * h);
  }
  double smoothingLength() const { return h_; }
  double support() const { return 2.0 * h_; }  ///< m, W = 0 for r >= support

  /// Without branches (loops over W vectorise): t = 0 beyond the support.
  double W(double r) const {
    const double q = r * invH_;
    const double t = q < 2.0 ? 1.0 - 0.5 * q : 0.0, t2 = t * t;
    return norm_ * t2 * t2 * (2.0 * q + 1.0);
  }
  /// dW/dr = -5 q sigma / h^(d+1) (1 - q/2)^3.
  double dWdr(double r) const {
    const double q = r * invH_;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * q * norm_ * invH_ * t * t * t;
  }
  /// (dW/dr) / r = -5 sigma / h^(d+2) (1 - q/2)^3, no division.
  double dWdrOverR(double r) const {
    const double q = r * invH_;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * norm_ * invH_ * invH_ * t * t * t;
  }
  /// grad_i W(x_i - x_j) for xij = x_i - x_j, r = |xij|; zero at r = 0.
  Vec3 gradW(const Vec3& xij, double r) const { return Vec3(dWdrOverR(r) * xij); }

 private:
  double h_, invH_, norm_ = 0.0;
};

}  // namespace fluidviz::particles
