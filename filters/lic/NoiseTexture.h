#pragma once
// The input texture of LIC: white noise on square cells of `grain` pixels, or an image (the
// second, "enhanced" pass). Lookup is nearest-cell (classic per-pixel noise at grain 1) or
// bilinear between cell centres. Bilinear is the default of LicParams: the texture is then
// continuous along a streamline, so the sampled sum is an accurate quadrature of the line
// integral (nearest makes it depend on where samples fall in the cells: moire, and pixels on the
// same streamline decorrelate by up to 0.06 at step 0.5 px), and FastLIC's sub-pixel offsets
// matter less (mean |fast - reference| 0.016 -> 0.007, see tests/filters/lic).
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "fieldviz/core/Params.h"

namespace fluidviz::lic {

enum class NoiseInterpolation { nearest, bilinear };
constexpr std::array<Choice<NoiseInterpolation>, 2> paramChoices(NoiseInterpolation) {
  return {{{NoiseInterpolation::bilinear, "bilinear"}, {NoiseInterpolation::nearest, "nearest"}}};
}

class NoiseTexture {
 public:
  /// Uniform [0, 1) values on ceil(width / grain) x ceil(height / grain) cells, drawn from
  /// std::mt19937_64(seed) row by row (53 random bits per value, so the same seed gives the same
  /// texture on every platform).
  static NoiseTexture white(int width, int height, double grain, std::uint64_t seed,
                            NoiseInterpolation interpolation = NoiseInterpolation::nearest);
  /// Texture with one cell per pixel holding `values` (row-major, row 0 = lowest y).
  static NoiseTexture fromImage(int width, int height, std::vector<double> values,
                                NoiseInterpolation interpolation = NoiseInterpolation::nearest);

  /// Value at pixel-space point (X, Y) in [0, width] x [0, height].
  double at(double X, double Y) const { return bilinear_ ? bilinearAt(X, Y) : nearestAt(X, Y); }
  double nearestAt(double X, double Y) const {
    const int i = std::min(static_cast<int>(X * invGrain_), nx_ - 1);
    const int j = std::min(static_cast<int>(Y * invGrain_), ny_ - 1);
    return values_[static_cast<std::size_t>(j) * nx_ + i];
  }
  /// Bilinear between cell centres (constant beyond the outermost centres).
  double bilinearAt(double X, double Y) const {
    const double u = std::clamp(X * invGrain_ - 0.5, 0.0, nx_ - 1.0);
    const double w = std::clamp(Y * invGrain_ - 0.5, 0.0, ny_ - 1.0);
    const int i = std::min(static_cast<int>(u), std::max(nx_ - 2, 0));
    const int j = std::min(static_cast<int>(w), std::max(ny_ - 2, 0));
    const double tx = u - i, ty = w - j;
    const int di = nx_ > 1 ? 1 : 0;
    const std::size_t dj = ny_ > 1 ? nx_ : 0;
    const double* a = &values_[static_cast<std::size_t>(j) * nx_ + i];
    return (1 - ty) * ((1 - tx) * a[0] + tx * a[di]) + ty * ((1 - tx) * a[dj] + tx * a[dj + di]);
  }
  int cellsX() const { return nx_; }
  int cellsY() const { return ny_; }
  const std::vector<double>& values() const { return values_; }

 private:
  int nx_ = 1, ny_ = 1;
  double invGrain_ = 1.0;
  bool bilinear_ = false;
  std::vector<double> values_;
};

}  // namespace fluidviz::lic
