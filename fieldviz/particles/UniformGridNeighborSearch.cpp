#include "fieldviz/particles/UniformGridNeighborSearch.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <omp.h>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define FLUIDVIZ_SPH_X86 1
#endif

#include "fieldviz/particles/Parallel.h"

namespace fluidviz::particles {

namespace {
// Beyond this many cells the edge grows (memory of cellStart_ stays below ~0.5 GB).
constexpr double kMaxCells = 5.0e7;
// Candidate tiles run this far past their last candidate, so that a vector load of 16 may start
// at any candidate (the lanes past the end are masked off); a row may be written this far past
// its end.
constexpr std::size_t kFloatPadding = 16;

// One query against the candidate tile of its cell (CandidateTile: the candidates of all its
// ranges copied into one contiguous run), so that every query of the cell runs one loop of the
// same length. A candidate with float d2 < inner is surely within the radius, one with
// d2 >= outer surely not; in between (a band of a few float roundings) the exact double test
// decides, on the query minus the range's shift and the sorted position, as brute force would.
struct RangeScan {
  const float *x, *y, *z;          ///< float coordinates of the candidates (box-relative)
  const int* index;                ///< original index of each candidate
  const std::int64_t* rangeStart;  ///< tile position of each range's first candidate (+ end)
  const std::int64_t* rangeSlot;   ///< sorted slot of each range's first candidate
  const Vec3* rangeShift;          ///< periodic shift of each range
  const Vec3* points;              ///< exact positions by sorted slot
  std::int64_t len;                ///< number of candidates
  std::int64_t self;               ///< candidate number of the query itself, or -1
  int maxNeighbor;                 ///< only original indices below this are kept
  float qx, qy, qz;                ///< query, float, relative to the box corner
  float inner, outer;              ///< squared-distance thresholds around radius^2
  Vec3 query;                      ///< the same query position in double (not relative)
  double r2;                       ///< radius^2
};

// The exact test, d = x_i - x_j in double (as brute force and the periodic shift compute it).
// Not inlined, so that it keeps this file's instruction set: inlined into the AVX-512 scan, the
// compiler would contract it into fused multiply-adds and decide ties at the radius differently.
__attribute__((noinline)) bool exactlyWithin(const Vec3& query, const Vec3& point, double r2) {
  const Vec3 d = query - point;
  return d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < r2;
}

// Appends the original indices of the candidates in `lanes` (bit k: candidate c + k) that are
// within the radius (band lanes checked exactly), not the query and below maxNeighbor.
inline int* appendHits(const RangeScan& r, std::int64_t c, unsigned lanes, unsigned band,
                       int* out) {
  for (; band; band &= band - 1) {
    const std::int64_t k = c + __builtin_ctz(band);
    std::size_t g = 0;
    while (r.rangeStart[g + 1] <= k) ++g;  // the candidate's range (a few, band lanes are rare)
    const Vec3 query = r.query - r.rangeShift[g];
    if (!exactlyWithin(query, r.points[r.rangeSlot[g] + (k - r.rangeStart[g])], r.r2))
      lanes &= ~(1u << (k - c));
  }
  for (; lanes; lanes &= lanes - 1) {
    const std::int64_t k = c + __builtin_ctz(lanes);
    const int j = r.index[k];
    *out = j;
    out += (k != r.self) & (j < r.maxNeighbor);
  }
  return out;
}

// Writes the neighbours among the candidates to out (in candidate order); returns the end.
// May write up to 16 entries past the end it returns.
using ScanFunction = int* (*)(const RangeScan& r, int* out);

template <bool WithZ>
int* scanRangeScalar(const RangeScan& r, int* out) {
  for (std::int64_t c = 0; c < r.len; c += 8) {
    unsigned lanes = 0, sure = 0;
    for (std::int64_t k = 0; k < 8 && c + k < r.len; ++k) {
      const float dx = r.qx - r.x[c + k], dy = r.qy - r.y[c + k];
      const float dz = WithZ ? r.qz - r.z[c + k] : 0.0f;
      const float d2 = dx * dx + dy * dy + dz * dz;
      lanes |= unsigned(d2 < r.outer) << k;
      sure |= unsigned(d2 < r.inner) << k;
    }
    out = appendHits(r, c, lanes, lanes & ~sure, out);
  }
  return out;
}

#ifdef FLUIDVIZ_SPH_X86
unsigned lanesBelow(std::int64_t remaining) {
  return remaining >= 8 ? 0xffu : (1u << remaining) - 1u;
}

// Lane permutations that move the set lanes of an 8-bit mask to the front (AVX2 has no
// compress instruction).
struct CompressTable {
  alignas(32) int lanes[256][8];
  constexpr CompressTable() : lanes{} {
    for (int m = 0; m < 256; ++m) {
      int n = 0;
      for (int k = 0; k < 8; ++k)
        if (m & (1 << k)) lanes[m][n++] = k;
      for (; n < 8; ++n) lanes[m][n] = 0;
    }
  }
};
constexpr CompressTable kCompress;

template <bool WithZ>
__attribute__((target("avx2,popcnt"))) int* scanRangeAvx2(const RangeScan& r, int* out) {
  const __m256 qx = _mm256_set1_ps(r.qx), qy = _mm256_set1_ps(r.qy), qz = _mm256_set1_ps(r.qz);
  const __m256 inner = _mm256_set1_ps(r.inner), outer = _mm256_set1_ps(r.outer);
  const bool limited = r.maxNeighbor != std::numeric_limits<int>::max();
  const __m256i lastKept = _mm256_set1_epi32(r.maxNeighbor - 1);
  // Locals: the stores through out must not make the compiler reload them.
  const float *x = r.x, *y = r.y, *z = r.z;
  const int* index = r.index;
  const std::int64_t len = r.len, self = r.self;
  for (std::int64_t c = 0; c < len; c += 8) {
    const __m256 dx = _mm256_sub_ps(qx, _mm256_loadu_ps(x + c));
    const __m256 dy = _mm256_sub_ps(qy, _mm256_loadu_ps(y + c));
    __m256 d2 = _mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy));
    if constexpr (WithZ) {
      const __m256 dz = _mm256_sub_ps(qz, _mm256_loadu_ps(z + c));
      d2 = _mm256_add_ps(d2, _mm256_mul_ps(dz, dz));
    }
    unsigned lanes = unsigned(_mm256_movemask_ps(_mm256_cmp_ps(d2, outer, _CMP_LT_OQ))) &
                     lanesBelow(len - c);
    const unsigned band =
        lanes & ~unsigned(_mm256_movemask_ps(_mm256_cmp_ps(d2, inner, _CMP_LT_OQ)));
    if (band) {  // rare: leave the exact test, self and maxNeighbor to the scalar path
      out = appendHits(r, c, lanes, band, out);
      continue;
    }
    if (self >= c && self < c + 8) lanes &= ~(1u << (self - c));
    const __m256i j = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(index + c));
    if (limited)
      lanes &= ~unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpgt_epi32(j, lastKept))));
    const __m256i order =
        _mm256_load_si256(reinterpret_cast<const __m256i*>(kCompress.lanes[lanes]));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_permutevar8x32_epi32(j, order));
    out += __builtin_popcount(lanes);
  }
  return out;
}

