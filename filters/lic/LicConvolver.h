#pragma once
// One LIC pass: every pixel gets the kernel-weighted mean of the input texture along the
// streamline through it. Two implementations behind this interface:
//   ReferenceLic  Cabral & Leedom 1993, "Imaging vector fields using line integral
//                 convolution", SIGGRAPH '93: one streamline of n steps each way per pixel.
//   FastLic       Stalling & Hege 1995, "Fast and resolution independent line integral
//                 convolution", SIGGRAPH '95: long streamlines whose sliding kernel sums are
//                 computed incrementally and deposited into every pixel they cross.
#include <vector>

#include "filters/lic/NoiseTexture.h"
#include "filters/lic/PixelVelocity.h"

namespace fluidviz::lic {

/// Weights at sample k = -n..n (sample spacing `step` px, n = round(L / step)).
struct LicKernel {
  int n = 1;          ///< samples on each side of the centre, >= 1
  double step = 0.5;  ///< px between samples
  bool hann = false;  ///< false: box (all 1); true: 0.5 + 0.5 cos(pi k / (n + 1)), > 0 for |k| <= n
  double weight(int k) const;
};

class LicConvolver {
 public:
  virtual ~LicConvolver() = default;
  /// One value per pixel, row-major, row 0 = lowest y. Where the streamline is cut short (image
  /// border, |v| = 0) the kernel is truncated and renormalised by its remaining weight, so a
  /// pixel on a zero field keeps exactly its texture value.
  virtual std::vector<double> convolve(const PixelVelocity& velocity, const NoiseTexture& texture,
                                       const LicKernel& kernel) const = 0;
};

class ReferenceLic final : public LicConvolver {
 public:
  std::vector<double> convolve(const PixelVelocity& velocity, const NoiseTexture& texture,
                               const LicKernel& kernel) const override;
};

/// FastLIC. Pixels are visited in a fixed scattered order; a pixel with fewer than `minHits`
/// deposits seeds a streamline of lineFactor * n steps each way (fewer where it ends); every
/// sample m of it whose kernel window lies on the line gets the window's weighted mean I_m, added
/// to the pixel that contains the sample. A pixel's value is the mean of its deposits. Samples
/// sit anywhere inside their pixel, not at its centre: that offset is FastLIC's approximation
/// (tests/filters/lic quantify it).
///
/// Box kernel: I_m from prefix sums of the texture values (the incremental sum of Stalling &
/// Hege). Hann kernel: also O(1) per sample, because 0.5 + 0.5 cos(w d) = 0.5 + 0.5 Re e^{iwd}:
/// the windowed sum is 0.5 (box sum) + 0.5 Re(e^{-iwm} sum_j T_j e^{iwj}), from complex prefix
/// sums (the idea of Hege & Stalling 1998, "Fast LIC with piecewise polynomial filter kernels",
/// applied to a trigonometric kernel).
///
/// Parallel and deterministic: rounds of 256 seeds (the next unsatisfied pixels of the order) are
/// traced and convolved in parallel, then committed one by one in visiting order; a line whose
/// seed an earlier line of the round has already satisfied is dropped. The result is exactly the
/// serial algorithm's, for any number of threads.
class FastLic final : public LicConvolver {
 public:
  FastLic(int minHits, double lineFactor) : minHits_(minHits), lineFactor_(lineFactor) {}
  std::vector<double> convolve(const PixelVelocity& velocity, const NoiseTexture& texture,
                               const LicKernel& kernel) const override;

 private:
  int minHits_;
  double lineFactor_;
};

}  // namespace fluidviz::lic
