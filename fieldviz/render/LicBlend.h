#pragma once
// The colour rule of LIC pictures: a LIC texture shifts the brightness of a colour-mapped
// scalar. No VTK here.
//
//   pixel = mask ? mask_color : clamp(map(t) + w * (lic - 1/2)),   t = (s - lo) / (hi - lo)
//
// per channel, with s the colour scalar interpolated (bilinearly) at the pixel centre, lic in
// [0, 1] the texture value and w = lic_weight. A pixel of average texture (lic = 1/2, the mean
// after the contrast stretch) shows exactly the legend's colour, and the streaks have the same
// contrast on dark and bright colours. (Multiplying the colour by the texture, the other common
// rule, hides the streaks where the map is dark: at the slow saddles and eddies that LIC is
// there to show.) w = 0 gives the plain colour map. Pixels where s is NaN or outside the
// scalar's grid start from the NaN grey (0.5, 0.5, 0.5).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/Params.h"
#include "fieldviz/render/ColorMap.h"
#include "fieldviz/render/PictureStyle.h"
#include "fieldviz/render/RgbaImage.h"

namespace fluidviz {

struct LicBlendParams {
  std::string color_by = "speed";  ///< scalar under the texture: speed, vorticity or an array
  double lic_weight = 0.6;         ///< w in [0, 1]: pixel = colour + w * (lic - 1/2)
  std::array<double, 3> mask_color = kMaskedGrey;  ///< RGB in [0, 1] of masked pixels

  template <class V>
  static void describe(V& v) {
    v(&LicBlendParams::color_by,
      {.key = "color_by",
       .description = "scalar coloured under the LIC texture: speed (|v|), vorticity (dv/dx - "
                      "du/dy), or another scalar field (scenes: density, velocity_x, velocity_y)"});
    v(&LicBlendParams::lic_weight,
      {.key = "lic_weight",
       .description = "contrast of the streaks: pixel = clamp(colour + w * (lic - 1/2)) per "
                      "channel, so an average pixel shows the legend's colour; 0 = colour only",
       .min = 0,
       .max = 1,
       .flag = "--weight"});
    v(&LicBlendParams::mask_color,
      {.key = "mask_color",
       .description = "RGB colour of masked pixels (solid bodies, mask_speed)",
       .min = 0,
       .max = 1});
  }
};

/// The colour of one unmasked pixel: mapped + weight * (lic - 1/2) per channel (not clamped).
ColorMap::Color blendLicColor(const ColorMap::Color& mapped, double lic, double weight);

/// 8-bit channel value of a colour component in [0, 1] (rounded, clamped).
std::uint8_t toByte(double c);

/// The blended texture: one pixel per texture node (texture.grid: pixel centres, row 0 = lowest
/// y), returned top row first. `mask` has one entry per pixel (1 = masked) or is empty; `range`
/// is {lo, hi} with lo < hi. Throws std::invalid_argument for sizes that do not match.
RgbaImage blendLicTexture(const ScalarField& texture, const std::vector<std::uint8_t>& mask,
                          const ScalarField& colour, const ColorMap& map,
                          const std::array<double, 2>& range, const LicBlendParams& params);

}  // namespace fluidviz
