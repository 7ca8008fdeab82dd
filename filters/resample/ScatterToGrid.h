#pragma once
// Internal to ParticleResampler.cpp: the sums of eqs. (1)-(3) (ParticleResampler.h) evaluated by
// scattering. Every particle adds V_j W, V_j W A_j and m_j W to the grid nodes inside its kernel
// support; those nodes form a box found by index arithmetic, so the grid itself is the neighbour
// search and no distance is computed for a node that is not within one box of the particle.
//
// Parallel and deterministic: the grid is cut into blocks of kLayersPerBlock node layers along
// its slowest axis (z in 3D, y in 2D). One thread owns a block: it adds the particles that reach
// it, in their sorted order, into its own block of sums and then writes the block's outputs.
// Every node sums the same terms in the same order whatever the thread count, and no two threads
// write the same node.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "fieldviz/core/DefaultInitVector.h"
#include "fieldviz/core/Grid.h"
#include "fieldviz/core/IsaLevel.h"

namespace fluidviz::resample::detail {

inline constexpr int kLayersPerBlock = 8;  // node layers per block of the slowest axis
inline constexpr int kChunk = 8;  // nodes of a support row evaluated at once

/// Particles ordered by the cell (edge `cell`) they sit in, slow axis first: the order and
/// where their positions, volumes, masses and the values to interpolate (one column per
/// component) are. Read in place through the order (a sorted copy would cost
/// more to write, page by page, than the scatter saves by reading it in sequence).
struct SortedParticles {
  struct Column {
    const double* data;  ///< component of particle i at data[i * stride]
    int stride;
  };
  std::vector<std::size_t> order;  // particle index of each sorted slot
  const Vec3* x = nullptr;
  const double* volume = nullptr;  // per particle; null: uniformVolume
  double uniformVolume = 0.0;
  const double* mass = nullptr;  // null without masses
  std::vector<Column> columns;
  DefaultInitVector<std::uint64_t> key;  // ascending cell keys; key / cellsPerLayer = slow-axis cell
  std::uint64_t cellsPerLayer = 1;
  double cell = 1.0;       // m
  double slowLower = 0.0;  // m, slow-axis coordinate of the first cell layer
  std::int64_t slowCells = 1;

  /// Index range [first, last) of the particles whose slow-axis cell overlaps [lo, hi] (m).
  std::pair<std::size_t, std::size_t> rangeOverlapping(double lo, double hi) const {
    auto layer = [&](double v) {
      const double c = std::floor((v - slowLower) / cell);
      return static_cast<std::uint64_t>(std::clamp<double>(c, 0.0, slowCells - 1.0));
    };
    const auto first = std::lower_bound(key.begin(), key.end(), layer(lo) * cellsPerLayer);
    const auto last = std::lower_bound(first, key.end(), (layer(hi) + 1) * cellsPerLayer);
    return {static_cast<std::size_t>(first - key.begin()),
            static_cast<std::size_t>(last - key.begin())};
  }
};

/// Where the results go: slot s of a particle's values -> base[s][node * stride[s]].
struct OutputTargets {
  std::vector<double*> base;
  std::vector<int> stride;
  double* color = nullptr;
  double* mask = nullptr;
  double* density = nullptr;  // null without masses
};

/// Node index range [lo, hi] within `radius` (in node units) of the continuous node index `q`,
/// clipped to [clipLo, clipHi]; empty when lo > hi.
inline std::pair<int, int> nodeRange(double q, double radius, int clipLo, int clipHi) {
  return {static_cast<int>(std::max<double>(std::ceil(q - radius), clipLo)),
          static_cast<int>(std::min<double>(std::floor(q + radius), clipHi))};
}

/// Doubles per node of BlockSums for `terms` sums: padded to 2, 4 or 8 so that a node's update
/// is one vector operation (8: one AVX-512 register, one cache line).
inline int paddedStride(int terms) {
  for (int s : {2, 4, 8})
    if (terms <= s) return s;
  return terms;
}

/// Per-node sums of eqs. (1)-(3) for the nodes of one block of layers, node-major so that one
/// node's sums share a cache line: [c, rho, V W A_0, ..., V W A_{width-1}, 0...] (rho only with
/// masses; zeros up to the padded stride). Each thread owns one and reuses it block after
/// block: the sums of the whole grid never exist at once, and the block's nodes are still in
/// cache when they are written out.
struct BlockSums {
  std::vector<double> data;  // nodes * stride
  std::int64_t firstNode = 0;  // grid index of the block's first node
  std::size_t nodes = 0;
  int stride = 0;  // doubles per node (padded)
  int first = 0;   // offset of V W A_0
  bool withMass = false;
  std::vector<double> terms;  // one particle's terms [V, m, V A_0, ...] (stride, zero-padded)

  BlockSums(std::size_t maxNodes, int width, bool mass)
      : data(maxNodes * paddedStride(width + (mass ? 2 : 1))),
        stride(paddedStride(width + (mass ? 2 : 1))),
        first(mass ? 2 : 1),
        withMass(mass),
        terms(stride, 0.0) {}

