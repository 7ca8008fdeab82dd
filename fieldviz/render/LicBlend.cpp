#include "fieldviz/render/LicBlend.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fieldviz/core/Sampling.h"

namespace fluidviz {

ColorMap::Color blendLicColor(const ColorMap::Color& mapped, double lic, double weight) {
  const double shift = weight * (std::clamp(lic, 0.0, 1.0) - 0.5);
  return {mapped[0] + shift, mapped[1] + shift, mapped[2] + shift};
}

std::uint8_t toByte(double c) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(c, 0.0, 1.0)));
}

namespace {

ColorMap::Color mappedColour(const ScalarField& colour, const Vec3& p, const ColorMap& map,
                             const std::array<double, 2>& range) {
  const std::optional<double> s = sample(colour, p);
  if (!s || !std::isfinite(*s)) return {0.5, 0.5, 0.5};
  return map.map((*s - range[0]) / (range[1] - range[0]));
}

}  // namespace

RgbaImage blendLicTexture(const ScalarField& texture, const std::vector<std::uint8_t>& mask,
                          const ScalarField& colour, const ColorMap& map,
                          const std::array<double, 2>& range, const LicBlendParams& params) {
  const Grid& g = texture.grid;
  const int W = g.dims[0], H = g.dims[1];
  if (texture.values.size() != g.nodeCount() || (!mask.empty() && mask.size() != g.nodeCount()))
    throw std::invalid_argument("blendLicTexture: texture '" + texture.name + "' (" +
                                g.describe() + ") has " + std::to_string(texture.values.size()) +
                                " values and " + std::to_string(mask.size()) + " mask entries");
  if (!(range[0] < range[1]))
    throw std::invalid_argument("blendLicTexture: colour range must have lo < hi");
  RgbaImage image{W, H, std::vector<std::uint8_t>(static_cast<std::size_t>(W) * H * 4)};
  // The colour scalar lives on the field grid (2D, or the slice at the texture's height).
  ScalarField planar = colour;
  if (planar.grid.is2D()) planar.grid.origin[2] = g.origin[2];
#pragma omp parallel for schedule(static)
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const std::size_t n = static_cast<std::size_t>(j) * W + i;
      const ColorMap::Color c =
          !mask.empty() && mask[n]
              ? params.mask_color
              : blendLicColor(mappedColour(planar, g.position(i, j), map, range),
                              texture.values[n], params.lic_weight);
      std::uint8_t* px = &image.pixels[4 * (static_cast<std::size_t>(H - 1 - j) * W + i)];
      px[0] = toByte(c[0]), px[1] = toByte(c[1]), px[2] = toByte(c[2]), px[3] = 255;
    }
  return image;
}

}  // namespace fluidviz
