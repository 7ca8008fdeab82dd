#include "filters/resample/ParticleResampler.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "filters/resample/InterpolationKernel.h"
#include "filters/resample/LinearResample.h"
#include "filters/resample/ResampleGrid.h"
#include "filters/resample/ScatterToGrid.h"

namespace fluidviz::resample {

namespace {

constexpr double kDefaultHOverSpacing = 1.3;  // h / s when smoothing_length is not given

// A particle array to interpolate: 1 (scalar) or 3 (vector) components.
struct Channel {
  std::string name;
  int components = 1;
  const std::vector<double>* scalars = nullptr;
  const std::vector<Vec3>* vectors = nullptr;
};

// Volumes V_j of eq. (1): per particle (m_j / rho_j) or one uniform value.
struct Volumes {
  std::vector<double> perParticle;  // empty: uniform
  double uniform = 0.0;
  const std::vector<double>* mass = nullptr;  // for eq. (3); null without a mass array
  std::string source;
};

std::string listArrays(const particles::ParticleSet& ps) {
  std::string s;
  for (const auto& a : ps.scalars) s += (s.empty() ? "" : ", ") + a.name + "(1)";
  for (const auto& a : ps.vectors) s += (s.empty() ? "" : ", ") + a.name + "(3)";
  return s.empty() ? "none" : s;
}

template <class Array>
void requireSize(const Array& a, std::size_t n) {
  if (a.values.size() != n)
    throw std::invalid_argument("particle array '" + a.name + "' has " +
                                std::to_string(a.values.size()) + " values for " +
                                std::to_string(n) + " particles");
}

// A NaN or infinity would spread over every node within the particle's support.
bool isFiniteValue(double v) { return std::isfinite(v); }
bool isFiniteValue(const Vec3& v) { return v.allFinite(); }

template <class Array>
void requireFinite(const Array& a) {
  for (std::size_t i = 0; i < a.values.size(); ++i)
    if (!isFiniteValue(a.values[i]))
      throw std::invalid_argument("particle array '" + a.name + "' has a NaN or infinite value "
                                  "at particle " + std::to_string(i) + "; resampled arrays must "
                                  "be finite (leave it out with --arrays)");
}

std::vector<Channel> selectChannels(const particles::ParticleSet& ps, const std::string& list) {
  std::vector<std::string> names = splitArrayList(list);
  if (list.find_first_not_of(" \t,") == std::string::npos) {
    names.clear();
    for (const auto& a : ps.scalars) names.push_back(a.name);
    for (const auto& a : ps.vectors) names.push_back(a.name);
  }
  std::vector<Channel> channels;
  for (const std::string& name : names) {
    if (const auto* s = ps.findScalar(name)) {
      requireSize(*s, ps.size());
      requireFinite(*s);
      channels.push_back({name, 1, &s->values, nullptr});
    } else if (const auto* v = ps.findVector(name)) {
      requireSize(*v, ps.size());
      requireFinite(*v);
      channels.push_back({name, 3, nullptr, &v->values});
    } else {
      throw ParamError("arrays", "names '" + name + "', which the particles do not have; arrays "
                                 "present: " + listArrays(ps));
    }
    for (const char* reserved :
         {kColorArray, kMaskArray, kSummationDensityArray, kResampleOrderArray})
      if (name == reserved)
        throw ParamError("arrays", "particle array '" + name + "' has the name of an output "
                                   "array of the resampler; leave it out of arrays");
  }
  return channels;
}

const std::vector<double>* positiveArray(const particles::ParticleSet& ps, const std::string& name) {
  const auto* a = ps.findScalar(name);
  if (a == nullptr) return nullptr;
  requireSize(*a, ps.size());
  for (std::size_t i = 0; i < a->values.size(); ++i)
    if (!(a->values[i] > 0) || !std::isfinite(a->values[i]))
      throw std::invalid_argument("particle array '" + name + "' is " +
                                  std::to_string(a->values[i]) + " at particle " +
                                  std::to_string(i) + "; masses and densities must be > 0");
  return &a->values;
}

// V_j = m_j / rho_j when both arrays exist; otherwise uniform (given, or s^d later).
Volumes chooseVolumes(const particles::ParticleSet& ps, const ParticleResampleParams& p) {
  Volumes v;
  v.mass = positiveArray(ps, p.mass_array);
  const std::vector<double>* rho = positiveArray(ps, p.density_array);
  if (p.particle_volume) {
    v.uniform = *p.particle_volume;
    v.source = "uniform, given (particle_volume)";
  } else if (v.mass && rho) {
    v.perParticle.resize(ps.size());
    for (std::size_t i = 0; i < ps.size(); ++i) v.perParticle[i] = (*v.mass)[i] / (*rho)[i];
    v.source = "m/rho from arrays '" + p.mass_array + "' and '" + p.density_array + "'";
  } else {
    v.source = std::string("uniform s^d (assumed: the particles have no ") +
               (v.mass ? "" : "'" + p.mass_array + "'") + (!v.mass && !rho ? " and no " : "") +
               (rho ? "" : "'" + p.density_array + "'") + " array)";
  }
  return v;
}

double medianOf(std::vector<double> values) {
  auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

double chooseParticleSpacing(const particles::ParticleSet& ps, const ParticleResampleParams& p,
                             const Volumes& v, int dim, const Bounds& b, std::string& source) {
  if (p.particle_spacing) {
    source = "given (particle_spacing)";
    return *p.particle_spacing;
  }
  if (!v.perParticle.empty()) {
    source = "median (m/rho)^(1/d)";
    return std::pow(medianOf(v.perParticle), 1.0 / dim);
  }
  if (v.uniform > 0) {
    source = "particle_volume^(1/d)";
    return std::pow(v.uniform, 1.0 / dim);
  }
  source = "median nearest-neighbour distance";
  return medianNearestNeighbourDistance(ps.positions, dim, b);
}

// Cell keys (cells of edge `cell` from the bounds' lower corner, slow axis first: z in 3D, y in
// 2D) and the permutation that sorts the particles by them.
struct CellOrder {
  DefaultInitVector<std::uint64_t> key;
  std::vector<std::size_t> order;
  std::uint64_t cellsPerLayer = 1;
  std::int64_t slowCells = 1;
};

// The permutation that sorts `key` (values < cells), stable: a counting sort, O(n + cells), when
// there are not many more cells than keys, else a comparison sort.
std::vector<std::size_t> stableOrder(const DefaultInitVector<std::uint64_t>& key, std::uint64_t cells) {
  std::vector<std::size_t> order(key.size());
  if (cells > 4 * key.size() + 1024) {
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t d) { return key[a] < key[d]; });
    return order;
  }
  std::vector<std::size_t> start(cells + 1, 0);
  for (std::uint64_t k : key) ++start[k + 1];
  for (std::uint64_t c = 1; c <= cells; ++c) start[c] += start[c - 1];
  for (std::size_t i = 0; i < key.size(); ++i) order[start[key[i]]++] = i;
  return order;
}

CellOrder cellOrder(const std::vector<Vec3>& x, const Bounds& b, double cell, int dimension) {
  CellOrder c;
  std::array<std::uint64_t, 3> n{1, 1, 1};
  for (int a = 0; a < dimension; ++a)
    n[a] = static_cast<std::uint64_t>(std::floor((b.upper[a] - b.lower[a]) / cell)) + 1;
  c.cellsPerLayer = dimension == 3 ? n[0] * n[1] : n[0];
  c.slowCells = static_cast<std::int64_t>(n[dimension - 1]);
  const std::int64_t count = static_cast<std::int64_t>(x.size());
  DefaultInitVector<std::uint64_t> key(x.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < count; ++i) {
    std::array<std::uint64_t, 3> q{0, 0, 0};
    for (int a = 0; a < dimension; ++a)
      q[a] = std::min(n[a] - 1, static_cast<std::uint64_t>((x[i][a] - b.lower[a]) / cell));
    key[i] = (q[2] * n[1] + q[1]) * n[0] + q[0];
  }
  c.order = stableOrder(key, n[0] * n[1] * n[2]);
  c.key.resize(x.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < count; ++k) c.key[k] = key[c.order[k]];
  return c;
}

detail::SortedParticles sortParticles(const particles::ParticleSet& ps,
                                      const std::vector<Channel>& channels, const Volumes& v,
                                      CellOrder order, const Bounds& b, double cell,
                                      int dimension) {
  detail::SortedParticles s;
  s.order = std::move(order.order);
  s.x = ps.positions.data();
  s.volume = v.perParticle.empty() ? nullptr : v.perParticle.data();
  s.uniformVolume = v.uniform;
  s.mass = v.mass ? v.mass->data() : nullptr;
  for (const Channel& c : channels) {
    if (c.components == 1) {
      s.columns.push_back({c.scalars->data(), 1});
    } else {
      static_assert(sizeof(Vec3) == 3 * sizeof(double), "vector columns read with stride 3");
      const double* first = c.vectors->data()->data();
      for (int k = 0; k < 3; ++k) s.columns.push_back({first + k, 3});
    }
  }
  s.key = std::move(order.key);
  s.cellsPerLayer = order.cellsPerLayer;
  s.slowCells = order.slowCells;
  s.cell = cell;
  s.slowLower = b.lower[dimension - 1];
  return s;
}

// The output arrays, and where each slot of a node's results goes.
detail::OutputTargets allocateOutputs(FieldSet& fields, const std::vector<Channel>& channels,
                                      bool withDensity, bool withOrder) {
  const Grid& g = fields.grid;
  const std::size_t nodes = g.nodeCount();
  std::vector<Channel> arrays = channels;
  for (const char* name : {kColorArray, kMaskArray, kSummationDensityArray})
    if (name != kSummationDensityArray || withDensity) arrays.push_back({name, 1});
  if (withOrder) arrays.push_back({kResampleOrderArray, 1});
  // Allocated (and their pages first touched) by several threads at once: for large grids the
  // page faults of the allocation cost as much as the interpolation's serial parts.
  std::vector<ScalarField> scalars(arrays.size());
  std::vector<VectorField> vectors(arrays.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    if (arrays[i].components == 1)
      scalars[i] = ScalarField{arrays[i].name, g, std::vector<double>(nodes, 0.0)};
    else
      vectors[i] = VectorField{arrays[i].name, g, std::vector<Vec3>(nodes, Vec3::Zero())};
  }
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    if (arrays[i].components == 1)
      fields.add(std::move(scalars[i]));
    else
      fields.add(std::move(vectors[i]));
  }
  auto scalar = [&](const std::string& name) {
    return const_cast<ScalarField*>(fields.findScalar(name))->values.data();
  };
  detail::OutputTargets t;
  for (const Channel& c : channels) {
    if (c.components == 1) {
      t.base.push_back(scalar(c.name));
      t.stride.push_back(1);
    } else {
      double* v = const_cast<VectorField*>(fields.findVector(c.name))->values.data()->data();
      for (int k = 0; k < 3; ++k) t.base.push_back(v + k), t.stride.push_back(3);
    }
  }
  t.color = scalar(kColorArray);
  t.mask = scalar(kMaskArray);
  if (withDensity) t.density = scalar(kSummationDensityArray);
  return t;
}

