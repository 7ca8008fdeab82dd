#include "fieldviz/core/PointMask.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fluidviz {

namespace {

// An empty mask masks nothing; any other has one entry per node of the field.
void requireMaskFits(const PointMask& mask, std::size_t nodes, const std::string& field) {
  if (!mask.empty() && mask.size() != nodes)
    throw std::invalid_argument("mask of " + std::to_string(mask.size()) + " nodes for field '" +
                                field + "' of " + std::to_string(nodes) + " nodes");
}

bool masked(const PointMask& m, std::size_t n) { return !m.empty() && m[n]; }

constexpr std::array<std::array<int, 2>, 4> kNeighbours{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};

// Flood fill of the 4-connected region of `slow` nodes around `seed`; returns its nodes.
std::vector<std::size_t> region(const Grid& g, const std::vector<std::uint8_t>& slow,
                                std::vector<std::uint8_t>& seen, std::size_t seed) {
  std::vector<std::size_t> nodes{seed}, stack{seed};
  seen[seed] = 1;
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    const int i = static_cast<int>(n % g.dims[0]), j = static_cast<int>(n / g.dims[0]);
    for (const auto& d : kNeighbours) {
      const int a = i + d[0], b = j + d[1];
      if (a < 0 || b < 0 || a >= g.dims[0] || b >= g.dims[1]) continue;
      const std::size_t m = g.index(a, b);
      if (!slow[m] || seen[m]) continue;
      seen[m] = 1;
      nodes.push_back(m);
      stack.push_back(m);
    }
  }
  return nodes;
}

}  // namespace

void require2DGrid(const Grid& g, const char* what) {
  if (!g.is2D()) throw std::invalid_argument(std::string(what) + " needs a 2D field, got " +
                                             g.describe());
}

double maxFiniteSpeed(const VectorField& v) {
  double vmax = 0.0;
  for (const Vec3& x : v.values)
    if (x.allFinite()) vmax = std::max(vmax, x.norm());
  return vmax;
}

CellCorners cellCornersAt(const Grid& g, const Vec3& p) {
  const Vec3 q = g.toIndexSpace(p);
  const int i = std::clamp(static_cast<int>(std::floor(q.x())), 0, std::max(g.dims[0] - 2, 0));
  const int j = std::clamp(static_cast<int>(std::floor(q.y())), 0, std::max(g.dims[1] - 2, 0));
  const int i1 = std::min(i + 1, g.dims[0] - 1), j1 = std::min(j + 1, g.dims[1] - 1);
  return {{g.index(i, j), g.index(i1, j), g.index(i, j1), g.index(i1, j1)},
          std::clamp(q.x() - i, 0.0, 1.0),
          std::clamp(q.y() - j, 0.0, 1.0)};
}

std::vector<std::uint8_t> validPointFlags(const PointMask& masked, std::size_t nodes) {
  if (!masked.empty() && masked.size() != nodes)
    throw std::invalid_argument("validPointFlags: the mask has " + std::to_string(masked.size()) +
                                " flags for " + std::to_string(nodes) + " nodes");
  std::vector<std::uint8_t> valid(nodes, 1);
  for (std::size_t n = 0; n < masked.size(); ++n) valid[n] = masked[n] ? 0 : 1;
  return valid;
}

