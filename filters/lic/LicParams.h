#pragma once
// Parameters of Line Integral Convolution (LicParams drives scene keys, CLI flags and docs).
//
// Pixel space: the output image covers the grid's xy bounding box; pixel (i, j) spans
// [i, i+1) x [j, j+1) in pixel coordinates and row j = 0 is the LOWEST y (the orientation of
// vtkImageData; image writers flip). Lengths below are in output pixels.
#include <optional>
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz::lic {

struct LicParams {
  double length = 20.0;         ///< px, half-length L: the kernel runs L px down- and upstream, [1, 1000]
  std::string kernel = "box";   ///< box (constant weight) or hann (0.5 + 0.5 cos, smooth ends)
  std::string method = "fast";  ///< reference (Cabral & Leedom 1993) or fast (Stalling & Hege 1995)
  int width = 0;                ///< px, [0, 16384]; 0 = from height and the grid's aspect ratio
  int height = 0;               ///< px, [0, 16384]; 0 = from width (both 0: one pixel per node in x)
  int noise_seed = 1;           ///< seed of the white noise (std::mt19937_64), [0, 2147483647]
  double noise_grain = 1.0;     ///< px, side of the square noise cells, [1, 100]
  std::string noise_interpolation = "bilinear";  ///< bilinear (smooth, accurate) or nearest
  double step = 0.5;            ///< px, arc length between samples along a streamline, [0.05, 10]
  std::string vectors = "normalized";  ///< normalized: every pixel gets the full kernel length;
                                       ///< speed: the length scales with |v| / max|v|
  bool contrast = true;         ///< stretch: mean -> 0.5, mean +- contrast_sigmas std -> 0, 1
  double contrast_sigmas = 2.5; ///< std devs mapped onto half the grey range, (0, 10]
  bool enhance = false;         ///< second LIC pass over the first (Okada & Kao 1997)
  double mask_speed = 0.0;      ///< mask pixels with |v| <= mask_speed * max|v|, [0, 1); 0 = off
  std::optional<double> slice_z;  ///< m, 3D fields: z of the xy slice; unset = mid-height
  int fast_min_hits = 2;        ///< fast: seed a line from a pixel with fewer hits, [1, 100]
  double fast_line_factor = 5.0;  ///< fast: line traced per seed and direction, in L, [1, 100]

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
                                          "smoother streaks",
                           .choices = {"box", "hann"}});
    v(&LicParams::method, {.key = "method",
                           .description = "reference: one streamline per pixel (Cabral & Leedom "
                                          "1993); fast: long streamlines reused by every pixel "
                                          "they cross (Stalling & Hege 1995)",
                           .choices = {"reference", "fast"}});
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
                               .max = 2147483647});
    v(&LicParams::noise_grain, {.key = "noise_grain",
                                .unit = "px",
                                .description = "side of the square noise cells; larger = "
                                               "coarser, wider streaks",
                                .min = 1,
                                .max = 100});
    v(&LicParams::noise_interpolation,
      {.key = "noise_interpolation",
       .description = "bilinear: noise interpolated between cell centres (accurate line "
                      "integrals, no moire); nearest: piecewise-constant cells (crisper, aliases)",
       .choices = {"bilinear", "nearest"}});
    v(&LicParams::step, {.key = "step",
                         .unit = "px",
                         .description = "distance between samples along a streamline (RK2 "
                                        "step); cost ~ 1 / step",
                         .min = 0.05,
                         .max = 10});
    v(&LicParams::vectors, {.key = "vectors",
                            .description = "normalized: full kernel length everywhere; speed: "
                                           "kernel length ~ |v| / max|v| (slow flow looks grainy)",
                            .choices = {"normalized", "speed"}});
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
                               .max = 1});
    v(&LicParams::slice_z, {.key = "slice_z",
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

/// Throws ParamError naming the key for values outside their ranges (mask_speed must be < 1).
void validateLicParams(const LicParams& p);

}  // namespace fluidviz::lic
