// Pictures of topology, checked pixel by pixel: critical point glyphs land on their points with
// their type's fill and a dark outline, the legend lists the types, the bifurcation diagram puts
// each point at its parameter and coordinate, and the topology picture (LIC background) carries
// the glyphs of the points it was given.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "pipeline/TopologyOutputs.h"
#include "fieldviz/render/BifurcationDiagram.h"
#include "fieldviz/render/CriticalPointGlyphs.h"
#include "fieldviz/render/LicBlend.h"
#include "filters/topology/Separatrices.h"
#include "filters/topology/VectorFieldTopology.h"

using namespace fluidviz;

namespace {

using Pixel = std::array<std::uint8_t, 4>;

std::array<int, 3> bytes(const Rgb& c) { return {toByte(c[0]), toByte(c[1]), toByte(c[2])}; }

bool isColour(const Pixel& p, const Rgb& c, int tolerance = 1) {
  const auto b = bytes(c);
  for (int k = 0; k < 3; ++k)
    if (std::abs(p[k] - b[k]) > tolerance) return false;
  return true;
}

int countColour(const RgbaImage& img, const Rgb& c) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += isColour(img.pixel(x, y), c);
  return n;
}

ScalarField constantField(double value) {
  Grid g;
  g.dims = {21, 21, 1};
  g.spacing = {0.05, 0.05, 1.0};
  return {"s", g, std::vector<double>(g.nodeCount(), value)};
}

}  // namespace

// A centre glyph (white disc, 16 px) at world (0.3, 0.7) of a 1 m field: its centre pixel is
// white, the ring just outside its radius is the dark outline, and beyond that the field shows.
TEST(CriticalPointGlyphs, GlyphSitsOnItsPointWithFillAndOutline) {
  FieldImageParams params;
  params.width = params.height = 400;
  params.scalar_bar = false;
  params.colormap = "viridis";
  FieldImageScene scene(constantField(0.0), params);
  const PixelRect r = scene.fieldPixels();
  const double scale = (r.right - r.left) / 1.0;
  addCriticalPointGlyphs(scene, {{Vec3(0.3, 0.7, 0), "centre"}, {Vec3(0.8, 0.2, 0), "saddle"}},
                         16.0, scale);
  const RgbaImage img = scene.render();
  // Picture pixel of a world point: x from the left edge, y from the top (y up in the world).
  auto pixelOf = [&](double x, double y) {
    return std::array<int, 2>{static_cast<int>(std::floor(r.left + x * scale)),
                              static_cast<int>(std::floor(r.bottom - y * scale))};
  };
  const auto c = pixelOf(0.3, 0.7);
  EXPECT_TRUE(isColour(img.pixel(c[0], c[1]), criticalPointGlyph("centre").fill));
  EXPECT_TRUE(isColour(img.pixel(c[0] + 5, c[1]), criticalPointGlyph("centre").fill));
  // Radius 8 px, outline 1.5 px: pixel 9 px right of the centre is the outline.
  const Pixel ring = img.pixel(c[0] + 9, c[1]);
  EXPECT_LT(ring[0] + ring[1] + ring[2], 3 * 40) << int(ring[0]) << "," << int(ring[1]);
  // 14 px away: the field's colour (viridis middle for a constant field).
  const Pixel outside = img.pixel(c[0] + 14, c[1]);
  EXPECT_FALSE(isColour(outside, criticalPointGlyph("centre").fill, 30));
  const auto s = pixelOf(0.8, 0.2);
  EXPECT_TRUE(isColour(img.pixel(s[0], s[1]), criticalPointGlyph("saddle").fill));
  // Each type its own shape and colour.
  std::set<std::string> fills;
  std::set<int> shapes;
  for (const std::string& type : criticalPointTypeOrder()) {
    const GlyphStyle g = criticalPointGlyph(type);
    fills.insert(std::to_string(bytes(g.fill)[0]) + "," + std::to_string(bytes(g.fill)[1]) +
                 "," + std::to_string(bytes(g.fill)[2]));
    shapes.insert(static_cast<int>(g.shape));
  }
  EXPECT_EQ(fills.size(), criticalPointTypeOrder().size());
  EXPECT_EQ(shapes.size(), criticalPointTypeOrder().size());
  EXPECT_EQ(criticalPointTypeOrder().size(), 14u);  // every CriticalPointType of the core
}

