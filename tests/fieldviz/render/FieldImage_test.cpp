// Field pictures: colours of known fields against the colour map, the field's place in the
// picture against the layout arithmetic, slices of 3D fields, overlays, and parameter errors.
#include "fieldviz/render/FieldImage.h"
#include "tests/fieldviz/render/PixelChecks.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkLineSource.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <set>

namespace fluidviz {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ScalarField makeField(const std::string& name, std::array<int, 3> dims,
                      std::array<double, 3> origin, std::array<double, 3> spacing,
                      const std::function<double(const Vec3&, int, int, int)>& value) {
  ScalarField f{name, Grid{dims, origin, spacing}, {}};
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        f.values.push_back(value(f.grid.position(i, j, k), i, j, k));
  return f;
}

// Largest per-channel difference, in 8-bit levels, between a pixel and a colour.
using fluidviz::testing::levelsOff;

bool isWhite(const RgbaImage& image, int x, int y) {
  return levelsOff(image, x, y, {1.0, 1.0, 1.0}) <= 1.0;
}

// A 2 x 1 field, x in [-1, 1], y in [2, 3], drawn 400 x 300 px with 10 px padding and nothing
// else: s = min((400 - 20) / 2, (300 - 20) / 1) = 190 px per unit, so the field covers
// x in [10, 390] and y in [10 + (280 - 190) / 2, ...] = [55, 245] (pixel edges, y from the top).
FieldImageParams bareParams() {
  FieldImageParams p;
  p.width = 400;
  p.height = 300;
  p.padding = 10;
  p.scalar_bar = false;
  p.title = "";
  return p;
}
constexpr double kLeft = 10, kRight = 390, kTop = 55, kBottom = 245, kPxPerUnit = 190;

ScalarField halves() {  // 0 left of x = 0, 1 right of it, 0.5 on the node at x = 0
  return makeField("halves", {41, 21, 1}, {-1.0, 2.0, 0.0}, {0.05, 0.05, 1.0},
                   [](const Vec3& p, int, int, int) {
                     return std::abs(p[0]) < 1e-9 ? 0.5 : (p[0] < 0 ? 0.0 : 1.0);
                   });
}

TEST(FieldImage, FlatRegionsHaveTheColourMapsColoursWithinTwoLevels) {
  const FieldImageParams params = bareParams();
  const RgbaImage image = renderFieldImage(halves(), params);
  const ColorMap& viridis = ColorMap::byName("viridis");
  // The node values change only within 1 spacing (9.5 px) of x = 0, i.e. pixel column 200.
  double worstLeft = 0, worstRight = 0;
  for (int y = 60; y <= 240; y += 20) {
    for (int x = 12; x <= 185; x += 7)
      worstLeft = std::max(worstLeft, levelsOff(image, x, y, viridis.map(0)));
    for (int x = 215; x <= 387; x += 7)
      worstRight = std::max(worstRight, levelsOff(image, x, y, viridis.map(1)));
  }
  EXPECT_LE(worstLeft, 2.0);
  EXPECT_LE(worstRight, 2.0);
}

TEST(FieldImage, FieldCoversItsPhysicalExtentWithTheRightAspectWithinOnePixel) {
  FieldImageScene scene(halves(), bareParams());
  const PixelRect r = scene.fieldPixels();
  EXPECT_NEAR(r.left, kLeft, 1e-9);
  EXPECT_NEAR(r.right, kRight, 1e-9);
  EXPECT_NEAR(r.top, kTop, 1e-9);
  EXPECT_NEAR(r.bottom, kBottom, 1e-9);
  const RgbaImage image = scene.render();
  int first = -1, last = -1;
  for (int x = 0; x < image.width; ++x)
    if (!isWhite(image, x, 150)) (first < 0 ? first : last) = x, last = x;
  EXPECT_NEAR(first, kLeft, 1.0);  // first covered column starts at the left edge
  EXPECT_NEAR(last, kRight - 1, 1.0);
  first = last = -1;
  for (int y = 0; y < image.height; ++y)
    if (!isWhite(image, 100, y)) (first < 0 ? first : last) = y, last = y;
  EXPECT_NEAR(first, kTop, 1.0);
  EXPECT_NEAR(last, kBottom - 1, 1.0);
}

// f = x on [-1, 1] with the automatic range: a pixel whose centre is at x shows map((x + 1) / 2).
// Tolerance 2 levels: the 1024-entry table quantises t by 1/1024 (viridis changes up to ~0.7
// levels per entry) and 8-bit rounding adds 0.5 (measured: 1.0).
TEST(FieldImage, LinearRampShowsTheMapsColourOfTheValueAtEachPixelWithinTwoLevels) {
  const ScalarField ramp = makeField("ramp", {41, 21, 1}, {-1.0, 2.0, 0.0}, {0.05, 0.05, 1.0},
                                     [](const Vec3& p, int, int, int) { return p[0]; });
  const RgbaImage image = renderFieldImage(ramp, bareParams());
  const ColorMap& viridis = ColorMap::byName("viridis");
  double worst = 0;
  for (int x = 11; x <= 388; ++x) {
    const double worldX = -1.0 + (x + 0.5 - kLeft) / kPxPerUnit;
    for (int y : {60, 150, 240})
      worst = std::max(worst, levelsOff(image, x, y, viridis.map((worldX + 1) / 2)));
  }
  EXPECT_LE(worst, 2.0);
}

TEST(FieldImage, GivenRangeMapsValuesOntoIt) {
  const ScalarField one = makeField("one", {5, 5, 1}, {0, 0, 0}, {1, 1, 1},
                                    [](const Vec3&, int, int, int) { return 1.0; });
  FieldImageParams p = bareParams();
  p.colormap = "grayscale";
  p.range_min = 0.0;
  p.range_max = 4.0;
  const RgbaImage image = renderFieldImage(one, p);  // t = 0.25: level 63.75
  EXPECT_LE(levelsOff(image, 200, 150, {0.25, 0.25, 0.25}), 1.0);
}

// A constant field cannot set a range: it is drawn with the middle colour, range value +- 5 %.
// A single given bound is kept even when all data lie on its wrong side.
TEST(FieldImage, ConstantFieldIsDrawnWithTheMiddleColourAndSingleBoundsAreKept) {
  const ScalarField two = makeField("two", {5, 5, 1}, {0, 0, 0}, {1, 1, 1},
                                    [](const Vec3&, int, int, int) { return 2.0; });
  FieldImageScene scene(two, bareParams());
  EXPECT_NEAR(scene.range()[0], 1.9, 1e-12);
  EXPECT_NEAR(scene.range()[1], 2.1, 1e-12);
  EXPECT_LE(levelsOff(scene.render(), 200, 150, ColorMap::byName("viridis").map(0.5)), 2.0);
  FieldImageParams p = bareParams();
  p.range_min = 3.0;
  EXPECT_EQ(FieldImageScene(two, p).range()[0], 3.0);
  EXPECT_NEAR(FieldImageScene(two, p).range()[1], 3.3, 1e-12);
  p.range_min.reset();
  p.range_max = 0.0;
  EXPECT_EQ(FieldImageScene(two, p).range(), (std::array<double, 2>{-1.0, 0.0}));
}

TEST(FieldImage, AutomaticRangeIgnoresNaNAndNaNNodesAreGrey) {
  const ScalarField f =
      makeField("holes", {21, 21, 1}, {0, 0, 0}, {0.1, 0.1, 1}, [](const Vec3& p, int i, int, int) {
        if (p[0] > 1.45) return kNaN;  // right quarter missing
        return i < 5 ? 3.0 : -1.0;
      });
  FieldImageParams params = bareParams();
  FieldImageScene scene(f, params);
  EXPECT_EQ(scene.range(), (std::array<double, 2>{-1.0, 3.0}));
  const RgbaImage image = scene.render();
  const PixelRect r = scene.fieldPixels();
  const int y = static_cast<int>(0.5 * (r.top + r.bottom));
  const auto atX = [&](double worldX) {
    return static_cast<int>(r.left + worldX / 2.0 * (r.right - r.left));
  };
  EXPECT_LE(levelsOff(image, atX(0.9), y, ColorMap::byName("viridis").map(0.0)), 2.0);
  EXPECT_LE(levelsOff(image, atX(1.8), y, kMaskedGrey), 2.0) << "NaN nodes in the LIC mask grey";
}

TEST(FieldImage, ThreeDimensionalFieldDrawsTheRequestedZSlice) {
  const ScalarField f = makeField("layers", {6, 4, 3}, {0, 0, -1}, {1, 1, 0.5},
                                  [](const Vec3&, int, int, int k) { return double(k); });
  FieldImageParams p = bareParams();
  p.range_min = 0.0;
  p.range_max = 2.0;
  const ColorMap& viridis = ColorMap::byName("viridis");
  for (int k = 0; k < 3; ++k) {
    p.slice_index = k;
    FieldImageScene scene(f, p);
    EXPECT_DOUBLE_EQ(scene.planeZ(), -1.0 + 0.5 * k);
    EXPECT_LE(levelsOff(scene.render(), 200, 150, viridis.map(k / 2.0)), 2.0) << "slice " << k;
  }
}

void expectParamError(const std::function<void()>& call, const std::string& key,
                      const std::vector<std::string>& mentions) {
  try {
    call();
    ADD_FAILURE() << "expected a ParamError for " << key;
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    for (const std::string& m : mentions)
      EXPECT_NE(std::string(e.what()).find(m), std::string::npos) << m << " not in: " << e.what();
  }
}

TEST(FieldImage, ThreeDimensionalFieldNeedsAValidSliceIndex) {
  const ScalarField f = makeField("p3d", {4, 4, 5}, {0, 0, 0}, {1, 1, 1},
                                  [](const Vec3&, int, int, int) { return 0.0; });
  FieldImageParams p = bareParams();
  expectParamError([&] { renderFieldImage(f, p); }, "slice_index", {"p3d", "[0, 4]"});
  p.slice_index = 5;
  expectParamError([&] { renderFieldImage(f, p); }, "slice_index", {"5", "[0, 4]"});
  p.slice_index = 1;
  expectParamError([&] { renderFieldImage(halves(), p); }, "slice_index", {"2D"});
}

TEST(FieldImage, BadParametersThrowNamingKeyAndAllowedRange) {
  const ScalarField f = halves();
  FieldImageParams p = bareParams();
  p.width = 8;
  expectParamError([&] { renderFieldImage(f, p); }, "width", {"8", "[16, 8192]"});
  p = bareParams();
  p.colormap = "jet";
  expectParamError([&] { renderFieldImage(f, p); }, "colormap", {"jet", "viridis", "coolwarm"});
  p = bareParams();
  p.background = static_cast<Background>(7);
  expectParamError([&] { renderFieldImage(f, p); }, "background", {"white", "dark"});
  p = bareParams();
  p.range_min = 1.0;
  p.range_max = 1.0;
  expectParamError([&] { renderFieldImage(f, p); }, "range_max", {"range_min"});
  p = bareParams();
  p.width = p.height = 16;
  p.padding = 10;
  expectParamError([&] { renderFieldImage(f, p); }, "padding", {"16 x 16"});
}

TEST(FieldImage, BadFieldsThrowNamingTheField) {
  ScalarField f = halves();
  f.values.pop_back();
  try {
    renderFieldImage(f, bareParams());
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("halves"), std::string::npos) << e.what();
  }
  const ScalarField empty = makeField("allnan", {3, 3, 1}, {0, 0, 0}, {1, 1, 1},
                                      [](const Vec3&, int, int, int) { return kNaN; });
  try {
    renderFieldImage(empty, bareParams());
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("range_min"), std::string::npos) << e.what();
  }
}

