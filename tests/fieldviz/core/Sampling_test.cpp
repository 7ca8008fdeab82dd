#include "fieldviz/core/Sampling.h"

#include <gtest/gtest.h>

using namespace fluidviz;

namespace {
Grid grid2D(int nx, int ny, double h) {
  Grid g;
  g.dims = {nx, ny, 1};
  g.origin = {-1.0, 0.5, 0.0};
  g.spacing = {h, 2 * h, 1.0};
  return g;
}
}  // namespace

// Bilinear interpolation reproduces any bilinear function exactly (up to round-off).
TEST(Sampling, BilinearFunctionIsReproducedExactly) {
  Grid g = grid2D(7, 5, 0.25);
  auto f = [](const Vec3& p) { return 2.0 + 3.0 * p.x() - 0.5 * p.y() + 1.5 * p.x() * p.y(); };
  ScalarField s{"f", g, {}};
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 7; ++i) s.values.push_back(f(g.position(i, j)));
  for (Vec3 p : {Vec3(-0.9, 0.6, 0), Vec3(0.37, 1.9, 0), Vec3(0.5, 2.5, 0), Vec3(-1.0, 0.5, 0)}) {
    auto v = sample(s, p);
    ASSERT_TRUE(v.has_value());
    EXPECT_NEAR(*v, f(p), 1e-13);
  }
}

TEST(Sampling, TrilinearVectorFieldIsReproducedExactly) {
  Grid g;
  g.dims = {4, 3, 5};
  g.spacing = {0.5, 1.0, 0.25};
  VectorField v{"v", g, {}};
  auto f = [](const Vec3& p) { return Vec3(p.x() * p.y() * p.z(), 1.0 - p.z(), p.x() + 2 * p.y()); };
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) v.values.push_back(f(g.position(i, j, k)));
  const Vec3 p(1.13, 0.77, 0.61);
  auto s = sample(v, p);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR((*s - f(p)).norm(), 0.0, 1e-13);
}

TEST(Sampling, OutsideTheGridGivesNothing) {
  Grid g = grid2D(3, 3, 1.0);
  ScalarField s{"f", g, std::vector<double>(9, 1.0)};
  EXPECT_FALSE(sample(s, Vec3(-1.5, 1.0, 0)).has_value());
  EXPECT_FALSE(sample(s, Vec3(0.0, 0.5, 0.1)).has_value());  // off the plane of a 2D grid
  EXPECT_TRUE(sample(s, Vec3(1.0, 4.5, 0)).has_value());      // upper corner is inside
}

TEST(Grid, ValidateNamesTheBadMember) {
  Grid g = grid2D(3, 3, 1.0);
  g.spacing[1] = 0.0;
  try {
    g.validate();
    FAIL() << "zero spacing accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("spacing along y"), std::string::npos) << e.what();
  }
}