// Output arrays (resampled, colour, mask, summation density, resample order); the node sums
// they are made from exist for one block of layers per thread only.
double bytesPerNode(const std::vector<Channel>& channels, bool withDensity, bool withOrder) {
  double resampled = 0.0;
  for (const Channel& c : channels) resampled += c.components;
  return (resampled + 2.0 + (withDensity ? 1.0 : 0.0) + (withOrder ? 1.0 : 0.0)) *
         sizeof(double);
}

std::size_t countSupported(const FieldSet& fields) {
  const auto& m = fields.findScalar(kMaskArray)->values;
  return static_cast<std::size_t>(std::count(m.begin(), m.end(), 1.0));
}

}  // namespace

std::string ResampleReport::summary() const {
  std::ostringstream s;
  s.precision(6);
  s << "particles: " << particles << " (" << dimension << "D)\n"
    << "kernel: " << kernel << ", h = " << smoothingLength << " m, support 2h = "
    << 2.0 * smoothingLength << " m\n"
    << "particle spacing s = " << particleSpacing << " m (" << spacingSource << ")\n"
    << "particle volume: " << volumeSource << "\n"
    << "grid: " << grid.describe() << "\n"
    << "arrays resampled:";
  for (const auto& a : resampledArrays) s << " " << a;
  s << (resampledArrays.empty() ? " none" : "") << "\n"
    << "nodes without particle support (mask = 0): " << unsupportedNodes << " of "
    << supportedNodes + unsupportedNodes << "\n";
  if (order == ResampleOrder::linear)
    s << "order: linear (first order) at " << firstOrderNodes << " of " << supportedNodes
      << " supported nodes, shepard at the others (array " << kResampleOrderArray << ")\n";
  return s.str();
}