template <bool WithZ>
__attribute__((target("avx512f,popcnt"))) int* scanRangeAvx512(const RangeScan& r, int* out) {
  const __m512 qx = _mm512_set1_ps(r.qx), qy = _mm512_set1_ps(r.qy), qz = _mm512_set1_ps(r.qz);
  const __m512 inner = _mm512_set1_ps(r.inner), outer = _mm512_set1_ps(r.outer);
  const bool limited = r.maxNeighbor != std::numeric_limits<int>::max();
  const __m512i lastKept = _mm512_set1_epi32(r.maxNeighbor - 1);
  const float *x = r.x, *y = r.y, *z = r.z;
  const int* index = r.index;
  const std::int64_t len = r.len, self = r.self;
  for (std::int64_t c = 0; c < len; c += 16) {
    const __m512 dx = _mm512_sub_ps(qx, _mm512_loadu_ps(x + c));
    const __m512 dy = _mm512_sub_ps(qy, _mm512_loadu_ps(y + c));
    __m512 d2 = _mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy));
    if constexpr (WithZ) {
      const __m512 dz = _mm512_sub_ps(qz, _mm512_loadu_ps(z + c));
      d2 = _mm512_add_ps(d2, _mm512_mul_ps(dz, dz));
    }
    const __mmask16 valid =
        len - c >= 16 ? __mmask16(0xffff) : __mmask16((1u << (len - c)) - 1u);
    unsigned lanes = _mm512_mask_cmp_ps_mask(valid, d2, outer, _CMP_LT_OQ);
    const unsigned band = lanes & ~unsigned(_mm512_cmp_ps_mask(d2, inner, _CMP_LT_OQ));
    if (band) {  // rare: leave the exact test, self and maxNeighbor to the scalar path
      out = appendHits(r, c, lanes, band, out);
      continue;
    }
    if (self >= c && self < c + 16) lanes &= ~(1u << (self - c));
    const __m512i j = _mm512_loadu_si512(index + c);
    if (limited) lanes &= ~unsigned(_mm512_cmpgt_epi32_mask(j, lastKept));
    _mm512_storeu_si512(out, _mm512_maskz_compress_epi32(__mmask16(lanes), j));
    out += __builtin_popcount(lanes);
  }
  return out;
}

