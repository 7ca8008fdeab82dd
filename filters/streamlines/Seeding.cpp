#include "filters/streamlines/Seeding.h"

#include <cmath>
#include <stdexcept>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz::streamlines {

namespace {
Vec3 toVec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

// Fraction i / (n - 1) of an edge, 1/2 for a single seed (as seedLine).
double edgeFraction(int i, int n) { return n == 1 ? 0.5 : double(i) / (n - 1); }

// The counts of a key as ints, each a whole number.
template <std::size_t N>
std::array<int, N> wholeCounts(const std::array<double, N>& counts, const std::string& key) {
  std::array<int, N> n{};
  for (std::size_t a = 0; a < N; ++a) {
    n[a] = static_cast<int>(counts[a]);
    if (n[a] != counts[a])
      throw ParamError(key + "[" + std::to_string(a) + "]", "must be a whole number");
  }
  return n;
}

// A box as a plane lattice stacked along z: nx * ny * nz seeds, x fastest.
std::vector<Vec3> seedBox(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& n) {
  const Vec3 d = hi - lo;
  std::vector<Vec3> seeds;
  for (int k = 0; k < n[2]; ++k) {
    const Vec3 origin = lo + Vec3(0, 0, d.z() * edgeFraction(k, n[2]));
    const auto layer = seedPlane(origin, {d.x(), 0, 0}, {0, d.y(), 0}, n[0], n[1]);
    seeds.insert(seeds.end(), layer.begin(), layer.end());
  }
  return seeds;
}
}  // namespace

std::vector<Vec3> seedLine(const Vec3& a, const Vec3& b, int n) {
  if (n < 1) throw std::invalid_argument("seedLine: count is " + std::to_string(n) + ", must be >= 1");
  if (n == 1) return {0.5 * (a + b)};
  std::vector<Vec3> seeds;
  for (int i = 0; i < n; ++i) seeds.push_back(a + (b - a) * (double(i) / (n - 1)));
  return seeds;
}

std::vector<Vec3> seedPlane(const Vec3& origin, const Vec3& u, const Vec3& v, int nu, int nv) {
  if (nu < 1 || nv < 1)
    throw std::invalid_argument("seedPlane: counts must be >= 1, got " + std::to_string(nu) +
                                " x " + std::to_string(nv));
  std::vector<Vec3> seeds;
  seeds.reserve(static_cast<std::size_t>(nu) * nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      seeds.push_back(origin + u * edgeFraction(i, nu) + v * edgeFraction(j, nv));
  return seeds;
}

std::vector<Vec3> seedGrid(const Grid& grid, int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1)
    throw std::invalid_argument("seedGrid: counts must be >= 1, got " + std::to_string(nx) + " x " +
                                std::to_string(ny) + " x " + std::to_string(nz));
  if (grid.is2D() && nz != 1)
    throw std::invalid_argument("seedGrid: a 2D grid takes 1 seed along z, got " +
                                std::to_string(nz));
  const Vec3 lo = grid.position(0, 0, 0), hi = grid.upperCorner();
  const int n[3] = {nx, ny, nz};
  std::vector<Vec3> seeds;
  seeds.reserve(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int c[3] = {i, j, k};
        Vec3 p;
        for (int a = 0; a < 3; ++a) p[a] = lo[a] + (hi[a] - lo[a]) * (c[a] + 0.5) / n[a];
        seeds.push_back(p);
      }
  return seeds;
}

std::vector<Vec3> generateSeeds(const Grid& grid, const SeedingParams& s) {
  params::checkRanges(s);
  if (s.strategy == SeedStrategy::points) {
    if (s.points.empty()) throw ParamError("points", "strategy points needs at least one seed");
    std::vector<Vec3> seeds;
    for (const auto& p : s.points) {
      Vec3 q = toVec(p.position);
      if (grid.is2D()) q.z() = grid.origin[2];
      seeds.push_back(q);
    }
    return seeds;
  }
  if (s.strategy == SeedStrategy::line) return seedLine(toVec(s.line_start), toVec(s.line_end), s.line_count);
  if (s.strategy == SeedStrategy::plane) {
    const auto n = wholeCounts(s.plane_counts, "plane_counts");
    return seedPlane(toVec(s.plane_origin), toVec(s.plane_u), toVec(s.plane_v), n[0], n[1]);
  }
  if (s.strategy == SeedStrategy::box)
    return seedBox(toVec(s.box_min), toVec(s.box_max), wholeCounts(s.box_counts, "box_counts"));
  if (s.strategy == SeedStrategy::grid) {
    const auto n = wholeCounts(s.grid_counts, "grid_counts");
    if (grid.is2D() && n[2] != 1)
      throw ParamError("grid_counts[2]", "must be 1 for a 2D field, got " + std::to_string(n[2]));
    return seedGrid(grid, n[0], n[1], n[2]);
  }
  throw ParamError("strategy", "\"" + choiceName(s.strategy) + "\" does not produce seed points");
}

std::vector<Streamline> traceSeeded(const VectorField& field, const SeedingParams& seeding,
                                    const StreamlineParams& integration) {
  if (seeding.strategy == SeedStrategy::evenly_spaced)
    return evenlySpacedStreamlines(field, seeding.evenly_spaced, integration);
  return traceStreamlines(field, generateSeeds(field.grid, seeding), integration);
}

}  // namespace fluidviz::streamlines
