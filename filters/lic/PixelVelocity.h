#pragma once
// The vector field as LIC sees it: the xy velocity (of the slice at slice_height for a 3D field) in
// pixel units, with an inline bilinear lookup and an inline midpoint-RK2 streamline stepper.
//
// Why not the shared StreamlineTracer (filters/streamlines)? LIC takes ~L/step steps for every
// one of ~10^6 pixels, so the stepper must be a few inlined multiplies: no std::optional, no
// 3D index arithmetic, no times/speeds recorded, no boundary bisection, no allocation. It
// integrates the NORMALISED direction v/|v| (arc-length parameter, so every sample is `step`
// pixels further along) or v/max|v| ("speed" mode). Lines end at the image border or where
// |v| = 0. tests/filters/lic/PixelVelocity_test.cpp checks it against the shared integrator.
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"

namespace fluidviz::lic {

/// A NaN or infinite vector refused by LIC. what() suggests the remedy with the scene key
/// (mask_speed); a command line words the remedy with its own options through message().
class NonFiniteFieldError : public std::invalid_argument {
 public:
  NonFiniteFieldError(std::string field, std::array<int, 3> node);
  /// The message with `remedy` in the closing parenthesis ("all values must be finite (...)").
  std::string message(const std::string& remedy) const;
  /// The remedy with `maskOption` (mask_speed in scenes, --mask-speed on the command line).
  static std::string maskRemedy(const std::string& maskOption);

 private:
  std::string field_;
  std::array<int, 3> node_;
};

class PixelVelocity {
 public:
  /// `field` covers the image [0, width] x [0, height]; `slice_height` (m) picks the xy slice of a 3D
  /// field (linear in z), ignored in 2D. `speedScaled` selects v/max|v| instead of v/|v|.
  /// Throws NonFiniteFieldError for a NaN/inf value (with its node), std::invalid_argument if the
  /// grid has fewer than 2 nodes along x or y, and ParamError("slice_height") outside the z range.
  PixelVelocity(const VectorField& field, int width, int height, double slice_height,
                bool speedScaled);

  int width() const { return width_; }
  int height() const { return height_; }
  double maxSpeed() const { return maxSpeed_; }  ///< px / s

  /// Bilinear velocity (px / s) at pixel-space point (X, Y); false outside [0, W] x [0, H].
  bool velocity(double X, double Y, double& vx, double& vy) const {
    if (!(X >= 0.0 && X <= width_ && Y >= 0.0 && Y <= height_)) return false;
    const double qx = X * toIndexX_, qy = Y * toIndexY_;
    const int i = std::min(static_cast<int>(qx), nx_ - 2);
    const int j = std::min(static_cast<int>(qy), ny_ - 2);
    const double tx = qx - i, ty = qy - j;
    const double* a = &v_[2 * (static_cast<std::size_t>(j) * nx_ + i)];
    const double* b = a + 2 * nx_;
    vx = (1 - ty) * ((1 - tx) * a[0] + tx * a[2]) + ty * ((1 - tx) * b[0] + tx * b[2]);
    vy = (1 - ty) * ((1 - tx) * a[1] + tx * a[3]) + ty * ((1 - tx) * b[1] + tx * b[3]);
    return true;
  }

  /// |v(X, Y)| / max|v| in [0, 1] (0 outside the image or for a zero field).
  double relativeSpeed(double X, double Y) const {
    double vx, vy;
    if (maxSpeed_ == 0.0 || !velocity(X, Y, vx, vy)) return 0.0;
    return std::hypot(vx, vy) / maxSpeed_;
  }

  /// What the LIC integrates: v/|v| or v/max|v|. False outside the image or where
  /// |v| <= 1e-9 max|v| (the line stops there).
  bool direction(double X, double Y, double& dx, double& dy) const {
    double vx, vy;
    if (!velocity(X, Y, vx, vy)) return false;
    const double s2 = vx * vx + vy * vy;
    if (!(s2 > stopSpeed2_)) return false;
    const double scale = speedScaled_ ? invMaxSpeed_ : 1.0 / std::sqrt(s2);
    dx = vx * scale;
    dy = vy * scale;
    return true;
  }

  /// Up to n explicit-midpoint (RK2) steps of length h along sign * direction from (X, Y),
  /// calling visit(X, Y) at each new point; returns the number of steps taken (< n when the line
  /// left the image or reached |v| = 0).
  template <class Visit>
  int trace(double X, double Y, double sign, double h, int n, Visit&& visit) const {
    const double sh = sign * h;
    for (int k = 0; k < n; ++k) {
      double dx, dy, mx, my;
      if (!direction(X, Y, dx, dy)) return k;
      if (!direction(X + 0.5 * sh * dx, Y + 0.5 * sh * dy, mx, my)) return k;
      X += sh * mx;
      Y += sh * my;
      if (!(X >= 0.0 && X <= width_ && Y >= 0.0 && Y <= height_)) return k;
      visit(X, Y);
    }
    return n;
  }

 private:
  int width_, height_;
  int nx_ = 2, ny_ = 2;
  double toIndexX_ = 1.0, toIndexY_ = 1.0;  // index coordinate per pixel
  std::vector<double> v_;                   // (vx, vy) per node of the slice, px / s
  double maxSpeed_ = 0.0, invMaxSpeed_ = 0.0, stopSpeed2_ = 0.0;
  bool speedScaled_ = false;
};

}  // namespace fluidviz::lic