template <bool WithZ>
int* scanRangeSse(const RangeScan& r, int* out) {
  const __m128 qx = _mm_set1_ps(r.qx), qy = _mm_set1_ps(r.qy), qz = _mm_set1_ps(r.qz);
  const __m128 inner = _mm_set1_ps(r.inner), outer = _mm_set1_ps(r.outer);
  auto squared = [&](std::int64_t c) {
    const __m128 dx = _mm_sub_ps(qx, _mm_loadu_ps(r.x + c));
    const __m128 dy = _mm_sub_ps(qy, _mm_loadu_ps(r.y + c));
    __m128 d2 = _mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy));
    if constexpr (WithZ) {
      const __m128 dz = _mm_sub_ps(qz, _mm_loadu_ps(r.z + c));
      d2 = _mm_add_ps(d2, _mm_mul_ps(dz, dz));
    }
    return d2;
  };
  for (std::int64_t c = 0; c < r.len; c += 8) {
    const __m128 lo = squared(c), hi = squared(c + 4);
    const unsigned lanes = unsigned(_mm_movemask_ps(_mm_cmplt_ps(lo, outer)) |
                                    (_mm_movemask_ps(_mm_cmplt_ps(hi, outer)) << 4)) &
                           lanesBelow(r.len - c);
    const unsigned sure = unsigned(_mm_movemask_ps(_mm_cmplt_ps(lo, inner)) |
                                   (_mm_movemask_ps(_mm_cmplt_ps(hi, inner)) << 4));
    out = appendHits(r, c, lanes, lanes & ~sure, out);
  }
  return out;
}
#endif

// The widest scan this CPU runs (chosen once).
ScanFunction scanFunction(bool withZ) {
#ifdef FLUIDVIZ_SPH_X86
  static const bool avx512 = __builtin_cpu_supports("avx512f");
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx512) return withZ ? scanRangeAvx512<true> : scanRangeAvx512<false>;
  if (avx2) return withZ ? scanRangeAvx2<true> : scanRangeAvx2<false>;
  return withZ ? scanRangeSse<true> : scanRangeSse<false>;
#else
  return withZ ? scanRangeScalar<true> : scanRangeScalar<false>;
#endif
}

// Thresholds around radius^2 that bound the float rounding: coordinates up to `extent` carry
// an error <= u extent each (u = 2^-24), so a float difference is off by
// delta <= 3 u extent + u |d| and a float d2 near radius^2 by <= 3 delta (2 radius + delta) plus
// ~4 u radius^2 from the products and sums; twice that is the band.
void floatThresholds(double radius, double extent, float& inner, float& outer) {
  const double u = std::ldexp(1.0, -24);
  const double delta = 3.0 * u * extent + u * radius;
  const double band = 2.0 * (3.0 * delta * (2.0 * radius + delta) + 4.0 * u * (radius + delta) * (radius + delta));
  const double r2 = radius * radius;
  outer = std::nextafter(static_cast<float>(r2 + band), std::numeric_limits<float>::infinity());
  inner = r2 - band > 0.0
              ? std::nextafter(static_cast<float>(r2 - band), -std::numeric_limits<float>::infinity())
              : -1.0f;
}
}  // namespace