  /// Starts the block of `count` nodes from grid node `firstIndex`, all sums 0.
  void reset(std::int64_t firstIndex, std::size_t count) {
    firstNode = firstIndex;
    nodes = count;
    std::fill(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(count * stride), 0.0);
  }
};

// A node's padded sums as one vector (GCC/Clang vector extension: one SSE, AVX or AVX-512
// register, whichever the enclosing function's target allows).
template <int kStride>
struct NodeVector;
template <>
struct NodeVector<2> {
  typedef double type __attribute__((vector_size(16)));
};
template <>
struct NodeVector<4> {
  typedef double type __attribute__((vector_size(32)));
};
template <>
struct NodeVector<8> {
  typedef double type __attribute__((vector_size(64)));
};

/// node[c] += w terms[c] for the stride's c: one vector operation when the stride is known.
template <int kStride>
FLUIDVIZ_ALWAYS_INLINE void addTerms(double* node, double w, const double* terms, int stride) {
  if constexpr (kStride > 0) {
    using Node = typename NodeVector<kStride>::type;
    static_assert(sizeof(Node) == kStride * sizeof(double));
    Node sum, t;
    std::memcpy(&sum, node, sizeof sum);
    std::memcpy(&t, terms, sizeof t);
    sum += w * t;
    std::memcpy(node, &sum, sizeof sum);
  } else {
    for (int c = 0; c < stride; ++c) node[c] += w * terms[c];
  }
}

/// Adds particle p's terms to the nodes of layers [layer0, layer1] (slow axis) within its
/// support. Rows run over the whole bounding box of the support, the same length for every
/// particle, and without branches: W is evaluated for the whole row at once (zero outside the
/// support) and every node of the row gets w times the particle's term vector
/// [V, m, V A_0, ...] (one vector operation per node with the padded stride kStride). Rows
/// wholly outside the support are skipped. kStride > 0 is sums.stride known at compile time;
/// 0: run-time stride.
/// Compiled once per instruction-set level (ParticleResampler.cpp), hence forced inline.
template <int kStride, bool kWithMass, class Kernel>
FLUIDVIZ_ALWAYS_INLINE void scatterParticle(const Grid& g, int dimension, const Kernel& kernel,
                                            const SortedParticles& sp, std::size_t p, int layer0,
                                            int layer1, BlockSums& sums) {
  const double s = kernel.support(), s2 = s * s;
  const std::size_t i = sp.order[p];
  const Vec3& x = sp.x[i];
  const int slow = dimension - 1;
  std::array<double, 3> q{0, 0, 0};  // continuous node index of the particle
  std::array<std::pair<int, int>, 3> r{};
  for (int a = 0; a < 3; ++a) {
    q[a] = (x[a] - g.origin[a]) / g.spacing[a];
    r[a] = a >= dimension ? std::pair<int, int>{0, 0}
                          : nodeRange(q[a], s / g.spacing[a], a == slow ? layer0 : 0,
                                      a == slow ? layer1 : g.dims[a] - 1);
  }
  const int rowLength = r[0].second - r[0].first + 1;
  const int stride = kStride > 0 ? kStride : sums.stride;
  // [V, m, V A_0, ...], zero-padded to the stride; a local copy when the stride is known (the
  // compiler then keeps it in registers: it cannot alias the sums).
  double local[kStride > 0 ? kStride : 1] = {};
  double* terms = kStride > 0 ? local : sums.terms.data();
  const double v = sp.volume ? sp.volume[i] : sp.uniformVolume;
  terms[0] = v;
  if constexpr (kWithMass) terms[1] = sp.mass[i];
  for (std::size_t c = 0; c < sp.columns.size(); ++c) {
    const SortedParticles::Column& column = sp.columns[c];
    terms[sums.first + c] = v * column.data[i * column.stride];
  }
  for (int k = r[2].first; k <= r[2].second; ++k) {
    const double dz = dimension == 3 ? (k - q[2]) * g.spacing[2] : 0.0;
    for (int j = r[1].first; j <= r[1].second; ++j) {
      const double dy = (j - q[1]) * g.spacing[1], dyz2 = dz * dz + dy * dy;
      if (dyz2 >= s2) continue;
      double* node = &sums.data[(g.index(r[0].first, j, k) - sums.firstNode) * stride];
      for (int i0 = 0; i0 < rowLength; i0 += kChunk) {
        double w[kChunk];  // all lanes evaluated (a fixed count vectorises fully)
#pragma omp simd
        for (int i = 0; i < kChunk; ++i) {
          const double dx = (r[0].first + i0 + i - q[0]) * g.spacing[0];
          w[i] = kernel.W(std::sqrt(dyz2 + dx * dx));
        }
        const int n = std::min(kChunk, rowLength - i0);
        for (int i = 0; i < n; ++i, node += stride) addTerms<kStride>(node, w[i], terms, stride);
      }
    }
  }
}

/// scatterParticle for particles [first, last).
template <int kStride, bool kWithMass, class Kernel>
FLUIDVIZ_ALWAYS_INLINE void scatterRange(const Grid& g, int dimension, const Kernel& kernel,
                                         const SortedParticles& sp, std::size_t first,
                                         std::size_t last, int layer0, int layer1,
                                         BlockSums& sums) {
  for (std::size_t p = first; p < last; ++p)
    scatterParticle<kStride, kWithMass>(g, dimension, kernel, sp, p, layer0, layer1, sums);
}

/// scatterRange with the padded strides 2, 4 and 8 compiled as constants.
template <bool kWithMass, class Kernel>
FLUIDVIZ_ALWAYS_INLINE void scatterParticlesOf(const Grid& g, int dimension, const Kernel& kernel,
                                               const SortedParticles& sp, std::size_t first,
                                               std::size_t last, int layer0, int layer1,
                                               BlockSums& sums) {
  switch (sums.stride) {
    case 2:
      return scatterRange<2, kWithMass>(g, dimension, kernel, sp, first, last, layer0, layer1,
                                        sums);
    case 4:
      return scatterRange<4, kWithMass>(g, dimension, kernel, sp, first, last, layer0, layer1,
                                        sums);
    case 8:
      return scatterRange<8, kWithMass>(g, dimension, kernel, sp, first, last, layer0, layer1,
                                        sums);
    default:
      return scatterRange<0, kWithMass>(g, dimension, kernel, sp, first, last, layer0, layer1,
                                        sums);
  }
}

/// All particles [first, last) into one block's sums.
template <class Kernel>
FLUIDVIZ_ALWAYS_INLINE void scatterParticles(const Grid& g, int dimension, const Kernel& kernel,
                                             const SortedParticles& sp, std::size_t first,
                                             std::size_t last, int layer0, int layer1,
                                             BlockSums& sums) {
  if (sums.withMass)
    scatterParticlesOf<true>(g, dimension, kernel, sp, first, last, layer0, layer1, sums);
  else
    scatterParticlesOf<false>(g, dimension, kernel, sp, first, last, layer0, layer1, sums);
}

/// scatterParticles compiled for one instruction-set level (ParticleResampler.cpp).
template <class Kernel>
using ScatterFunction = void (*)(const Grid&, int, const Kernel&, const SortedParticles&,
                                 std::size_t, std::size_t, int, int, BlockSums&);

/// Copies a block's sums into the output arrays: colour (1), summation density (3), and eq.
/// (2) - the sums divided by the colour field where it reaches `threshold` (mask 1), `empty`
/// elsewhere (mask 0).
inline void writeNodes(const BlockSums& sums, double threshold, double empty,
                       const OutputTargets& out) {
  for (std::size_t b = 0; b < sums.nodes; ++b) {
    const std::int64_t n = sums.firstNode + static_cast<std::int64_t>(b);
    const double* node = &sums.data[b * sums.stride];
    const double c = node[0];
    const bool supported = c > 0.0 && c >= threshold;
    for (std::size_t s = 0; s < out.base.size(); ++s)
      out.base[s][n * out.stride[s]] = supported ? node[sums.first + s] / c : empty;
    out.color[n] = c;
    out.mask[n] = supported ? 1.0 : 0.0;
    if (out.density) out.density[n] = node[1];
  }
}

/// Evaluates eqs. (1)-(3) at every node of the grid and writes the outputs (writeNodes), one
/// block of layers at a time.
template <class Kernel>
void resampleToGrid(const Grid& g, int dimension, const Kernel& kernel, const SortedParticles& sp,
                    bool withMass, double threshold, double empty, const OutputTargets& out,
                    ScatterFunction<Kernel> scatter) {
  const int slow = dimension - 1, layers = g.dims[slow];
  const int blocks = (layers + kLayersPerBlock - 1) / kLayersPerBlock;
  const std::size_t layerNodes = g.nodeCount() / static_cast<std::size_t>(layers);
  const double s = kernel.support();
#pragma omp parallel
  {
    BlockSums sums(layerNodes * std::min(layers, kLayersPerBlock),
                   static_cast<int>(sp.columns.size()), withMass);
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < blocks; ++b) {
      const int layer0 = b * kLayersPerBlock;
      const int layer1 = std::min(layers, layer0 + kLayersPerBlock) - 1;
      sums.reset(static_cast<std::int64_t>(layer0 * layerNodes), (layer1 - layer0 + 1) * layerNodes);
      const double lo = g.origin[slow] + layer0 * g.spacing[slow] - s;
      const double hi = g.origin[slow] + layer1 * g.spacing[slow] + s;
      const auto [first, last] = sp.rangeOverlapping(lo, hi);
      scatter(g, dimension, kernel, sp, first, last, layer0, layer1, sums);
      writeNodes(sums, threshold, empty, out);
    }
  }
}

}  // namespace fluidviz::resample::detail
