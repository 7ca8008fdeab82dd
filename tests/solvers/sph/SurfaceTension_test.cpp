// Model A colour-field surface tension (Mueller et al. 2003): a square drop of side 0.2 m
// (20 x 20 particles, dx = 0.01 m, h = 1.5 dx) in zero gravity, sigma = 0.1 N (2D), nu = 1e-3
// m^2/s, c0 = 2 m/s, relaxes to a disc of the same area, R = 0.2 / sqrt(pi) = 0.1128 m, in 2 s:
//   - the rms distance of the particles from the centroid tends to that of a uniform disc,
//     R / sqrt(2) = 0.0798 m, within 1% (square: 0.0815 m; measured 0.0797 m);
//   - the outermost particle, at the corner distance 0.1344 m for the square, comes to the disc's
//     outer layer R - dx/2 = 0.1078 m within 3% (measured 0.1067 m).
// Control: with sigma = 0 the square keeps its corners (outermost particle still at 0.1344 m).
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include "tests/support/SphScenes.h"

namespace fluidviz::sph {
namespace {

struct Shape {
  double rms = 0.0, outermost = 0.0;
};

Shape relaxSquareDrop(double sigma) {
  SphParams p;
  p.model = fluidviz::sph::SphModel::muller2003;
  p.particle_spacing = 0.01;
  p.smoothing_length_ratio = 1.5;
  p.domain_lower = {0, 0, 0};
  p.domain_upper = {1, 1, 0};
  p.walls = {fluidviz::sph::SphSide::open, fluidviz::sph::SphSide::open, fluidviz::sph::SphSide::open, fluidviz::sph::SphSide::open, fluidviz::sph::SphSide::open, fluidviz::sph::SphSide::open};
  p.fluid_blocks = {{{0.4, 0.4, 0}, {0.6, 0.6, 0}}};
  p.gravity = {0, 0, 0};
  p.viscosity = 1e-3;
  p.speed_of_sound = 2;
  p.surface_tension = sigma;
  p.end_time = 2;
  SphSolver s(p);
  s.run();
  Vec3 c = Vec3::Zero();
  for (const Vec3& x : s.state().x) c += x;
  c /= static_cast<double>(s.fluidCount());
  Shape shape;
  for (const Vec3& x : s.state().x) {
    shape.rms += (x - c).squaredNorm();
    shape.outermost = std::max(shape.outermost, (x - c).norm());
  }
  shape.rms = std::sqrt(shape.rms / s.fluidCount());
  return shape;
}

TEST(SurfaceTensionMuller2003, SquareDropBecomesADisc) {
  const double R = 0.2 / std::sqrt(std::numbers::pi);
  const Shape drop = relaxSquareDrop(0.1);
  EXPECT_NEAR(drop.rms, R / std::sqrt(2.0), 0.01 * R / std::sqrt(2.0));
  EXPECT_NEAR(drop.outermost, R - 0.005, 0.03 * (R - 0.005));
  std::printf("[measured] rms radius %.4f m (disc %.4f), outermost %.4f m (disc %.4f)\n",
              drop.rms, R / std::sqrt(2.0), drop.outermost, R - 0.005);
  const Shape square = relaxSquareDrop(0.0);
  EXPECT_NEAR(square.outermost, std::hypot(0.095, 0.095), 1e-3);
}

}  // namespace
}  // namespace fluidviz::sph
