#pragma once
// Scenes shared by the SPH validation tests and benches, with the resolutions they use.
#include <algorithm>
#include <cmath>

#include "solvers/sph/SphSolver.h"

namespace fluidviz::sph::test {

constexpr double kGravity = 9.81;  // m/s^2

/// 2D tank [0, W] x [0, 2H], water [0, W] x [0, H], open top, model B, c0 = 10 sqrt(2 g H).
inline SphParams hydrostaticTank2D(double W, double H, int layers) {
  SphParams p;
  p.dimension = 2;
  p.model = fluidviz::sph::SphModel::weakly_compressible;
  p.particle_spacing = H / layers;
  p.domain_lower = {0, 0, 0};
  p.domain_upper = {W, 2 * H, 0};
  p.walls.y_max = fluidviz::sph::SphSide::open;
  p.fluid_blocks = {{{0, 0, 0}, {W, H, 0}}};
  p.gravity = {0, -kGravity, 0};
  p.speed_of_sound = 10 * std::sqrt(2 * kGravity * H);
  p.end_time = 100;
  return p;
}

/// Martin & Moyce dam break: column a wide, 2a high, at the left of a tank 4a long and 3a high
/// (open top), c0 = 10 sqrt(2 g a) (10x the shallow-water speed of the column).
inline SphParams damBreak2D(const std::string& model, double a, int particlesAcross) {
  SphParams p;
  p.dimension = 2;
  p.model = fluidviz::choiceNamed<fluidviz::sph::SphModel>(model);
  p.particle_spacing = a / particlesAcross;
  p.domain_lower = {0, 0, 0};
  p.domain_upper = {4 * a, 3 * a, 0};
  p.walls.y_max = fluidviz::sph::SphSide::open;
  p.fluid_blocks = {{{0, 0, 0}, {a, 2 * a, 0}}};
  p.gravity = {0, -kGravity, 0};
  p.speed_of_sound = 10 * std::sqrt(2 * kGravity * a);
  p.end_time = 100;
  return p;
}

/// Largest |x| of any value in the fluid's arrays (NaN-safe: returns +inf on NaN).
inline double largestMagnitude(const particles::ParticleSet& s) {
  double m = 0.0;
  auto take = [&](double v) { m = std::isfinite(v) ? std::max(m, std::abs(v)) : INFINITY; };
  for (const Vec3& x : s.positions)
    for (int a = 0; a < 3; ++a) take(x[a]);
  for (const auto& v : s.vectors)
    for (const Vec3& x : v.values)
      for (int a = 0; a < 3; ++a) take(x[a]);
  for (const auto& sc : s.scalars)
    for (double x : sc.values) take(x);
  return m;
}

}  // namespace fluidviz::sph::test