namespace {

// The scatter compiled for three x86-64 levels; the widest the CPU runs is used (a node's
// update is one AVX-512 register with the padded stride 8).
template <class Kernel>
__attribute__((noinline)) void scatterBase(const Grid& g, int dimension, const Kernel& kernel,
                                           const detail::SortedParticles& sp, std::size_t first,
                                           std::size_t last, int layer0, int layer1,
                                           detail::BlockSums& sums) {
  detail::scatterParticles(g, dimension, kernel, sp, first, last, layer0, layer1, sums);
}
#if defined(FLUIDVIZ_MULTI_ISA)
template <class Kernel>
__attribute__((noinline, target("arch=x86-64-v3"))) void scatterV3(
    const Grid& g, int dimension, const Kernel& kernel, const detail::SortedParticles& sp,
    std::size_t first, std::size_t last, int layer0, int layer1, detail::BlockSums& sums) {
  detail::scatterParticles(g, dimension, kernel, sp, first, last, layer0, layer1, sums);
}
template <class Kernel>
__attribute__((noinline, target("arch=x86-64-v4"))) void scatterV4(
    const Grid& g, int dimension, const Kernel& kernel, const detail::SortedParticles& sp,
    std::size_t first, std::size_t last, int layer0, int layer1, detail::BlockSums& sums) {
  detail::scatterParticles(g, dimension, kernel, sp, first, last, layer0, layer1, sums);
}
#endif

template <class Kernel>
detail::ScatterFunction<Kernel> bestScatter() {
#if defined(FLUIDVIZ_MULTI_ISA)
  if (bestIsaLevel() == 4) return scatterV4<Kernel>;
  if (bestIsaLevel() == 3) return scatterV3<Kernel>;
#endif
  return scatterBase<Kernel>;
}

// Everything decided before any grid memory is allocated.
struct Plan {
  ResampleReport report;
  Bounds bounds;
  std::vector<Channel> channels;
  Volumes volumes;
  InterpolationKernel kernel;
};

// The uniform volume s^d when neither particle_volume nor mass and density are given.
void completeVolumes(Volumes& v, const ParticleResampleParams& p, double s, int dimension) {
  if (!v.perParticle.empty() || p.particle_volume) return;
  v.uniform = std::pow(s, dimension);
  std::ostringstream text;
  text << v.uniform << " m^" << dimension << ", " << v.source;
  v.source = text.str();
}

Plan planResample(const particles::ParticleSet& ps, const ParticleResampleParams& p,
                  const Bounds* gridBox) {
  validateResampleParams(p);
  const Bounds bounds = boundsOf(ps.positions);
  ResampleReport r;
  r.particles = ps.size();
  r.dimension = chooseDimension(p, bounds);
  r.kernel = choiceName(p.kernel);
  r.order = p.order;
  std::vector<Channel> channels = selectChannels(ps, p.arrays);
  Volumes volumes = chooseVolumes(ps, p);
  r.particleSpacing =
      chooseParticleSpacing(ps, p, volumes, r.dimension, bounds, r.spacingSource);
  completeVolumes(volumes, p, r.particleSpacing, r.dimension);
  r.volumeSource = volumes.source;
  r.smoothingLength = p.smoothing_length.value_or(kDefaultHOverSpacing * r.particleSpacing);
  InterpolationKernel kernel = makeInterpolationKernel(p.kernel, r.smoothingLength, r.dimension);
  const double nodeBytes =
      bytesPerNode(channels, volumes.mass != nullptr, p.order == ResampleOrder::linear);
  r.grid = planGrid(gridBox ? *gridBox : bounds, r.dimension, p.padding.value_or(supportRadius(kernel)),
                    r.particleSpacing, p, nodeBytes);
  r.fieldBytes = nodeBytes * static_cast<double>(r.grid.nodeCount());
  for (const Channel& c : channels) r.resampledArrays.push_back(c.name);
  return {std::move(r), bounds, std::move(channels), std::move(volumes), kernel};
}

}  // namespace