UniformGridNeighborSearch::UniformGridNeighborSearch(int dimension, const Vec3& lower,
                                                     const Vec3& upper, double cellSize,
                                                     std::array<bool, 3> periodic)
    : dim_(dimension), lower_(lower), upper_(upper), periodic_(periodic) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("UniformGridNeighborSearch: dimension must be 2 or 3");
  if (!(cellSize > 0) || !std::isfinite(cellSize))
    throw std::invalid_argument("UniformGridNeighborSearch: cell size must be > 0");
  double cells = 1.0;
  for (int a = 0; a < dim_; ++a) {
    const double length = upper[a] - lower[a];
    if (!(length > 0))
      throw std::invalid_argument("UniformGridNeighborSearch: upper must exceed lower on axis " +
                                  std::to_string(a));
    cells *= std::ceil(length / cellSize);
  }
  const double grow = cells > kMaxCells ? std::pow(cells / kMaxCells, 1.0 / dim_) : 1.0;
  edge_ = invEdge_ = period_ = Vec3(1, 1, 1);
  for (int a = 0; a < dim_; ++a) {
    const double length = upper[a] - lower[a];
    if (periodic_[a]) {
      n_[a] = static_cast<int>(std::floor(length / (cellSize * grow)));
      if (n_[a] < 3)
        throw std::invalid_argument(
            "UniformGridNeighborSearch: periodic axis " + std::to_string(a) +
            " is shorter than 3 search radii; lengthen the periodic box");
      edge_[a] = length / n_[a];
      period_[a] = length;
    } else {
      n_[a] = std::max(1, static_cast<int>(std::ceil(length / (cellSize * grow))));
      edge_[a] = cellSize * grow;
    }
    invEdge_[a] = 1.0 / edge_[a];
  }
  for (int a = dim_; a < 3; ++a) periodic_[a] = false;
  anyPeriodic_ = periodic_[0] || periodic_[1] || periodic_[2];
  cellStart_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
}

void UniformGridNeighborSearch::throwRadiusTooLarge(double radius, int axis) const {
  throw std::invalid_argument("UniformGridNeighborSearch: query radius " + std::to_string(radius) +
                              " m reaches around periodic axis " + std::to_string(axis) +
                              " (period " + std::to_string(period_[axis]) + " m)");
}

// Counting sort by cell (Green 2010): histogram, exclusive prefix sum, stable scatter.
void UniformGridNeighborSearch::build(std::span<const Vec3> points) {
  points_ = points;
  const std::int64_t n = static_cast<std::int64_t>(points.size());
  cellOfPoint_.resize(n);
#pragma omp parallel for schedule(static) if(n >= kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    const Vec3& p = points[i];
    cellOfPoint_[i] = cellIndex(cellCoord(p[0], 0), cellCoord(p[1], 1),
                                dim_ == 3 ? cellCoord(p[2], 2) : 0);
  }
  std::fill(cellStart_.begin(), cellStart_.end(), 0);
  for (std::int64_t i = 0; i < n; ++i) ++cellStart_[cellOfPoint_[i] + 1];
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  sortedIndex_.resize(n);
  sortedPoints_.resize(n);
  {
    std::vector<std::int64_t> next(cellStart_.begin(), cellStart_.end() - 1);
    for (std::int64_t i = 0; i < n; ++i) sortedIndex_[next[cellOfPoint_[i]]++] = static_cast<int>(i);
  }
  for (std::vector<float>* f : {&floatX_, &floatY_, &floatZ_}) f->resize(n);
  double extent = 0.0, zMin = 0.0, zMax = 0.0;
  if (n > 0) zMin = zMax = points[0][2];
#pragma omp parallel for schedule(static) reduction(max : extent, zMax) reduction(min : zMin) if(n >= kParallelMinItems)
  for (std::int64_t s = 0; s < n; ++s) {
    const Vec3 p = anyPeriodic_ ? wrap(points[sortedIndex_[s]]) : points[sortedIndex_[s]];
    sortedPoints_[s] = p;
    const Vec3 q = p - lower_;
    floatX_[s] = static_cast<float>(q[0]);
    floatY_[s] = static_cast<float>(q[1]);
    floatZ_[s] = static_cast<float>(q[2]);
    extent = std::max(extent, q.cwiseAbs().maxCoeff());
    zMin = std::min(zMin, p[2]);
    zMax = std::max(zMax, p[2]);
  }
  // Queries shifted by a period reach beyond the box by up to one period.
  floatExtent_ = extent + (anyPeriodic_ ? period_.maxCoeff() : 0.0);
  scanZ_ = dim_ == 3 || zMin != zMax;  // 2D points normally share one z
}