TEST(CriticalPointGlyphs, LegendShowsEveryEntrysGlyph) {
  const RgbaImage legend = renderGlyphLegend(
      {{"saddle (2)", "saddle"}, {"monkey saddle (1)", "monkey_saddle"}, {"source", "source"}},
      500, fluidviz::Background::white, 16.0);
  EXPECT_EQ(legend.width, 500);
  EXPECT_GT(legend.height, 16);
  EXPECT_LT(legend.height, 80);  // one row
  for (const char* type : {"saddle", "monkey_saddle", "source"})
    EXPECT_GT(countColour(legend, criticalPointGlyph(type).fill), 40) << type;
  const RgbaImage top{2, 1, std::vector<std::uint8_t>(8, 7)};
  const RgbaImage stacked = stackImages(top, legend);
  EXPECT_EQ(stacked.height, legend.height + 1);
  EXPECT_EQ(stacked.pixel(0, 0)[0], 7);
  EXPECT_EQ(stacked.pixel(10, 0)[0], 255);  // padding of the narrower image
}

// Monkey saddle at parameter 0, two saddles at +-1 moving apart: one magenta star and four red
// crosses per panel, each at its parameter and coordinate.
TEST(BifurcationDiagram, EachPointIsDrawnWithItsTypesGlyph) {
  std::vector<DiagramPoint> points = {{0.0, 0.5, 0.5, "monkey_saddle"},
                                      {-1.0, 0.45, 0.5, "saddle"}, {-1.0, 0.55, 0.5, "saddle"},
                                      {1.0, 0.42, 0.5, "saddle"},  {1.0, 0.58, 0.5, "saddle"}};
  BifurcationDiagramParams p;
  p.steps = {-1, 0, 1};
  p.title = "test";
  const RgbaImage img = renderBifurcationDiagram(points, p);
  EXPECT_EQ(img.width, p.width);
  EXPECT_GT(img.height, p.height);  // legend below
  const int star = countColour(img, criticalPointGlyph("monkey_saddle").fill);
  const int cross = countColour(img, criticalPointGlyph("saddle").fill);
  // Per glyph (13 px): star ~ 60 px, cross ~ 45 px (measured); 2 panels + legend.
  EXPECT_GT(star, 3 * 30);
  EXPECT_GT(cross, 9 * 25);
  EXPECT_GT(cross, star);  // eight saddle glyphs against two stars in the panels
}

// A cellular flow's topology picture over its LIC: every point's glyph and the separatrices.
TEST(TopologyPicture, LicPictureWithGlyphsAndLegend) {
  Grid g;
  g.dims = {61, 61, 1};
  g.origin = {-0.9, -0.9, 0};
  g.spacing = {0.03, 0.03, 1};
  VectorField v{"velocity", g, {}};
  const double k = std::numbers::pi;
  for (int j = 0; j < 61; ++j)
    for (int i = 0; i < 61; ++i) {
      const Vec3 q = g.position(i, j);
      v.values.emplace_back(k * std::sin(k * q.x()) * std::cos(k * q.y()),
                            -k * std::cos(k * q.x()) * std::sin(k * q.y()), 0);
    }
  const auto points = topology::findCriticalPoints(v, {});
  const auto seps = topology::computeSeparatrices(v, points, {});
  ASSERT_EQ(points.size(), 5u);
  TopologyPictureParams p;
  p.lic.width = 300;
  p.picture.title = "cellular flow";
  const RgbaImage img = renderTopologyPicture(v, points, seps, p);
  EXPECT_GE(img.width, 300);
  EXPECT_GT(img.height, 300);
  // Four white centre discs (~200 px each incl. legend: at least 4 x 150) and the saddle's red.
  EXPECT_GT(countColour(img, criticalPointGlyph("saddle").fill), 2 * 30);
  EXPECT_GT(countColour(img, criticalPointGlyph("centre").fill), 4 * 150);
  EXPECT_THROW(renderTopologyPicture(v, points, seps,
                                     [] {
                                       TopologyPictureParams bad;
                                       bad.glyph_size = 1;
                                       return bad;
                                     }()),
               ParamError);
}
