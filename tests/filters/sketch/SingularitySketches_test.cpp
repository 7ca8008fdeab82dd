// Sketched singularities (issue 20): a source, a sink, a centre and a saddle drawn as strokes
// are found by the topology filter (filters/topology) within one cell of where they were drawn,
// with the right Poincare index and type, and nothing else on the 48^2 grid (zero-flux sides).
// The radial sketches are not symmetric on the grid, so the source and sink get a rotation
// |Im| / |Re| ~ 2e-3 that the classifier reports as a spiral: both are accepted, the rotation
// bounded.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "filters/sketch/SketchedFlow.h"
#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/sketch/SketchTestFields.h"

namespace fluidviz::sketch {
namespace {

using topology::CriticalPointType;

const Vec3 kDrawnAt(23.4, 24.7, 0.0);  // off the nodes on purpose

Vec3 polar(double r, double angle) { return {r * std::cos(angle), r * std::sin(angle), 0.0}; }

/// Eight radial strokes from radius 3 to 15, outwards (source) or inwards (sink).
std::vector<Stroke> radialStrokes(bool outwards) {
  std::vector<Stroke> s;
  for (int k = 0; k < 8; ++k) {
    const double a = k * std::numbers::pi / 4 + 0.2;
    Vec3 inner = kDrawnAt + polar(3, a), outer = kDrawnAt + polar(15, a);
    if (!outwards) std::swap(inner, outer);
    s.push_back(testing::lineStroke(inner, outer, 0.05));
  }
  return s;
}

/// Concentric circles of radius 5, 10, 15 counter-clockwise.
std::vector<Stroke> circles() {
  std::vector<Stroke> s;
  for (double r : {5.0, 10.0, 15.0}) s.push_back(testing::circleStroke(kDrawnAt, r, 72, 0.05));
  return s;
}

/// Inflow along x from both sides, outflow along y to both sides.
std::vector<Stroke> saddleStrokes() {
  std::vector<Stroke> s;
  for (double side : {-1.0, 1.0}) {
    s.push_back(testing::lineStroke(kDrawnAt + Vec3(15 * side, 0, 0),
                                    kDrawnAt + Vec3(3 * side, 0, 0), 0.05));
    s.push_back(testing::lineStroke(kDrawnAt + Vec3(0, 3 * side, 0),
                                    kDrawnAt + Vec3(0, 15 * side, 0), 0.05));
  }
  return s;
}

struct Case {
  std::string name;
  std::vector<Stroke> strokes;
  int index;
  std::vector<CriticalPointType> types;  ///< accepted types
};

/// |Im| / |Re| of the Jacobian's first eigenvalue: how much a node spirals.
double spiralRatio(const topology::CriticalPoint& p) {
  return std::abs(p.eigenvalues[0].imag()) / std::abs(p.eigenvalues[0].real());
}

TEST(SingularitySketches, FoundWithinOneCellWithTheRightIndex) {
  const Grid grid = testing::latticeGrid(48, 48);
  const Case cases[] = {
      {"source",
       radialStrokes(true),
       1,
       {CriticalPointType::Source, CriticalPointType::SpiralSource}},
      {"sink", radialStrokes(false), 1, {CriticalPointType::Sink, CriticalPointType::SpiralSink}},
      {"centre", circles(), 1, {CriticalPointType::Centre}},
      {"saddle", saddleStrokes(), -1, {CriticalPointType::Saddle}},
  };
  for (const Case& c : cases) {
    const SketchedFlow f = sketchFlow(c.strokes, grid, SketchParams{});
    const std::vector<topology::CriticalPoint> points =
        topology::findCriticalPoints(f.velocity, topology::TopologyParams{});
    const topology::CriticalPoint* nearest = nullptr;
    for (const topology::CriticalPoint& p : points)
      if (!nearest || (p.position - kDrawnAt).norm() < (nearest->position - kDrawnAt).norm())
        nearest = &p;
    ASSERT_NE(nearest, nullptr) << c.name;
    EXPECT_EQ(points.size(), 1u) << c.name;
    const Vec3 offset = nearest->position - kDrawnAt;
    EXPECT_LE(std::max(std::abs(offset[0]), std::abs(offset[1])), 1.0) << c.name;
    EXPECT_TRUE(nearest->index_measured) << c.name;
    EXPECT_EQ(nearest->index, c.index) << c.name;
    EXPECT_NE(std::find(c.types.begin(), c.types.end(), nearest->type), c.types.end())
        << c.name << ": " << topology::toString(nearest->type);
    if (c.name == "source" || c.name == "sink") {
      EXPECT_LT(spiralRatio(*nearest), 0.1) << c.name;
      RecordProperty(c.name + "_spiral_ratio", formatNumber(spiralRatio(*nearest), 3));
    }
    RecordProperty(c.name + "_offset_cells", formatNumber(offset.norm(), 3));
    RecordProperty(c.name + "_points_found", std::to_string(points.size()));
  }
}

}  // namespace
}  // namespace fluidviz::sketch