void UniformGridNeighborSearch::pointsWithin(const Vec3& x, double radius,
                                             std::vector<int>& out) const {
  out.clear();
  forEachWithin(x, radius, [&](int j, const Vec3&, double) { out.push_back(j); });
}

// The rows (y, z offsets) of the cell stencil of `radius` whose distance to the query cell is
// below the radius, each with the half-width of its x run (rows and runs beyond the radius
// are pruned). The same for every cell: computed once per neighborLists call.
std::vector<UniformGridNeighborSearch::StencilRow> UniformGridNeighborSearch::stencilRows(
    double radius) const {
  std::array<int, 3> k{0, 0, 0};
  for (int a = 0; a < dim_; ++a) {
    k[a] = static_cast<int>(std::ceil(radius * invEdge_[a]));
    if (periodic_[a] && 2 * k[a] + 1 > n_[a]) throwRadiusTooLarge(radius, a);
  }
  const double r2 = radius * radius;
  auto gap = [&](int d, int a) { return edge_[a] * std::max(std::abs(d) - 1, 0); };
  std::vector<StencilRow> rows;
  for (int dz = -k[2]; dz <= k[2]; ++dz) {
    const double gz = gap(dz, 2);
    if (gz * gz >= r2) continue;
    for (int dy = -k[1]; dy <= k[1]; ++dy) {
      const double gy = gap(dy, 1), rest = r2 - gy * gy - gz * gz;
      if (rest <= 0.0) continue;
      rows.push_back({dy, dz, std::min(k[0], static_cast<int>(std::ceil(std::sqrt(rest) * invEdge_[0])))});
    }
  }
  return rows;
}

// Candidate ranges around `cell`: for every stencil row, the x run of cells, split where it
// wraps around a periodic x axis. `interesting` (optional) flags the cells worth visiting.
void UniformGridNeighborSearch::candidateRanges(const std::array<int, 3>& cell,
                                                const std::vector<StencilRow>& rows,
                                                const std::vector<unsigned char>* interesting,
                                                std::vector<CandidateRange>& out) const {
  out.clear();
  auto wrapAxis = [&](int u, int a, int& w, double& shift) {
    if (!periodic_[a]) {
      w = u;
      shift = 0.0;
      return u >= 0 && u < n_[a];
    }
    const int q = static_cast<int>(std::floor(static_cast<double>(u) / n_[a]));
    w = u - q * n_[a];
    shift = q * period_[a];
    return true;
  };
  auto addRun = [&](int x0, int x1, int wy, int wz, const Vec3& shift) {
    if (interesting) {
      bool any = false;
      for (int x = x0; x <= x1 && !any; ++x) any = (*interesting)[cellIndex(x, wy, wz)] != 0;
      if (!any) return;
    }
    const std::int64_t b = cellStart_[cellIndex(x0, wy, wz)], e = cellStart_[cellIndex(x1, wy, wz) + 1];
    if (e > b) out.push_back({b, e, shift});
  };
  for (const StencilRow& row : rows) {
    int wy, wz;
    double sy, sz;
    if (!wrapAxis(cell[2] + row.dz, 2, wz, sz) || !wrapAxis(cell[1] + row.dy, 1, wy, sy)) continue;
    int x0 = cell[0] - row.m, x1 = cell[0] + row.m;
    if (!periodic_[0]) {
      addRun(std::max(x0, 0), std::min(x1, n_[0] - 1), wy, wz, Vec3(0.0, sy, sz));
      continue;
    }
    const double L = period_[0];
    if (x0 < 0) addRun(x0 + n_[0], n_[0] - 1, wy, wz, Vec3(-L, sy, sz)), x0 = 0;
    if (x1 >= n_[0]) addRun(0, x1 - n_[0], wy, wz, Vec3(L, sy, sz)), x1 = n_[0] - 1;
    addRun(x0, x1, wy, wz, Vec3(0.0, sy, sz));
  }
}