// A line added at overlayZ() in world coordinates lands where fieldPixels() says it should.
TEST(FieldImage, OverlayActorsDrawOnTopOfTheFieldAtTheirWorldPosition) {
  FieldImageParams p = bareParams();
  p.colormap = "grayscale";
  FieldImageScene scene(halves(), p);
  const double y = 2.75;  // a quarter below the top edge y = 3
  vtkNew<vtkLineSource> line;
  line->SetPoint1(-0.9, y, scene.overlayZ());
  line->SetPoint2(0.9, y, scene.overlayZ());
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(line->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1.0, 0.0, 0.0);
  actor->GetProperty()->SetLineWidth(3.0);
  actor->GetProperty()->LightingOff();
  scene.renderer().addProp(actor);
  const RgbaImage image = scene.render();
  const int row = static_cast<int>(kTop + (3.0 - y) * kPxPerUnit);  // 102
  for (int x : {40, 150, 250, 360}) {
    EXPECT_LE(levelsOff(image, x, row, {1.0, 0.0, 0.0}), 2.0) << "on the line at x " << x;
    EXPECT_GT(levelsOff(image, x, row - 4, {1.0, 0.0, 0.0}), 100.0) << "above the line at x " << x;
  }
}

TEST(FieldImage, TitleAndScalarBarAreDrawnBesideAndAboveTheField) {
  FieldImageParams p;
  p.width = 800;
  p.height = 600;
  p.title = "Halves";
  FieldImageScene scene(halves(), p);
  const PixelRect r = scene.fieldPixels();
  const RgbaImage image = scene.render();
  // Text is black on white: dark pixels above the field (left of the legend, whose title may
  // stand higher), centred on the picture.
  int minX = image.width, maxX = -1;
  for (int y = 0; y < static_cast<int>(r.top); ++y)
    for (int x = 0; x < static_cast<int>(r.right); ++x)
      if (levelsOff(image, x, y, {0, 0, 0}) < 60)
        minX = std::min(minX, x), maxX = std::max(maxX, x);
  ASSERT_GE(maxX, 0) << "no title pixels above the field";
  EXPECT_NEAR(0.5 * (minX + maxX), 400.0, 4.0);
  // The legend right of the field shows both ends of the colour map.
  const ColorMap& viridis = ColorMap::byName("viridis");
  bool sawFirst = false, sawLast = false;
  for (int y = static_cast<int>(r.top); y < static_cast<int>(r.bottom); ++y)
    for (int x = static_cast<int>(r.right) + 2; x < image.width; ++x) {
      sawFirst = sawFirst || levelsOff(image, x, y, viridis.map(0.0)) <= 2.0;
      sawLast = sawLast || levelsOff(image, x, y, viridis.map(1.0)) <= 2.0;
    }
  EXPECT_TRUE(sawFirst);
  EXPECT_TRUE(sawLast);
}