ResampleReport planResampling(const particles::ParticleSet& ps, const ParticleResampleParams& p,
                              const Bounds* gridBox) {
  return planResample(ps, p, gridBox).report;
}

std::optional<double> medianSmoothingLength(const particles::ParticleSet& particles) {
  const particles::ParticleScalars* h = particles.findScalar(kSmoothingLengthArray);
  if (!h || h->values.empty()) return std::nullopt;
  std::vector<double> values = h->values;
  auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

ResampleResult resampleParticles(const particles::ParticleSet& ps, const ParticleResampleParams& p) {
  return resampleParticles(ps, p, nullptr);
}

ResampleResult resampleParticles(const particles::ParticleSet& ps, const ParticleResampleParams& p,
                                 const Bounds* gridBox) {
  Plan plan = planResample(ps, p, gridBox);
  const Grid& grid = plan.report.grid;
  const int dim = plan.report.dimension;
  const double support = supportRadius(plan.kernel);
  const bool withMass = plan.volumes.mass != nullptr;
  const detail::SortedParticles sorted =
      sortParticles(ps, plan.channels, plan.volumes,
                    cellOrder(ps.positions, plan.bounds, support, dim), plan.bounds, support, dim);
  ResampleResult result;
  result.fields.grid = grid;
  const bool linear = p.order == ResampleOrder::linear;
  const detail::OutputTargets out = allocateOutputs(result.fields, plan.channels, withMass, linear);
  const double empty = p.empty_value.value_or(std::numeric_limits<double>::quiet_NaN());
  std::visit(
      [&](const auto& k) {
        using Kernel = std::decay_t<decltype(k)>;
        detail::resampleToGrid(grid, dim, k, sorted, withMass, p.support_threshold, empty, out,
                               bestScatter<Kernel>());
      },
      plan.kernel);
  if (linear) {
    double* order =
        const_cast<ScalarField*>(result.fields.findScalar(kResampleOrderArray))->values.data();
    correctToFirstOrder(grid, dim, plan.kernel, sorted, out, order);
    plan.report.firstOrderNodes = static_cast<std::size_t>(
        std::count(order, order + grid.nodeCount(), 1.0));
  }
  plan.report.supportedNodes = countSupported(result.fields);
  plan.report.unsupportedNodes = grid.nodeCount() - plan.report.supportedNodes;
  result.report = std::move(plan.report);
  return result;
}

}  // namespace fluidviz::resample