// Lists of the queries in one cell: each candidate range is scanned 16, 8 or 4 candidates at a
// time on the float copy (the widest the CPU has); the few candidates in the rounding band are decided
// by the exact double distance (the same expression as brute force); the hits become original
// indices in slot order.
void UniformGridNeighborSearch::listCellQueries(std::int64_t cell, std::size_t first,
                                                std::size_t last, double radius,
                                                std::size_t maxNeighbor, float inner, float outer,
                                                const std::vector<CandidateRange>& ranges,
                                                RowBlock& b) const {
  CandidateTile& tile = b.tile;
  fillTile(ranges, cellStart_[cell], tile);
  const std::int64_t candidates = tile.rangeStart.back();
  RangeScan rs{};
  rs.x = tile.x.data();
  rs.y = tile.y.data();
  rs.z = tile.z.data();
  rs.index = tile.index.data();
  rs.rangeStart = tile.rangeStart.data();
  rs.rangeSlot = tile.rangeSlot.data();
  rs.rangeShift = tile.rangeShift.data();
  rs.points = sortedPoints_.data();
  rs.len = candidates;
  rs.inner = inner;
  rs.outer = outer;
  rs.r2 = radius * radius;
  rs.maxNeighbor = static_cast<int>(std::min<std::size_t>(maxNeighbor, std::numeric_limits<int>::max()));
  const ScanFunction scan = scanFunction(scanZ_);
  for (std::int64_t s = cellStart_[cell]; s < cellStart_[cell + 1]; ++s) {
    const std::size_t i = static_cast<std::size_t>(sortedIndex_[s]);
    if (i < first || i >= last) continue;
    const std::size_t need = b.used + static_cast<std::size_t>(candidates) + kFloatPadding;
    if (b.indices->size() < need)  // grows by 1/8 (the block is kept for the next call)
      b.indices->resize(std::max(b.indices->size() + b.indices->size() / 8, need));
    int* const row = b.indices->data() + b.used;
    rs.query = sortedPoints_[s];
    rs.qx = floatX_[s];
    rs.qy = floatY_[s];
    rs.qz = floatZ_[s];
    rs.self = tile.ownCell < 0 ? -1 : tile.ownCell + (s - cellStart_[cell]);
    int* out = scan(rs, row);
    b.used += static_cast<std::size_t>(out - row);
    b.counts.push_back(out - row);
    b.rowQueries.push_back(static_cast<int>(i - first));
  }
}

// Copies the candidates of all ranges into the tile, in range order, and finds the unshifted
// copy of sorted slot ownSlot (the query cell's first point). Shifted ranges get float
// coordinates from the exact positions plus the shift (one rounding, within floatExtent_).
void UniformGridNeighborSearch::fillTile(const std::vector<CandidateRange>& ranges,
                                         std::int64_t ownSlot, CandidateTile& tile) const {
  tile.rangeStart.assign(1, 0);
  tile.rangeSlot.clear();
  tile.rangeShift.clear();
  for (const CandidateRange& r : ranges) {
    tile.rangeStart.push_back(tile.rangeStart.back() + r.end - r.begin);
    tile.rangeSlot.push_back(r.begin);
    tile.rangeShift.push_back(r.shift);
  }
  const std::size_t size = static_cast<std::size_t>(tile.rangeStart.back()) + kFloatPadding;
  // Padding zeroed: vector loads read past the candidates (masked lanes).
  for (std::vector<float>* f : {&tile.x, &tile.y, &tile.z}) {
    f->resize(size);
    std::fill(f->end() - kFloatPadding, f->end(), 0.0f);
  }
  tile.index.resize(size);
  std::fill(tile.index.end() - kFloatPadding, tile.index.end(), 0);
  tile.ownCell = -1;
  float* __restrict tx = tile.x.data();
  float* __restrict ty = tile.y.data();
  float* __restrict tz = tile.z.data();
  int* __restrict ti = tile.index.data();
  const float* __restrict fx = floatX_.data();
  const float* __restrict fy = floatY_.data();
  const float* __restrict fz = floatZ_.data();
  const int* __restrict si = sortedIndex_.data();
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const CandidateRange& r = ranges[k];
    const std::int64_t t = tile.rangeStart[k], b = r.begin, len = r.end - r.begin;
    const bool shifted = r.shift != Vec3::Zero();
    if (!shifted && ownSlot >= b && ownSlot < r.end) tile.ownCell = t + (ownSlot - b);
    for (std::int64_t m = 0; m < len; ++m) ti[t + m] = si[b + m];
    if (!shifted) {
      for (std::int64_t m = 0; m < len; ++m) tx[t + m] = fx[b + m];
      for (std::int64_t m = 0; m < len; ++m) ty[t + m] = fy[b + m];
      if (scanZ_)
        for (std::int64_t m = 0; m < len; ++m) tz[t + m] = fz[b + m];
      continue;
    }
    for (std::int64_t m = 0; m < len; ++m) {
      const Vec3 q = sortedPoints_[b + m] - lower_ + r.shift;
      tx[t + m] = static_cast<float>(q[0]);
      ty[t + m] = static_cast<float>(q[1]);
      tz[t + m] = static_cast<float>(q[2]);
    }
  }
}

// Cells are split into one contiguous block per thread (equal numbers of points); each thread
// writes its rows into its own block of the lists and points their rows at them.
void UniformGridNeighborSearch::neighborLists(std::size_t first, std::size_t last, double radius,
                                              NeighborLists& out,
                                              std::size_t maxNeighbor) const {
  if (first > last || last > points_.size())
    throw std::invalid_argument("UniformGridNeighborSearch::neighborLists: bad query range");
  const std::int64_t cells = static_cast<std::int64_t>(cellStart_.size()) - 1;
  const std::int64_t n = static_cast<std::int64_t>(points_.size());
  std::vector<unsigned char> interesting;
  if (maxNeighbor < points_.size()) {
    interesting.resize(cells);
#pragma omp parallel for schedule(static) if(n >= kParallelMinItems)
    for (std::int64_t c = 0; c < cells; ++c) {
      bool any = false;
      for (std::int64_t s = cellStart_[c]; s < cellStart_[c + 1] && !any; ++s)
        any = static_cast<std::size_t>(sortedIndex_[s]) < maxNeighbor;
      interesting[c] = any;
    }
  }
  float inner, outer;
  floatThresholds(radius, floatExtent_, inner, outer);
  const std::vector<StencilRow> stencil = stencilRows(radius);
  const int threads = (last - first) >= static_cast<std::size_t>(kParallelMinItems)
                          ? omp_get_max_threads() : 1;
  if (static_cast<int>(rowBlocks_.size()) < threads) rowBlocks_.resize(threads);
  if (static_cast<int>(out.blocks.size()) < threads) out.blocks.resize(threads);
  out.rows.resize(last - first);  // every query has a row
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    auto cellAtSlot = [&](std::int64_t slot) {
      return static_cast<std::int64_t>(
          std::upper_bound(cellStart_.begin(), cellStart_.end(), slot) - cellStart_.begin() - 1);
    };
    const std::int64_t c0 = t == 0 ? 0 : cellAtSlot(n * t / nt);
    const std::int64_t c1 = t == nt - 1 ? cells : cellAtSlot(n * (t + 1) / nt);
    RowBlock& b = rowBlocks_[t];
    b.indices = &out.blocks[t];
    b.used = 0;
    b.counts.clear();
    b.rowQueries.clear();
    std::vector<CandidateRange> ranges;
    for (std::int64_t c = c0; c < c1; ++c) {
      if (cellStart_[c] == cellStart_[c + 1]) continue;
      const std::int64_t cx = c % n_[0], cy = (c / n_[0]) % n_[1], cz = c / (std::int64_t(n_[0]) * n_[1]);
      candidateRanges({int(cx), int(cy), int(cz)}, stencil,
                      interesting.empty() ? nullptr : &interesting, ranges);
      listCellQueries(c, first, last, radius, maxNeighbor, inner, outer, ranges, b);
    }
    const int* row = b.indices->data();  // final now: the block no longer grows
    for (std::size_t k = 0; k < b.counts.size(); ++k) {
      out.rows[b.rowQueries[k]] = {row, b.counts[k]};
      row += b.counts[k];
    }
  }
  out.pairs = 0;
  for (int t = 0; t < threads; ++t) out.pairs += rowBlocks_[t].used;
}

}  // namespace fluidviz::particles
