// Colour maps against their published tables.
#include "fieldviz/render/ColorMap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace fluidviz {
namespace {

constexpr double kOneLevel = 1.0 / 255.0;  // one 8-bit step

void expectColorNear(const ColorMap::Color& actual, const ColorMap::Color& expected, double tol,
                     const std::string& what) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(actual[k], expected[k], tol) << what << " channel " << k;
}

// Matplotlib 3.6 `_cm_listed.py`, 256-entry tables: entry i is the colour at t = i / 255. The
// middle t = 0.5 is checked against what matplotlib draws for it, entry floor(256 t) = 128.
struct Published {
  double t;
  ColorMap::Color rgb;
};

TEST(ColorMap, ViridisMatchesMatplotlibAtEndsQuartilesAndMiddleWithinOneLevel) {
  const Published points[] = {{0.0, {0.267004, 0.004874, 0.329415}},
                              {64 / 255.0, {0.229739, 0.322361, 0.545706}},
                              {0.5, {0.127568, 0.566949, 0.550556}},
                              {192 / 255.0, {0.369214, 0.788888, 0.382914}},
                              {1.0, {0.993248, 0.906157, 0.143936}}};
  const ColorMap& viridis = ColorMap::byName("viridis");
  for (const Published& p : points)
    expectColorNear(viridis.map(p.t), p.rgb, kOneLevel, "viridis t=" + std::to_string(p.t));
}

TEST(ColorMap, InfernoMatchesMatplotlibAtEndsQuartilesAndMiddleWithinOneLevel) {
  const Published points[] = {{0.0, {0.001462, 0.000466, 0.013866}},
                              {64 / 255.0, {0.3415, 0.062325, 0.429425}},
                              {0.5, {0.735683, 0.215906, 0.330245}},
                              {192 / 255.0, {0.978422, 0.557937, 0.034931}},
                              {1.0, {0.988362, 0.998364, 0.644924}}};
  const ColorMap& inferno = ColorMap::byName("inferno");
  for (const Published& p : points)
    expectColorNear(inferno.map(p.t), p.rgb, kOneLevel, "inferno t=" + std::to_string(p.t));
}

// Moreland (2009), Table "CoolWarmFloat33": blue end, grey middle (221,221,221), red end.
TEST(ColorMap, CoolwarmMatchesMorelandTableAtEndsAndMiddle) {
  const ColorMap& coolwarm = ColorMap::byName("coolwarm");
  expectColorNear(coolwarm.map(0.0), {0.2298057, 0.298717966, 0.753683153}, 1e-9, "t=0");
  expectColorNear(coolwarm.map(0.5), {0.865395197, 0.86541021, 0.865395561}, 1e-9, "t=0.5");
  expectColorNear(coolwarm.map(1.0), {0.705673158, 0.01555616, 0.150232812}, 1e-9, "t=1");
  // Between the published samples at 0.46875 and 0.5 the map is their average.
  expectColorNear(coolwarm.map(0.484375),
                  {(0.833466556 + 0.865395197) / 2, (0.860207984 + 0.86541021) / 2,
                   (0.901068838 + 0.865395561) / 2},
                  1e-9, "t=0.484375");
}

TEST(ColorMap, GrayscaleIsTheIdentityOnEachChannel) {
  const ColorMap& gray = ColorMap::byName("grayscale");
  for (double t : {0.0, 0.3, 0.71, 1.0}) expectColorNear(gray.map(t), {t, t, t}, 1e-12, "gray");
}

TEST(ColorMap, ClampsOutsideZeroOneAndDrawsNaNWithTheFirstColour) {
  const ColorMap& viridis = ColorMap::byName("viridis");
  expectColorNear(viridis.map(-3.0), viridis.map(0.0), 0.0, "below");
  expectColorNear(viridis.map(7.0), viridis.map(1.0), 0.0, "above");
  expectColorNear(viridis.map(std::numeric_limits<double>::quiet_NaN()), viridis.map(0.0), 0.0,
                  "NaN");
}

TEST(ColorMap, NamesListsTheFourMapsAndByNameFindsEach) {
  const std::vector<std::string> names = ColorMap::names();
  EXPECT_EQ(names, (std::vector<std::string>{"viridis", "inferno", "coolwarm", "grayscale"}));
  for (const std::string& n : names) EXPECT_EQ(ColorMap::byName(n).name(), n);
}

TEST(ColorMap, UnknownNameThrowsListingEveryAllowedName) {
  try {
    ColorMap::byName("jet");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("\"jet\""), std::string::npos) << message;
    for (const std::string& n : ColorMap::names())
      EXPECT_NE(message.find(n), std::string::npos) << message;
  }
}

TEST(ColorMap, RejectsFewerThanTwoControlPoints) {
  EXPECT_THROW(ColorMap("one", {{0.0, 0.0, 0.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz
