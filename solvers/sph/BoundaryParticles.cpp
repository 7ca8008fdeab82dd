#include "solvers/sph/BoundaryParticles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fluidviz::sph {

namespace {

// One coordinate of the wall lattice and whether it lies outside the domain.
struct AxisCoord {
  double x;
  bool outside;
};

// Lattice coordinates along one axis: wall layers below, the interior, wall layers above.
std::vector<AxisCoord> axisCoords(double lo, double hi, double dx, bool wallLo, bool wallHi,
                                  int layers) {
  std::vector<AxisCoord> c;
  if (wallLo)
    for (int k = layers - 1; k >= 0; --k) c.push_back({lo - (k + 0.5) * dx, true});
  const int n = static_cast<int>(std::floor((hi - lo) / dx + 1e-9));
  for (int i = 0; i < n; ++i) c.push_back({lo + (i + 0.5) * dx, false});
  if (wallHi)
    for (int k = 0; k < layers; ++k) c.push_back({hi + (k + 0.5) * dx, true});
  return c;
}

double outsideDistance(const Vec3& x, const Vec3& lo, const Vec3& hi, int dim) {
  double s = 0.0;
  for (int a = 0; a < dim; ++a) {
    const double e = std::max({lo[a] - x[a], x[a] - hi[a], 0.0});
    s += e * e;
  }
  return std::sqrt(s);
}

double insideDepth(const Vec3& x, const Vec3& lo, const Vec3& hi, int dim) {
  double d = std::numeric_limits<double>::infinity();
  for (int a = 0; a < dim; ++a) d = std::min({d, x[a] - lo[a], hi[a] - x[a]});
  return d;
}

void add(BoundaryParticles& b, const Vec3& x, int surface, double depth) {
  b.positions.push_back(x);
  b.restPositions.push_back(x);
  b.velocities.push_back(b.surfaces[surface].velocityAt(x));
  b.surface.push_back(surface);
  b.depth.push_back(depth);
}

void addDomainWalls(const SphParams& p, int layers, BoundaryParticles& b) {
  const int dim = p.dimension;
  BoundarySurface s;
  s.kind = BoundarySurface::Kind::DomainWalls;
  s.dimension = dim;
  s.lower = sceneVector(p.domain_lower, dim);
  s.upper = sceneVector(p.domain_upper, dim);
  bool any = false;
  for (int side = 0; side < 2 * dim; ++side)
    any |= (s.wallSide[side] = sideType(p.walls, side) == SphSide::wall);
  if (!any) return;
  b.surfaces.push_back(s);
  const int id = static_cast<int>(b.surfaces.size()) - 1;
  std::array<std::vector<AxisCoord>, 3> c;
  for (int a = 0; a < 3; ++a)
    c[a] = a < dim ? axisCoords(s.lower[a], s.upper[a], p.particle_spacing, s.wallSide[2 * a],
                                s.wallSide[2 * a + 1], layers)
                   : std::vector<AxisCoord>{{0.0, false}};
  for (const AxisCoord& z : c[2])
    for (const AxisCoord& y : c[1])
      for (const AxisCoord& x : c[0])
        if (x.outside || y.outside || z.outside) {
          const Vec3 q(x.x, y.x, z.x);
          add(b, q, id, outsideDistance(q, s.lower, s.upper, dim));
        }
}

void addObstacle(const SphParams& p, const SphBoxParams& box, int layers, BoundaryParticles& b) {
  const int dim = p.dimension;
  const double dx = p.particle_spacing;
  BoundarySurface s;
  s.kind = BoundarySurface::Kind::Box;
  s.dimension = dim;
  s.lower = sceneVector(box.lower, dim);
  s.upper = sceneVector(box.upper, dim);
  b.surfaces.push_back(s);
  const int id = static_cast<int>(b.surfaces.size()) - 1;
  std::array<int, 3> n{1, 1, 1};
  for (int a = 0; a < dim; ++a)
    n[a] = std::max(1, static_cast<int>(std::floor((s.upper[a] - s.lower[a]) / dx + 1e-9)));
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        Vec3 q = s.lower + dx * Vec3(i + 0.5, j + 0.5, k + 0.5);
        if (dim == 2) q[2] = 0.0;
        const double depth = insideDepth(q, s.lower, s.upper, dim);
        if (depth <= layers * dx) add(b, q, id, depth);  // a shell is enough
      }
}

