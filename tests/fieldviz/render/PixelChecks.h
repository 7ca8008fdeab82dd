#pragma once
// Pixel comparisons shared by the rendering tests.
#include <algorithm>
#include <array>
#include <cmath>

#include "fieldviz/render/ColorMap.h"
#include "fieldviz/render/RgbaImage.h"

namespace fluidviz::testing {

/// Largest difference, in 8-bit levels over R, G and B, between pixel (x, y) and colour c
/// (components in [0, 1], clamped as the renderer clamps them).
inline double levelsOff(const RgbaImage& image, int x, int y, const ColorMap::Color& c) {
  const auto p = image.pixel(x, y);
  double worst = 0;
  for (int k = 0; k < 3; ++k)
    worst = std::max(worst, std::abs(p[k] - 255.0 * std::clamp(c[k], 0.0, 1.0)));
  return worst;
}

/// True if pixel (x, y) shows the background colour within 1.5 levels (rounding of the blend).
inline bool isBackground(const RgbaImage& image, int x, int y, const std::array<double, 3>& background) {
  return levelsOff(image, x, y, {background[0], background[1], background[2]}) <= 1.5;
}

}  // namespace fluidviz::testing
