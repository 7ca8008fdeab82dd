// Slices of an analytic field linear in x, y, z: trilinear sampling reproduces it exactly, so
// every slice's 2D values are known in closed form (tolerance: rounding, 1e-12).
#include "fieldviz/core/FieldSlices.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fieldviz/core/PointMask.h"

using namespace fluidviz;

namespace {

constexpr double kTol = 1e-12;

Vec3 linear(const Vec3& p) {
  return {1 + 2 * p.x() + 3 * p.y() + 4 * p.z(), 5 - p.x() + 2 * p.y() - p.z(),
          0.5 * p.x() + p.y() + 2 * p.z()};
}

VectorField linearField() {
  VectorField f{"v", {}, {}};
  f.grid.dims = {5, 4, 6};
  f.grid.origin = {-1.0, 0.5, 2.0};
  f.grid.spacing = {0.5, 0.25, 0.4};
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i) f.values.push_back(linear(f.grid.position(i, j, k)));
  return f;
}

}  // namespace

TEST(FieldSlices, IndexSliceNormalToXHasAxesYZAndComponentsVyVzVx) {
  const VectorField f = linearField();
  const VectorField s = sliceAxis(f, 0, 3);
  ASSERT_EQ(s.grid.dims, (std::array<int, 3>{4, 6, 1}));
  EXPECT_DOUBLE_EQ(s.grid.origin[0], 0.5);
  EXPECT_DOUBLE_EQ(s.grid.origin[1], 2.0);
  EXPECT_DOUBLE_EQ(s.grid.origin[2], 0.5);  // x of layer 3
  for (int t = 0; t < 6; ++t)
    for (int u = 0; u < 4; ++u) {
      const Vec3 v = linear({0.5, 0.5 + 0.25 * u, 2.0 + 0.4 * t});
      EXPECT_NEAR((s.values[s.grid.index(u, t)] - Vec3(v.y(), v.z(), v.x())).norm(), 0, kTol);
    }
  EXPECT_THROW(sliceAxis(f, 1, 4), std::invalid_argument);
}

TEST(FieldSlices, CoordinateSliceInterpolatesBetweenLayers) {
  const VectorField f = linearField();
  const VectorField s = sliceAt(f, 2, 2.5);  // between layers 1 (2.4) and 2 (2.8)
  ASSERT_EQ(s.grid.dims, (std::array<int, 3>{5, 4, 1}));
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i)
      EXPECT_NEAR((s.values[s.grid.index(i, j)] -
                   linear({-1.0 + 0.5 * i, 0.5 + 0.25 * j, 2.5})).norm(), 0, kTol);
  EXPECT_THROW(sliceAt(f, 2, 4.1), std::invalid_argument);  // z extent [2, 4]
}

TEST(FieldSlices, PlaneSliceProjectsOntoItsAxesAndMasksNodesOutside) {
  const VectorField f = linearField();
  const SlicePlane plane = slicePlane({0.0, 1.0, 3.0}, {1.0, 1.0, 1.0});
  EXPECT_NEAR(plane.e1.dot(plane.normal), 0, kTol);
  EXPECT_NEAR(plane.e2.dot(plane.e1), 0, kTol);
  const PlaneSlice s = sliceOnPlane(f, plane);
  const Grid& g = s.velocity.grid;
  EXPECT_DOUBLE_EQ(g.spacing[0], 0.25);  // the smallest spacing
  int inside = 0;
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      const std::size_t n = g.index(i, j);
      const Vec3 p = plane.origin + g.position(i, j).x() * plane.e1 + g.position(i, j).y() * plane.e2;
      const Vec3 lo = f.grid.position(0, 0, 0), hi = f.grid.upperCorner();
      const bool in = (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
      ASSERT_EQ(s.outside[n], in ? 0 : 1) << i << ", " << j;
      if (!in) continue;
      ++inside;
      const Vec3 v = linear(p);
      const Vec3 expected(v.dot(plane.e1), v.dot(plane.e2), v.dot(plane.normal));
      EXPECT_NEAR((s.velocity.values[n] - expected).norm(), 0, 1e-11);
    }
  EXPECT_GT(inside, 20);
  EXPECT_THROW(sliceOnPlane(f, slicePlane({0, 0, 10}, {0, 0, 1})), std::invalid_argument);
}

TEST(FieldSlices, CropKeepsTheNodesInsideTheBox) {
  const VectorField s = sliceAxis(linearField(), 2, 0);  // x in [-1, 1], y in [0.5, 1.25]
  const NodeBox b = cropBox(s.grid, {-0.6, 0.5, 0.7, 1.25});
  EXPECT_EQ(b.lo, (std::array<int, 2>{1, 1}));
  EXPECT_EQ(b.hi, (std::array<int, 2>{3, 3}));
  const VectorField c = crop(s, b);
  EXPECT_DOUBLE_EQ(c.grid.origin[0], -0.5);
  EXPECT_DOUBLE_EQ(c.grid.origin[1], 0.75);
  EXPECT_NEAR((c.values[c.grid.index(2, 2)] - linear({0.5, 1.25, 2.0})).norm(), 0, kTol);
  EXPECT_THROW(cropBox(s.grid, {0.5, 0.4, 0.5, 1.0}), std::invalid_argument);   // empty
  EXPECT_THROW(cropBox(s.grid, {-2.0, 0.0, 0.5, 1.0}), std::invalid_argument);  // outside
}

TEST(PointMask, SolidIsAZeroRegionOfAtLeastTheMinimumSizeNotAStagnationNode) {
  VectorField v{"v", {}, {}};
  v.grid.dims = {10, 10, 1};
  v.values.assign(100, Vec3(1, 0, 0));
  v.values[v.grid.index(1, 1)] = Vec3::Zero();  // a stagnation node
  for (int j = 5; j < 8; ++j)
    for (int i = 5; i < 8; ++i) v.values[v.grid.index(i, j)] = Vec3::Zero();  // a 3 x 3 body
  const PointMask m = solidNodes(v, SolidParams{});
  EXPECT_EQ(maskedCount(m), 9u);
  EXPECT_EQ(m[v.grid.index(1, 1)], 0);
  EXPECT_EQ(m[v.grid.index(6, 6)], 1);
  // The wall layer is continued from the fluid (here uniform: (1, 0, 0)), the interior is NaN.
  const VectorField t = withWallLayerContinued(v, m);
  EXPECT_NEAR((t.values[v.grid.index(5, 6)] - Vec3(1, 0, 0)).norm(), 0, kTol);
  EXPECT_TRUE(std::isnan(t.values[v.grid.index(6, 6)].x()));
  EXPECT_THROW(validateSolidParams({0.02, 9}), std::invalid_argument);
}
