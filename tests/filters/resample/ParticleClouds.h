#pragma once
// Particle sets for resampling tests: jittered lattices in a box or a ball, with analytic arrays.
#include <cstdint>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>

#include "fieldviz/particles/ParticleSet.h"

namespace fluidviz::testing {

/// Lattice of spacing dx filling [lo, hi]^d (nodes at lo + (i + 1/2) dx), each particle moved by
/// a uniform random offset in [-jitter, jitter] dx per axis (seeded: the same set every run).
inline particles::ParticleSet jitteredBox(int dimension, double lo, double hi, double dx, double jitter,
                                    std::uint32_t seed = 7) {
  particles::ParticleSet ps;
  ps.dimension = dimension;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * dx, jitter * dx);
  const int n = static_cast<int>((hi - lo) / dx + 0.5);
  const int nz = dimension == 3 ? n : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Vec3 p(lo + (i + 0.5) * dx, lo + (j + 0.5) * dx, dimension == 3 ? lo + (k + 0.5) * dx : 0);
        p.x() += u(rng), p.y() += u(rng);
        if (dimension == 3) p.z() += u(rng);
        ps.positions.push_back(p);
      }
  return ps;
}

/// Cubic lattice of spacing dx (one node at the centre) restricted to |x - centre| < radius.
inline particles::ParticleSet latticeBall(const Vec3& centre, double radius, double dx) {
  particles::ParticleSet ps;
  ps.dimension = 3;
  const int n = static_cast<int>(radius / dx) + 1;
  for (int k = -n; k <= n; ++k)
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) {
        const Vec3 d(i * dx, j * dx, k * dx);
        if (d.norm() < radius) ps.positions.push_back(centre + d);
      }
  return ps;
}

/// A ball of radius n dx built from n concentric shells at radii (k + 1/2) dx, k = 0..n-1, each
/// with round(4 pi r_k^2 / dx^2) points on a Fibonacci spiral (a different rotation per shell), so
/// that every particle stands for a volume ~dx^3 and the outer layer is a smooth sphere
/// dx/2 inside the ball's surface (as in a relaxed SPH fluid). Carries "mass" = rho0 dx^3 and
/// "density" = rho0 (rho0 = 1000 kg/m^3), like SPH output files.
inline particles::ParticleSet shellBall(const Vec3& centre, int n, double dx) {
  particles::ParticleSet ps;
  ps.dimension = 3;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double r = (k + 0.5) * dx;
    const int count = std::max(1, static_cast<int>(std::lround(4.0 * std::numbers::pi * r * r / (dx * dx))));
    const double twist = 0.7 * k;  // rotate each shell about z
    for (int i = 0; i < count; ++i) {
      const double z = count == 1 ? 0.0 : 1.0 - 2.0 * (i + 0.5) / count;
      const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = golden * i + twist;
      ps.positions.push_back(centre + r * Vec3(rho * std::cos(phi), rho * std::sin(phi), z));
    }
  }
  const double rho0 = 1000.0;
  ps.scalars.push_back({"mass", std::vector<double>(ps.size(), rho0 * dx * dx * dx)});
  ps.scalars.push_back({"density", std::vector<double>(ps.size(), rho0)});
  return ps;
}

/// Adds a scalar array f(x_j) to the set.
inline void addScalar(particles::ParticleSet& ps, const std::string& name,
                      const std::function<double(const Vec3&)>& f) {
  particles::ParticleScalars s{name, {}};
  for (const Vec3& p : ps.positions) s.values.push_back(f(p));
  ps.scalars.push_back(std::move(s));
}

}  // namespace fluidviz::testing
