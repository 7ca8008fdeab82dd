#pragma once
// Cubic B-spline smoothing kernel, support radius 2h.
//
// References:
//   J. J. Monaghan, "Smoothed particle hydrodynamics", Annu. Rev. Astron. Astrophys. 30 (1992)
//   543-574, sec. 2 (the M4 spline of Schoenberg 1946).
//   J. J. Monaghan, J. C. Lattanzio, "A refined particle method for astrophysical problems",
//   Astron. Astrophys. 149 (1985) 135-143 (normalisations 10/(7 pi) in 2D, 1/pi in 3D).
//
//   W(r, h) = sigma_d / h^d * { 1 - 3/2 q^2 + 3/4 q^3,  0 <= q < 1
//                               1/4 (2 - q)^3,          1 <= q < 2
//                               0,                      q >= 2 },   q = r / h
#include <numbers>
#include <stdexcept>

#include "fieldviz/core/Grid.h"

namespace fluidviz::particles {

class KernelCubicSpline {
 public:
  /// h: smoothing length (m), > 0; dimension: 2 or 3.
  KernelCubicSpline(double h, int dimension) : h_(h), invH_(1.0 / h) {
    if (!(h > 0) || (dimension != 2 && dimension != 3))
      throw std::invalid_argument("KernelCubicSpline: need h > 0 and dimension 2 or 3");
    const double sigma = dimension == 2 ? 10.0 / (7.0 * std::numbers::pi) : 1.0 / std::numbers::pi;
    norm_ = sigma / (dimension == 2 ? h * h : h * h * h);
  }
  double smoothingLength() const { return h_; }
  double support() const { return 2.0 * h_; }  ///< m, W = 0 for r >= support

  /// Both pieces evaluated and one selected (no branches: loops over W vectorise).
  double W(double r) const {
    const double q = r * invH_;
    const double t = q < 2.0 ? 2.0 - q : 0.0;
    const double inner = norm_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    const double outer = norm_ * 0.25 * t * t * t;
    return q < 1.0 ? inner : outer;
  }
  /// dW/dr (1/m^(d+1)).
  double dWdr(double r) const {
    const double q = r * invH_;
    if (q < 1.0) return norm_ * invH_ * (-3.0 * q + 2.25 * q * q);
    if (q < 2.0) return -norm_ * invH_ * 0.75 * (2.0 - q) * (2.0 - q);
    return 0.0;
  }
  /// (dW/dr) / r, finite at r = 0 (the inner piece has no division).
  double dWdrOverR(double r) const {
    const double q = r * invH_;
    if (q < 1.0) return norm_ * invH_ * invH_ * (-3.0 + 2.25 * q);
    if (q < 2.0) return -norm_ * invH_ * 0.75 * (2.0 - q) * (2.0 - q) / r;
    return 0.0;
  }
  /// grad_i W(x_i - x_j) for xij = x_i - x_j, r = |xij|; zero at r = 0.
  Vec3 gradW(const Vec3& xij, double r) const {
    return r > 0.0 ? Vec3(dWdrOverR(r) * xij) : Vec3::Zero();
  }

 private:
  double h_, invH_, norm_ = 0.0;
};

}  // namespace fluidviz::particles
