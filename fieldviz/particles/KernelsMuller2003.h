#pragma once
// The three kernels of Mueller, Charypar & Gross (2003): poly6 (density, colour field), spiky
// (pressure: its gradient does not vanish at r = 0, so particles do not clump) and viscosity
// (its Laplacian is positive everywhere, so the viscous force only damps).
//
// References:
//   M. Mueller, D. Charypar, M. Gross, "Particle-based fluid simulation for interactive
//   applications", Proc. SCA 2003, 154-159: eqs. (20) poly6, (21) spiky, (22) viscosity, with
//   their 3D normalisations.
//   2D normalisations: integrals of the same profiles over the disc (checked by the kernel tests).
//
// Convention of this project: every kernel has compact support radius H = 2h, h being the
// smoothing length (so h / dx means the same for all kernels). The paper writes H as "h".
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fieldviz/core/Grid.h"

namespace fluidviz::particles {

namespace detail {
inline void checkKernelArgs(double h, int dimension, const char* name) {
  if (!(h > 0) || (dimension != 2 && dimension != 3))
    throw std::invalid_argument(std::string(name) + ": need h > 0 and dimension 2 or 3");
}
}  // namespace detail

/// W = sigma (H^2 - r^2)^3; sigma_3 = 315 / (64 pi H^9) (eq. 20), sigma_2 = 4 / (pi H^8).
class KernelPoly6 {
 public:
  KernelPoly6(double h, int dimension) : H_(2.0 * h), H2_(H_ * H_), dim_(dimension) {
    detail::checkKernelArgs(h, dimension, "KernelPoly6");
    const double pi = std::numbers::pi;
    sigma_ = dimension == 3 ? 315.0 / (64.0 * pi * std::pow(H_, 9)) : 4.0 / (pi * std::pow(H_, 8));
  }
  double support() const { return H_; }
  double W(double r) const {
    const double s = H2_ - r * r;
    return r < H_ ? sigma_ * s * s * s : 0.0;
  }
  double dWdr(double r) const {
    const double s = H2_ - r * r;
    return r < H_ ? -6.0 * sigma_ * r * s * s : 0.0;
  }
  Vec3 gradW(const Vec3& xij, double r) const {  // = -6 sigma (H^2 - r^2)^2 x_ij
    const double s = H2_ - r * r;
    return r < H_ ? Vec3(-6.0 * sigma_ * s * s * xij) : Vec3::Zero();
  }
  /// Laplacian: -6 sigma (H^2 - r^2) (d (H^2 - r^2) - 4 r^2); 3D: the paper's
  /// -945 / (32 pi H^9) (H^2 - r^2) (3 H^2 - 7 r^2).
  double laplacianW(double r) const {
    const double s = H2_ - r * r;
    return r < H_ ? -6.0 * sigma_ * s * (dim_ * s - 4.0 * r * r) : 0.0;
  }

 private:
  double H_, H2_, sigma_ = 0.0;
  int dim_;
};

/// W = sigma (H - r)^3; sigma_3 = 15 / (pi H^6) (eq. 21), sigma_2 = 10 / (pi H^5).
class KernelSpiky {
 public:
  KernelSpiky(double h, int dimension) : H_(2.0 * h) {
    detail::checkKernelArgs(h, dimension, "KernelSpiky");
    const double pi = std::numbers::pi;
    sigma_ = dimension == 3 ? 15.0 / (pi * std::pow(H_, 6)) : 10.0 / (pi * std::pow(H_, 5));
  }
  double support() const { return H_; }
  double W(double r) const { return r < H_ ? sigma_ * (H_ - r) * (H_ - r) * (H_ - r) : 0.0; }
  double dWdr(double r) const { return r < H_ ? -3.0 * sigma_ * (H_ - r) * (H_ - r) : 0.0; }
  /// -3 sigma (H - r)^2 x_ij / r; zero at r = 0 (the limit depends on the direction).
  Vec3 gradW(const Vec3& xij, double r) const {
    return r > 0.0 ? Vec3(dWdr(r) / r * xij) : Vec3::Zero();
  }

 private:
  double H_, sigma_ = 0.0;
};

/// W = sigma (-r^3 / (2 H^3) + r^2 / H^2 + H / (2 r) - 1) (eq. 22); sigma_3 = 15 / (2 pi H^3),
/// sigma_2 = 10 / (3 pi H^2). Only its Laplacian is used (viscosity force, eq. 14):
///   3D: 45 / (pi H^6) (H - r) (the paper's, the exact Laplacian of W);
///   2D: 40 / (pi H^5) (H - r). In 2D the Laplacian of the profile is not linear in r; the same
///   linear form is normalised like the 3D one, by its second moment
///   int r^2 lap W dV = 2 d, which makes sum_j V_j (v_j - v_i) lap W_ij consistent with the
///   Laplacian of v (the 3D formula satisfies it too).
class KernelViscosity {
 public:
  KernelViscosity(double h, int dimension) : H_(2.0 * h) {
    detail::checkKernelArgs(h, dimension, "KernelViscosity");
    const double pi = std::numbers::pi;
    sigma_ = dimension == 3 ? 15.0 / (2.0 * pi * H_ * H_ * H_) : 10.0 / (3.0 * pi * H_ * H_);
    lap_ = dimension == 3 ? 45.0 / (pi * std::pow(H_, 6)) : 40.0 / (pi * std::pow(H_, 5));
  }
  double support() const { return H_; }
  double W(double r) const {
    if (!(r < H_)) return 0.0;
    return sigma_ * (-r * r * r / (2.0 * H_ * H_ * H_) + r * r / (H_ * H_) + H_ / (2.0 * r) - 1.0);
  }
  double dWdr(double r) const {
    if (!(r < H_)) return 0.0;
    return sigma_ * (-1.5 * r * r / (H_ * H_ * H_) + 2.0 * r / (H_ * H_) - H_ / (2.0 * r * r));
  }
  Vec3 gradW(const Vec3& xij, double r) const {
    return r > 0.0 ? Vec3(dWdr(r) / r * xij) : Vec3::Zero();
  }
  double laplacianW(double r) const { return r < H_ ? lap_ * (H_ - r) : 0.0; }

 private:
  double H_, sigma_ = 0.0, lap_ = 0.0;
};

}  // namespace fluidviz::particles
