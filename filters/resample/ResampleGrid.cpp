#include "filters/resample/ResampleGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "fieldviz/core/ByteSize.h"
#include "fieldviz/particles/UniformGridNeighborSearch.h"

namespace fluidviz::resample {

namespace {

constexpr std::size_t kSpacingSamples = 4096;  // particles whose nearest neighbour is measured

// Squared distance from particle i to its nearest other particle, searching within `radius`
// and doubling it until one is found (at most up to `maxRadius`); infinity if none.
double nearestSquaredDistance(const particles::UniformGridNeighborSearch& search,
                              const std::vector<Vec3>& x, std::size_t i, double radius,
                              double maxRadius) {
  double best = std::numeric_limits<double>::infinity();
  for (; !std::isfinite(best) && radius <= maxRadius; radius *= 2.0)
    search.forEachWithin(x[i], radius, [&](int j, const Vec3&, double r2) {
      if (static_cast<std::size_t>(j) != i) best = std::min(best, r2);
    });
  return best;
}

std::string formatGridDims(const std::array<double, 3>& n, int dimension) {
  std::ostringstream s;
  s.precision(6);
  s << n[0] << " x " << n[1];
  if (dimension == 3) s << " x " << n[2];
  return s.str();
}

}  // namespace

Bounds boundsOf(const std::vector<Vec3>& positions) {
  if (positions.empty()) throw std::invalid_argument("there are no particles to resample");
  Bounds b{positions[0], positions[0]};
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = positions[i];
    if (!p.allFinite())
      throw std::invalid_argument("particle " + std::to_string(i) +
                                  " has a non-finite position (NaN or infinity)");
    b.lower = b.lower.cwiseMin(p);
    b.upper = b.upper.cwiseMax(p);
  }
  return b;
}

int chooseDimension(const ParticleResampleParams& params, const Bounds& bounds) {
  if (params.dimension != 0) return params.dimension;
  return bounds.upper.z() == bounds.lower.z() ? 2 : 3;
}

double medianNearestNeighbourDistance(const std::vector<Vec3>& x, int dimension,
                                      const Bounds& b) {
  const std::size_t n = x.size();
  if (n < 2)
    throw std::invalid_argument("cannot estimate the particle spacing from " + std::to_string(n) +
                                " particle; give particle_spacing");
  double measure = 1.0, longest = 0.0;
  for (int a = 0; a < dimension; ++a) {
    measure *= b.upper[a] - b.lower[a];
    longest = std::max(longest, b.upper[a] - b.lower[a]);
  }
  if (!(longest > 0))
    throw std::invalid_argument("all " + std::to_string(n) +
                                " particles sit at one position; give particle_spacing");
  // Start at twice the spacing the particles would have if they filled their bounding box evenly.
  const double start = measure > 0 ? 2.0 * std::pow(measure / n, 1.0 / dimension)
                                   : 2.0 * longest / static_cast<double>(n);
  const Vec3 pad = Vec3::Constant(start);
  particles::UniformGridNeighborSearch search(dimension, b.lower - pad, b.upper + pad, start);
  search.build(x);
  const std::size_t stride = std::max<std::size_t>(1, n / kSpacingSamples);
  std::vector<double> d2;
  for (std::size_t i = 0; i < n; i += stride)
    d2.push_back(nearestSquaredDistance(search, x, i, start, 4.0 * longest));
  auto mid = d2.begin() + static_cast<std::ptrdiff_t>(d2.size() / 2);
  std::nth_element(d2.begin(), mid, d2.end());
  if (!(*mid > 0))
    throw std::invalid_argument("most particles coincide with another one; give "
                                "particle_spacing");
  return std::sqrt(*mid);
}

Grid planGrid(const Bounds& bounds, int dimension, double padding, double particleSpacing,
              const ParticleResampleParams& params, double bytesPerNode) {
  const Vec3 lower = bounds.lower - Vec3::Constant(padding);
  const Vec3 upper = bounds.upper + Vec3::Constant(padding);
  double longest = 0.0;
  for (int a = 0; a < dimension; ++a) longest = std::max(longest, upper[a] - lower[a]);
  std::string key = "spacing";
  double d = particleSpacing;
  if (params.spacing) {
    d = *params.spacing;
  } else if (params.dims != 0) {
    if (params.dims < 2) throw ParamError("dims", "is 1; a grid needs at least 2 nodes per axis");
    if (!(longest > 0))
      throw ParamError("dims", "cannot set the spacing: the particles and padding have no extent; "
                               "give spacing");
    d = longest / (params.dims - 1);
    key = "dims";
  }
  std::array<double, 3> nodes{1.0, 1.0, 1.0};
  for (int a = 0; a < dimension; ++a) nodes[a] = std::ceil((upper[a] - lower[a]) / d - 1e-9) + 1.0;
  const double count = nodes[0] * nodes[1] * nodes[2];
  const double bytes = count * bytesPerNode;
  if (bytes > params.max_memory_mb * 1e6 || nodes[0] > 2e9 || nodes[1] > 2e9 || nodes[2] > 2e9) {
    std::ostringstream s;
    s.precision(4);
    if (key == "spacing" && !params.spacing) s << "(not given: the particle spacing) ";
    s << "gives a " << formatGridDims(nodes, dimension) << " grid (" << count
      << " nodes, node spacing " << d << " m) whose arrays would need " << formatBytes(bytes)
      << ", more than max_memory_mb = " << params.max_memory_mb
      << " MB; use a larger spacing (or fewer dims), or raise max_memory_mb";
    throw ParamError(key, s.str());
  }
  Grid g;
  for (int a = 0; a < 3; ++a) {
    g.dims[a] = static_cast<int>(nodes[a]);
    g.spacing[a] = d;
    g.origin[a] = 0.5 * (bounds.lower[a] + bounds.upper[a]) - 0.5 * (nodes[a] - 1.0) * d;
  }
  if (dimension == 2) g.origin[2] = bounds.lower.z();
  g.validate();
  return g;
}

}  // namespace fluidviz::resample