void validateSolidParams(const SolidParams& p) {
  if (!(p.solid_speed >= 0.0 && p.solid_speed <= 0.01))
    throw std::invalid_argument("solid_speed is " + std::to_string(p.solid_speed) +
                                "; allowed [0, 0.01] (fraction of max|v|)");
  if (p.solid_min_nodes < 3 || p.solid_min_nodes > 1'000'000'000)
    throw std::invalid_argument("solid_min_nodes is " + std::to_string(p.solid_min_nodes) +
                                "; allowed [3, 1e9] nodes");
}

PointMask nonFiniteNodes(const VectorField& v) {
  PointMask m(v.values.size(), 0);
  for (std::size_t n = 0; n < m.size(); ++n) m[n] = !v.values[n].allFinite();
  return m;
}

PointMask solidNodes(const VectorField& v, const SolidParams& params) {
  validateSolidParams(params);
  require2DGrid(v.grid, "solidNodes");
  const double vmax = maxFiniteSpeed(v);
  // A field without any flow has no solid to tell from its fluid: nothing is masked.
  if (vmax == 0.0) return PointMask(v.values.size(), 0);
  const double limit = params.solid_speed * vmax;
  std::vector<std::uint8_t> slow(v.values.size(), 0), seen(v.values.size(), 0);
  for (std::size_t n = 0; n < slow.size(); ++n)
    slow[n] = v.values[n].allFinite() && v.values[n].norm() <= limit;
  PointMask solid(v.values.size(), 0);
  for (std::size_t n = 0; n < slow.size(); ++n) {
    if (!slow[n] || seen[n]) continue;
    const std::vector<std::size_t> nodes = region(v.grid, slow, seen, n);
    if (static_cast<int>(nodes.size()) < params.solid_min_nodes) continue;
    for (std::size_t m : nodes) solid[m] = 1;
  }
  return solid;
}

PointMask zeroNodes(const ScalarField& fluid) {
  PointMask m(fluid.values.size(), 0);
  for (std::size_t n = 0; n < m.size(); ++n)
    m[n] = !(std::isfinite(fluid.values[n]) && fluid.values[n] != 0.0);
  return m;
}

PointMask flowMask(const VectorField& velocity, const ScalarField* fluid) {
  PointMask mask;
  if (fluid) addMask(mask, zeroNodes(*fluid));
  addMask(mask, nonFiniteNodes(velocity));
  addMask(mask, solidNodes(velocity, SolidParams{}));
  if (maskedCount(mask) == 0) mask.clear();
  return mask;
}

void addMask(PointMask& into, const PointMask& other) {
  if (other.empty()) return;
  if (into.empty()) {
    into = other;
    return;
  }
  if (into.size() != other.size())
    throw std::invalid_argument("masks of " + std::to_string(into.size()) + " and " +
                                std::to_string(other.size()) + " nodes");
  for (std::size_t n = 0; n < into.size(); ++n) into[n] |= other[n];
}

std::size_t maskedCount(const PointMask& mask) {
  return static_cast<std::size_t>(std::count(mask.begin(), mask.end(), 1));
}

VectorField withMaskedValue(const VectorField& v, const PointMask& mask, const Vec3& value) {
  requireMaskFits(mask, v.values.size(), v.name);
  VectorField out = v;
  for (std::size_t n = 0; n < out.values.size(); ++n)
    if (masked(mask, n)) out.values[n] = value;
  return out;
}

VectorField withMaskedNaN(const VectorField& v, const PointMask& mask) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return withMaskedValue(v, mask, Vec3(nan, nan, nan));
}

ScalarField withMaskedNaN(const ScalarField& s, const PointMask& mask) {
  requireMaskFits(mask, s.values.size(), s.name);
  ScalarField out = s;
  for (std::size_t n = 0; n < out.values.size(); ++n)
    if (masked(mask, n)) out.values[n] = std::numeric_limits<double>::quiet_NaN();
  return out;
}

double maskFraction(const Grid& g, const PointMask& mask, const Vec3& p) {
  if (mask.empty()) return 0.0;
  const CellCorners c = cellCornersAt(g, p);
  const auto m = [&](int k) { return static_cast<double>(mask[c.nodes[k]]); };
  return (1 - c.s) * (1 - c.t) * m(0) + c.s * (1 - c.t) * m(1) + (1 - c.s) * c.t * m(2) +
         c.s * c.t * m(3);
}

VectorField withWallLayerContinued(const VectorField& v, const PointMask& mask) {
  require2DGrid(v.grid, "withWallLayerContinued");
  const Grid& g = v.grid;
  VectorField out = withMaskedNaN(v, mask);
  const auto fluidAt = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < g.dims[0] && j < g.dims[1] && !masked(mask, g.index(i, j)) &&
           v.values[g.index(i, j)].allFinite();
  };
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      if (!masked(mask, g.index(i, j))) continue;
      Vec3 sum = Vec3::Zero();
      int count = 0;
      for (const auto& d : kNeighbours) {
        const int a = i + d[0], b = j + d[1];
        if (!fluidAt(a, b)) continue;
        const Vec3& near = v.values[g.index(a, b)];
        sum += fluidAt(a + d[0], b + d[1]) ? Vec3(2 * near - v.values[g.index(a + d[0], b + d[1])])
                                           : near;
        ++count;
      }
      if (count > 0) out.values[g.index(i, j)] = sum / count;
    }
  return out;
}

bool cellTouchesFluid(const Grid& g, const PointMask& mask, const Vec3& p) {
  if (mask.empty()) return true;
  for (std::size_t n : cellCornersAt(g, p).nodes)
    if (!mask[n]) return true;
  return false;
}

}  // namespace fluidviz
