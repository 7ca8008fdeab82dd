// LIC pictures and streamline overlays (fieldviz/render/LicBlend.h, LicPicture.h,
// StreamlineOverlay.h): the blend rule per pixel, texture pixels landing 1:1 on picture pixels
// with row 0 at the bottom, masked pixels, lines and arrowheads where the geometry puts them.
#include <gtest/gtest.h>

#include <cmath>

#include "fieldviz/render/LicBlend.h"
#include "fieldviz/render/LicPicture.h"
#include "fieldviz/render/StreamlineOverlay.h"
#include "tests/fieldviz/render/PixelChecks.h"

namespace fluidviz {
namespace {

// Largest per-channel difference in 8-bit levels between a picture pixel and a colour.
using fluidviz::testing::levelsOff;

TEST(LicBlend, AverageTextureShowsTheLegendColourAndStreaksShiftAllChannelsEqually) {
  const ColorMap::Color c{0.2, 0.4, 0.6};
  EXPECT_EQ(blendLicColor(c, 0.5, 0.6), c);
  const auto bright = blendLicColor(c, 1.0, 0.6), dark = blendLicColor(c, 0.0, 0.6);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(bright[k], c[k] + 0.3);
    EXPECT_DOUBLE_EQ(dark[k], c[k] - 0.3);
  }
  EXPECT_EQ(blendLicColor(c, 0.9, 0.0), c);  // weight 0: the colour map alone
  EXPECT_EQ(toByte(1.2), 255);
  EXPECT_EQ(toByte(-0.1), 0);
  EXPECT_EQ(toByte(0.5), 128);  // 127.5 rounds up
}

// A 2 m x 1 m field (colour = x), a 100 x 50 px texture with a known pattern and a masked
// block: every texture pixel must appear at picture pixel (left + i, top + 49 - j) with the
// colour of the blend rule.
struct Synthetic {
  ScalarField colour{"x", {}, {}};
  ScalarField texture{"lic", {}, {}};
  std::vector<std::uint8_t> mask;
  Synthetic() {
    colour.grid.dims = {21, 11, 1};
    colour.grid.spacing = {0.1, 0.1, 1.0};
    for (int j = 0; j < 11; ++j)
      for (int i = 0; i < 21; ++i) colour.values.push_back(0.1 * i);
    texture.grid.dims = {100, 50, 1};
    texture.grid.spacing = {0.02, 0.02, 1.0};
    texture.grid.origin = {0.01, 0.01, 0.0};
    for (int j = 0; j < 50; ++j)
      for (int i = 0; i < 100; ++i) {
        texture.values.push_back(((7 * i + 3 * j) % 11) / 10.0);
        mask.push_back(i >= 80 && j < 10);  // bottom-right block
      }
  }
};

// Largest difference (8-bit levels) between a texture pixel, blended by the rule, and the
// picture pixel it must land on (left + i, top + 49 - j); also counts the masked pixels seen.
double worstTexturePixel(const LicPicture& out, const Synthetic& s, const LicBlendParams& blend,
                         int& masked) {
  const ColorMap& viridis = ColorMap::byName("viridis");
  double worst = 0;
  masked = 0;
  for (int j = 0; j < 50; ++j)
    for (int i = 0; i < 100; ++i) {
      const std::size_t n = static_cast<std::size_t>(j) * 100 + i;
      const double x = 0.01 + 0.02 * i;  // pixel centre; colour = x, range [0, 2]
      const ColorMap::Color expected =
          s.mask[n] ? blend.mask_color
                    : blendLicColor(viridis.map(x / 2.0), s.texture.values[n], blend.lic_weight);
      const int px = static_cast<int>(out.texture.left) + i;
      const int py = static_cast<int>(out.texture.top) + 49 - j;
      worst = std::max(worst, levelsOff(out.image, px, py, expected));
      masked += s.mask[n];
    }
  return worst;
}

// The synthetic picture titled "synthetic", half LIC, masked pixels magenta; with or without axes.
struct SyntheticPicture {
  Synthetic s;
  FieldImageParams picture;
  LicBlendParams blend;
  LicPicture out;
  explicit SyntheticPicture(bool axes) {
    picture.title = "synthetic";
    picture.axes = axes;
    blend.lic_weight = 0.5;
    blend.mask_color = {1.0, 0.0, 1.0};
    out = renderLicPicture(s.texture, s.mask, s.colour, picture, blend);
  }
};

TEST(LicPicture, EveryTexturePixelLandsOnOnePicturePixelWithTheBlendRuleColour) {
  const SyntheticPicture p(false);
  // Plain references, not a structured binding: clang 14 cannot capture those in lambdas.
  const Synthetic& s = p.s;
  const FieldImageParams& picture = p.picture;
  const LicBlendParams& blend = p.blend;
  const LicPicture& out = p.out;
  EXPECT_EQ(out.texture.right - out.texture.left, 100);
  EXPECT_EQ(out.texture.bottom - out.texture.top, 50);
  EXPECT_EQ(out.range, (std::array<double, 2>{0.0, 2.0}));
  // The picture is fitted around the texture: no spare margin beyond padding, legend and title.
  EXPECT_LT(out.image.width, 100 + 2 * picture.padding + 200);
  int masked = 0;
  // Exact up to 8-bit rounding of the map's interpolation (the texture is uploaded as bytes).
  EXPECT_LE(worstTexturePixel(out, s, blend, masked), 1.0);
  EXPECT_EQ(masked, 200);
}

// axes = true: the picture grows by the axes' bands, the texture still lands 1:1 on picture
// pixels, a tick sits below the texture at every round x (0, 0.5, ..., 2 m), and the picture
// keeps no spare margin: its leftmost drawn column (the y axis title) lies within 3 px of the
// padding.
TEST(LicPicture, AxesGrowThePictureAndLeaveTheTextureOnItsPixels) {
  const SyntheticPicture p(true);
  // Plain references, not a structured binding: clang 14 cannot capture those in lambdas.
  const Synthetic& s = p.s;
  const FieldImageParams& picture = p.picture;
  const LicBlendParams& blend = p.blend;
  const LicPicture& out = p.out;
  EXPECT_EQ(out.texture.right - out.texture.left, 100);
  EXPECT_EQ(out.texture.bottom - out.texture.top, 50);
  int masked = 0;
  EXPECT_LE(worstTexturePixel(out, s, blend, masked), 1.0);
  const auto dark = [&](int x, int y) {
    const auto px = out.image.pixel(x, y);
    return px[0] < 128 && px[1] < 128 && px[2] < 128;
  };
  const int tickY = static_cast<int>(out.texture.bottom) + 1;
  for (double x : {0.0, 0.5, 1.0, 1.5, 2.0}) {
    const int px = static_cast<int>(std::floor(out.texture.left + 50 * x));
    EXPECT_TRUE(dark(px, tickY) || dark(px - 1, tickY)) << x;
  }
  EXPECT_FALSE(dark(static_cast<int>(out.texture.left + 50 * 0.25), tickY)) << "between ticks";
  int firstDarkColumn = out.image.width;
  for (int x = 0; x < out.image.width && firstDarkColumn == out.image.width; ++x)
    for (int y = 0; y < out.image.height; ++y)
      if (dark(x, y)) {
        firstDarkColumn = x;
        break;
      }
  EXPECT_GE(firstDarkColumn, picture.padding);
  EXPECT_LE(firstDarkColumn, picture.padding + 3);
}

TEST(LicPicture, LinesAndOutlinesCoverThePixelsTheirWidthsSay) {
  const Synthetic s;
  FieldImageParams picture;
  picture.scalar_bar = false;
  LicBlendParams blend;
  blend.lic_weight = 0.0;  // plain colour map under the line
  LineOverlay line;
  // y = 0.51 m: the centre of texture row 25, i.e. picture row top + 24 (20 m / 0.02 px = 50 px).
  line.lines = {{Vec3(0.2, 0.51, 0), Vec3(1.8, 0.51, 0)}};
  line.style.line_color = {1.0, 0.0, 0.0};
  line.style.line_width = 1.0;
  line.style.outline_width = 1.0;
  line.style.arrows = false;
  const LicPicture out = renderLicPicture(s.texture, {}, s.colour, picture, blend, {line});
  const int row = static_cast<int>(out.texture.top) + 24;
  const ColorMap& viridis = ColorMap::byName("viridis");
  for (int i : {20, 50, 80}) {  // x = 0.41, 1.01, 1.61 m
    const int x = static_cast<int>(out.texture.left) + i;
    const ColorMap::Color under = viridis.map((0.01 + 0.02 * i) / 2.0);
    EXPECT_LE(levelsOff(out.image, x, row, {1, 0, 0}), 1.0) << "line at column " << i;
    // 1 px outline each side of a 1 px line: the rows next to it are white (red is a dark
    // colour: luma 0.21 < 1/2) ...
    EXPECT_LE(levelsOff(out.image, x, row - 1, {1, 1, 1}), 1.0) << "outline above, column " << i;
    EXPECT_LE(levelsOff(out.image, x, row + 1, {1, 1, 1}), 1.0) << "outline below, column " << i;
    // ... and two rows away the field shows again.
    EXPECT_LE(levelsOff(out.image, x, row - 2, under), 1.0) << "field above, column " << i;
    EXPECT_LE(levelsOff(out.image, x, row + 2, under), 1.0) << "field below, column " << i;
  }
  // Past the line's ends (x < 0.2 m, 10 px from the left edge) the field is untouched.
  EXPECT_LE(levelsOff(out.image, static_cast<int>(out.texture.left) + 5, row,
                      viridis.map(0.11 / 2.0)),
            1.0);
}

TEST(StreamlineOverlay, ArrowheadsSitEverySpacingFromHalfASpacingAndPointDownstream) {
  // An L-shaped line 3 + 2 units long, spacing 1: centres at 0.5, 1.5, 2.5, 3.5, 4.5 of arc.
  const std::vector<std::vector<Vec3>> lines = {
      {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 2, 0)}};
  const auto tris = arrowheads(lines, 1.0, 0.2, 7.0);
  ASSERT_EQ(tris.size(), 5u);
  const Vec3 centres[5] = {{0.5, 0, 7}, {1.5, 0, 7}, {2.5, 0, 7}, {3, 0.5, 7}, {3, 1.5, 7}};
  const Vec3 dirs[5] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}};
  for (int k = 0; k < 5; ++k) {
    EXPECT_LT((tris[k][0] - (centres[k] + 0.1 * dirs[k])).norm(), 1e-12) << "tip " << k;
    const Vec3 base = 0.5 * (tris[k][1] + tris[k][2]);
    EXPECT_LT((base - (centres[k] - 0.1 * dirs[k])).norm(), 1e-12) << "base " << k;
    EXPECT_NEAR((tris[k][1] - tris[k][2]).norm(), 0.14, 1e-12) << "width " << k;
  }
  EXPECT_TRUE(arrowheads({{Vec3(0, 0, 0)}}, 1.0, 0.2, 0.0).empty());  // a seed alone: no arrow
}

}  // namespace
}  // namespace fluidviz
