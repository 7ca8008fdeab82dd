#pragma once
// Parameters of Line Integral Convolution (LicParams drives scene keys, CLI flags and docs).
//
// Pixel space: the output image covers the grid's xy bounding box; pixel (i, j) spans
// [i, i+1) x [j, j+1) in pixel coordinates and row j = 0 is the LOWEST y (the orientation of
// vtkImageData; image writers flip). Lengths below are in output pixels.
#include <array>
#include <optional>
#include <string>

#include "fieldviz/core/Params.h"
#include "filters/lic/NoiseTexture.h"

namespace fluidviz::lic {

/// Weights along the streamline: equal (box) or 0.5 + 0.5 cos(pi s / L) (hann).
enum class KernelShape { box, hann };
constexpr std::array<Choice<KernelShape>, 2> paramChoices(KernelShape) {
  return {{{KernelShape::box, "box"}, {KernelShape::hann, "hann"}}};
}

/// One streamline per pixel (Cabral & Leedom 1993) or long reused lines (Stalling & Hege 1995).
enum class LicMethod { reference, fast };
constexpr std::array<Choice<LicMethod>, 2> paramChoices(LicMethod) {
  return {{{LicMethod::reference, "reference"}, {LicMethod::fast, "fast"}}};
}

/// Kernel length everywhere the same (normalized) or proportional to the local speed.
enum class LicVectors { normalized, speed };
constexpr std::array<Choice<LicVectors>, 2> paramChoices(LicVectors) {
  return {{{LicVectors::normalized, "normalized"}, {LicVectors::speed, "speed"}}};
}

struct LicParams {
  // Units, ranges and meanings of the members: their describe() declarations below.
  double length = 20.0;  ///< half-length L
  KernelShape kernel = KernelShape::box;
  LicMethod method = LicMethod::fast;
  int width = 0;
  int height = 0;
  int noise_seed = 1;  ///< seed of std::mt19937_64
  double noise_grain = 1.0;
  NoiseInterpolation noise_interpolation = NoiseInterpolation::bilinear;
  double step = 0.5;
  LicVectors vectors = LicVectors::normalized;
  bool contrast = true;
  double contrast_sigmas = 2.5;
  bool enhance = false;
  double mask_speed = 0.0;
  std::optional<double> slice_height;  ///< z of the xy slice of a 3D field; unset = mid-height
  int fast_min_hits = 2;
  double fast_line_factor = 5.0;

  /// slice_z meant a height here and a layer index in output.images; it is now two keys.
  static constexpr std::array retiredKeys{RetiredKey{
      "slice_z", "was split: give slice_height (m, the z of the xy slice of a 3D field) here; "
                 "slice_index (a node layer) is the key of output.images"}};

  template <class V>
  static void describe(V& v) {
    v(&LicParams::length, {.key = "length",
                           .unit = "px",
                           .description = "half-length L of the convolution: the streamline "
                                          "runs L pixels down- and upstream; cost ~ L "
                                          "(reference), ~ independent of L (fast)",
                           .min = 1,
                           .max = 1000});
    v(&LicParams::kernel, {.key = "kernel",
                           .description = "box: equal weights; hann: 0.5 + 0.5 cos(pi s / L), "
                                          "smoother streaks"});
    v(&LicParams::method, {.key = "method",
                           .description = "reference: one streamline per pixel (Cabral & Leedom "
                                          "1993); fast: long streamlines reused by every pixel "
                                          "they cross (Stalling & Hege 1995)"});
    v(&LicParams::width, {.key = "width",
                          .unit = "px",
                          .description = "image width; 0 = from height and the grid aspect",
                          .min = 0,
                          .max = 16384});
    v(&LicParams::height, {.key = "height",
                           .unit = "px",
                           .description = "image height; 0 = from width and the grid aspect "
                                          "(both 0: one pixel per grid node along x)",
                           .min = 0,
                           .max = 16384});
    v(&LicParams::noise_seed, {.key = "noise_seed",
                               .description = "seed of the white noise; same seed, same image",
                               .min = 0,
                               .max = 2147483647,
                               .flag = "--seed"});
    v(&LicParams::noise_grain, {.key = "noise_grain",
                                .unit = "px",
                                .description = "side of the square noise cells; larger = "
                                               "coarser, wider streaks",
                                .min = 1,
                                .max = 100,
                                .flag = "--grain"});
    v(&LicParams::noise_interpolation,
      {.key = "noise_interpolation",
       .description = "bilinear: noise interpolated between cell centres (accurate line "
                      "integrals, no moire); nearest: piecewise-constant cells (crisper, aliases)"});
    v(&LicParams::step, {.key = "step",
                         .unit = "px",
                         .description = "distance between samples along a streamline (RK2 "
                                        "step); cost ~ 1 / step",
                         .min = 0.05,
                         .max = 10});
    v(&LicParams::vectors, {.key = "vectors",
                            .description = "normalized: full kernel length everywhere; speed: "
                                           "kernel length ~ |v| / max|v| (slow flow looks grainy)"});
    v(&LicParams::contrast, {.key = "contrast",
                             .description = "histogram stretch: mean -> 0.5, mean +- "
                                            "contrast_sigmas std -> 0 and 1 (clamped)"});
    v(&LicParams::contrast_sigmas, {.key = "contrast_sigmas",
                                    .description = "standard deviations mapped onto half the "
                                                   "grey range by the stretch",
                                    .min = 0,
                                    .max = 10,
                                    .minExclusive = true});
    v(&LicParams::enhance, {.key = "enhance",
                            .description = "second pass that convolves the (stretched) first "
                                           "pass instead of noise: longer, crisper streaks "
                                           "(Okada & Kao 1997); doubles the cost"});
    v(&LicParams::mask_speed, {.key = "mask_speed",
                               .description = "pixels with |v| <= mask_speed * max|v| are masked "
                                              "(value 0, mask 1); 0 = no mask",
                               .min = 0,
                               .max = 1,
                               .maxExclusive = true});
    v(&LicParams::slice_height, {.key = "slice_height",
                            .unit = "m",
                            .description = "3D fields: height of the xy slice (inside the grid); "
                                           "unset = mid-height; ignored for 2D fields"});
    v(&LicParams::fast_min_hits,
      {.key = "fast_min_hits",
       .description = "fast: a pixel reached by the scan with fewer deposits than this seeds a "
                      "new long streamline; more = smoother, slower",
       .min = 1,
       .max = 100});
    v(&LicParams::fast_line_factor,
      {.key = "fast_line_factor",
       .description = "fast: length of each long streamline per direction, in units of L",
       .min = 1,
       .max = 100});
  }
};

/// Throws ParamError naming the key for values outside their declared ranges.
void validateLicParams(const LicParams& p);

}  // namespace fluidviz::lic