void addRoller(const SphParams& p, const SphRollerParams& r, int layers, BoundaryParticles& b) {
  const int dim = p.dimension;
  const double dx = p.particle_spacing;
  BoundarySurface s;
  s.kind = BoundarySurface::Kind::Roller;
  s.dimension = dim;
  s.center = Vec3(r.center[0], r.center[1], 0.0);
  s.radius = r.radius;
  s.angularVelocity = r.angular_velocity;
  b.surfaces.push_back(s);
  const int id = static_cast<int>(b.surfaces.size()) - 1;
  std::vector<double> zs{0.0};
  if (dim == 3) {  // the cylinder spans the domain along z
    zs.clear();
    const int nz = static_cast<int>(std::floor((p.domain_upper[2] - p.domain_lower[2]) / dx + 1e-9));
    for (int k = 0; k < nz; ++k) zs.push_back(p.domain_lower[2] + (k + 0.5) * dx);
  }
  for (int k = 0; k < layers; ++k) {
    const double rk = r.radius - (k + 0.5) * dx;
    if (rk <= 0.0) break;
    const int n = std::max(1, static_cast<int>(std::lround(2.0 * std::numbers::pi * rk / dx)));
    const double shift = (k % 2) * 0.5;  // stagger the rings
    for (double z : zs)
      for (int m = 0; m < n; ++m) {
        const double t = 2.0 * std::numbers::pi * (m + shift) / n;
        add(b, Vec3(s.center[0] + rk * std::cos(t), s.center[1] + rk * std::sin(t), z), id,
            (k + 0.5) * dx);
      }
  }
}

}  // namespace

Vec3 sceneVector(const std::array<double, 3>& a, int dimension) {
  return {a[0], a[1], dimension == 3 ? a[2] : 0.0};
}

double BoundarySurface::fluidDistance(const Vec3& x) const {
  switch (kind) {
    case Kind::DomainWalls: {
      double d = std::numeric_limits<double>::infinity();
      for (int a = 0; a < dimension; ++a) {
        if (wallSide[2 * a]) d = std::min(d, x[a] - lower[a]);
        if (wallSide[2 * a + 1]) d = std::min(d, upper[a] - x[a]);
      }
      return d;
    }
    case Kind::Box: {
      const double out = outsideDistance(x, lower, upper, dimension);
      return out > 0.0 ? out : -insideDepth(x, lower, upper, dimension);
    }
    case Kind::Roller:
      return std::hypot(x[0] - center[0], x[1] - center[1]) - radius;
  }
  return 0.0;
}

void BoundaryParticles::moveTo(double t) {
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const BoundarySurface& s = surfaces[surface[k]];
    if (s.kind != BoundarySurface::Kind::Roller || s.angularVelocity == 0.0) continue;
    const double c = std::cos(s.angularVelocity * t), sn = std::sin(s.angularVelocity * t);
    const Vec3 r = restPositions[k] - s.center;
    positions[k] = s.center + Vec3(c * r[0] - sn * r[1], sn * r[0] + c * r[1], 0.0);
    positions[k][2] = restPositions[k][2];
    velocities[k] = s.velocityAt(positions[k]);
  }
}

BoundaryParticles makeBoundaryParticles(const SphParams& p, int layers) {
  BoundaryParticles b;
  addDomainWalls(p, layers, b);
  for (const SphBoxParams& box : p.obstacles) addObstacle(p, box, layers, b);
  for (const SphRollerParams& r : p.rollers) addRoller(p, r, layers, b);
  return b;
}

std::vector<Vec3> makeFluidParticles(const SphParams& p, const BoundaryParticles& solids) {
  const int dim = p.dimension;
  const double dx = p.particle_spacing;
  std::vector<Vec3> x;
  for (const SphBoxParams& block : p.fluid_blocks) {
    const Vec3 lo = sceneVector(block.lower, dim), hi = sceneVector(block.upper, dim);
    std::array<int, 3> n{1, 1, 1};
    for (int a = 0; a < dim; ++a)
      n[a] = std::max(1, static_cast<int>(std::floor((hi[a] - lo[a]) / dx + 1e-9)));
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          Vec3 q = lo + dx * Vec3(i + 0.5, j + 0.5, k + 0.5);
          if (dim == 2) q[2] = 0.0;
          bool free = true;
          for (const BoundarySurface& s : solids.surfaces)
            if (s.kind != BoundarySurface::Kind::DomainWalls && s.fluidDistance(q) < 0.5 * dx)
              free = false;
          if (free) x.push_back(q);
        }
  }
  return x;
}

}  // namespace fluidviz::sph