TEST(FieldImage, DarkBackgroundFillsAroundTheField) {
  FieldImageParams p = bareParams();
  p.background = fluidviz::Background::dark;
  const RgbaImage image = renderFieldImage(halves(), p);
  EXPECT_LE(levelsOff(image, 3, 3, {0.08, 0.08, 0.10}), 1.0);
  EXPECT_LE(levelsOff(image, 200, 20, {0.08, 0.08, 0.10}), 1.0);
}

TEST(FieldImage, PngFileHoldsTheRenderedPicture) {
  const fs::path dir =
      fs::temp_directory_path() / ("fluidviz_field_image_test_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "halves.png";
  writeFieldImagePng(halves(), bareParams(), file);
  const RgbaImage expected = renderFieldImage(halves(), bareParams());
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkImageData* read = reader->GetOutput();
  ASSERT_EQ(read->GetDimensions()[0], 400);
  ASSERT_EQ(read->GetDimensions()[1], 300);
  int mismatches = 0;
  for (int y = 0; y < 300; y += 3)
    for (int x = 0; x < 400; x += 3)
      for (int k = 0; k < 3; ++k)
        mismatches += read->GetScalarComponentAsDouble(x, 299 - y, 0, k) != expected.pixel(x, y)[k];
  EXPECT_EQ(mismatches, 0);
  FieldImageParams bad = bareParams();
  bad.colormap = "nope";
  EXPECT_THROW(writeFieldImagePng(halves(), bad, dir / "bad.png"), ParamError);
  EXPECT_FALSE(fs::exists(dir / "bad.png"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

// axes = true: a tick below the field at every round x (0, 0.5, ..., 2 on [0, 2]) and left of
// it at every round y, in the text colour, nothing between them; the field gives up the bands
// the labels need and keeps its aspect ratio.
TEST(FieldImage, AxesPutATickAtEveryRoundCoordinate) {
  const ScalarField f = makeField("plane", {21, 11, 1}, {0, 0, 0}, {0.1, 0.1, 1},
                                  [](const Vec3&, int, int, int) { return 1.0; });
  FieldImageParams p = bareParams();
  p.axes = true;
  p.range_min = 0.0;
  p.range_max = 2.0;
  FieldImageScene scene(f, p);
  const PixelRect r = scene.fieldPixels();
  EXPECT_GT(r.left, kLeft + 20) << "room for the y labels";
  EXPECT_LT(r.bottom, kBottom) << "room for the x labels";
  EXPECT_NEAR((r.right - r.left) / (r.bottom - r.top), 2.0, 0.02);
  const RgbaImage image = scene.render();
  const double s = (r.right - r.left) / 2.0;
  const int tickY = static_cast<int>(r.bottom) + 1;  // just below the field's bottom edge
  const auto dark = [&](int x, int y) {
    const auto px = image.pixel(x, y);
    return px[0] < 128 && px[1] < 128 && px[2] < 128;
  };
  const auto darkNear = [&](double x, int y) {  // a 1 px line lands on one of two pixels
    return dark(static_cast<int>(std::floor(x)), y) || dark(static_cast<int>(std::floor(x)) - 1, y);
  };
  for (double x : {0.0, 0.5, 1.0, 1.5, 2.0}) EXPECT_TRUE(darkNear(r.left + x * s, tickY)) << x;
  for (double x : {0.25, 0.75, 1.25, 1.75})
    EXPECT_FALSE(dark(static_cast<int>(r.left + x * s), tickY)) << "between ticks " << x;
  const int tickX = static_cast<int>(r.left) - 2;
  for (double y : {0.2, 0.4, 0.6, 0.8}) {
    const double py = r.bottom - y * s;
    EXPECT_TRUE(dark(tickX, static_cast<int>(std::floor(py))) ||
                dark(tickX, static_cast<int>(std::floor(py)) - 1))
        << y;
  }
  EXPECT_FALSE(dark(tickX, static_cast<int>(r.bottom - 0.3 * s))) << "between ticks 0.3";
}

TEST(FieldImage, AnAxesUnitLongerThan16CharactersIsRefusedNamingTheKey) {
  FieldImageParams p = bareParams();
  p.axes_unit = "astronomical units";
  try {
    validateFieldImageParams(p);
    FAIL() << "no error";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "axes_unit");
    EXPECT_NE(std::string(e.what()).find("at most 16 characters"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidviz

// Legend labels must tell neighbouring values apart: 5 labels of a narrow range far from zero
// (a settled SPH density, 1000-1000.25 kg/m^3) print as 5 different strings, and a range of
// 2.5 prints the one decimal of its round ticks (0.5 apart).
TEST(FieldImageLegend, LabelsOfANarrowRangeDiffer) {
  const auto labels = [](std::array<double, 2> range) {
    const std::string format = fluidviz::legendLabelFormat(range);
    std::set<std::string> distinct;
    for (int i = 0; i < 5; ++i) {
      char text[64];
      std::snprintf(text, sizeof text, format.c_str(), range[0] + (range[1] - range[0]) * i / 4);
      distinct.insert(text);
    }
    return distinct;
  };
  EXPECT_EQ(labels({1000.0, 1000.25}).size(), 5u);
  EXPECT_EQ(labels({-1e-6, 1e-6}).size(), 5u);
  EXPECT_EQ(fluidviz::legendLabelFormat({0.0, 2.5}), "%.1f");  // ticks 0.0, 0.5, ..., 2.5
  EXPECT_EQ(*labels({1000.0, 1000.25}).begin(), "1000.00");
}
