#include "solvers/sph/UniformGridNeighborSearch.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <omp.h>

#include "solvers/sph/Parallel.h"

namespace fluidviz::sph {

namespace {
// Beyond this many cells the edge grows (memory of cellStart_ stays below ~0.5 GB).
constexpr double kMaxCells = 5.0e7;
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
  sortedX_.resize(n);
  sortedY_.resize(n);
  sortedZ_.resize(n);
  {
    std::vector<std::int64_t> next(cellStart_.begin(), cellStart_.end() - 1);
    for (std::int64_t i = 0; i < n; ++i) sortedIndex_[next[cellOfPoint_[i]]++] = static_cast<int>(i);
  }
#pragma omp parallel for schedule(static) if(n >= kParallelMinItems)
  for (std::int64_t s = 0; s < n; ++s) {
    const Vec3 p = anyPeriodic_ ? wrap(points[sortedIndex_[s]]) : points[sortedIndex_[s]];
    sortedPoints_[s] = p;
    sortedX_[s] = p[0];
    sortedY_[s] = p[1];
    sortedZ_[s] = p[2];
  }
}

void UniformGridNeighborSearch::pointsWithin(const Vec3& x, double radius,
                                             std::vector<int>& out) const {
  out.clear();
  forEachWithin(x, radius, [&](int j, const Vec3&, double) { out.push_back(j); });
}

// Candidate ranges around `cell`: for every row (y, z offset) of the stencil, the x run of cells
// whose distance to the query cell is below the radius (rows and runs outside that distance are
// pruned), split where it wraps around a periodic x axis. `interesting` (optional) flags the
// cells worth visiting.
void UniformGridNeighborSearch::candidateRanges(const std::array<int, 3>& cell, double radius,
                                                const std::vector<unsigned char>* interesting,
                                                std::vector<CandidateRange>& out) const {
  out.clear();
  std::array<int, 3> k{0, 0, 0};
  for (int a = 0; a < dim_; ++a) {
    k[a] = static_cast<int>(std::ceil(radius * invEdge_[a]));
    if (periodic_[a] && 2 * k[a] + 1 > n_[a]) throwRadiusTooLarge(radius, a);
  }
  const double r2 = radius * radius;
  auto gap = [&](int d, int a) { return edge_[a] * std::max(std::abs(d) - 1, 0); };
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
  for (int dz = -k[2]; dz <= k[2]; ++dz) {
    const double gz = gap(dz, 2);
    int wz;
    double sz;
    if (gz * gz >= r2 || !wrapAxis(cell[2] + dz, 2, wz, sz)) continue;
    for (int dy = -k[1]; dy <= k[1]; ++dy) {
      const double gy = gap(dy, 1), rest = r2 - gy * gy - gz * gz;
      int wy;
      double sy;
      if (rest <= 0.0 || !wrapAxis(cell[1] + dy, 1, wy, sy)) continue;
      const int m = std::min(k[0], static_cast<int>(std::ceil(std::sqrt(rest) * invEdge_[0])));
      int x0 = cell[0] - m, x1 = cell[0] + m;
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
}

// Lists of the queries in one cell, in two passes per candidate range: squared distances into
// a buffer (a plain arithmetic loop the compiler vectorises), then a compaction by groups of 8
// (a bit mask per group; groups without a hit, the majority, cost one test); slots become
// original indices.
void UniformGridNeighborSearch::listCellQueries(
    std::int64_t cell, std::size_t first, std::size_t last, double radius, std::size_t maxNeighbor,
    const std::vector<CandidateRange>& ranges, std::vector<int>& indices,
    std::vector<std::int64_t>& counts, std::vector<int>& rowQueries,
    std::vector<std::int64_t>& scratch) const {
  const double r2 = radius * radius;
  const double* __restrict sx = sortedX_.data();
  const double* __restrict sy = sortedY_.data();
  const double* __restrict sz = sortedZ_.data();
  std::int64_t candidates = 0, longest = 0;
  for (const CandidateRange& r : ranges) {
    candidates += r.end - r.begin;
    longest = std::max(longest, r.end - r.begin);
  }
  if (static_cast<std::int64_t>(scratch.size()) < candidates) scratch.resize(candidates);
  thread_local std::vector<double> d2;
  if (static_cast<std::int64_t>(d2.size()) < longest + 8) d2.resize(longest + 8);
  for (std::int64_t s = cellStart_[cell]; s < cellStart_[cell + 1]; ++s) {
    const std::size_t i = static_cast<std::size_t>(sortedIndex_[s]);
    if (i < first || i >= last) continue;
    std::int64_t hits = 0;
    std::int64_t* __restrict out = scratch.data();
    double* __restrict dist = d2.data();
    for (const CandidateRange& r : ranges) {
      const double qx = sx[s] - r.shift[0], qy = sy[s] - r.shift[1], qz = sz[s] - r.shift[2];
      const std::int64_t begin = r.begin, len = r.end - r.begin;
      const double* __restrict x = sx + begin;
      const double* __restrict y = sy + begin;
      const double* __restrict z = sz + begin;
      for (std::int64_t c = 0; c < len; ++c) {
        const double dx = qx - x[c], dy = qy - y[c], dz = qz - z[c];
        dist[c] = dx * dx + dy * dy + dz * dz;
      }
      for (std::int64_t c = 0; c < len; ++c) {
        out[hits] = begin + c;
        hits += dist[c] < r2;
      }
    }
    const std::size_t before = indices.size();
    for (std::int64_t h = 0; h < hits; ++h) {
      if (out[h] == s) continue;
      const int j = sortedIndex_[out[h]];
      if (static_cast<std::size_t>(j) < maxNeighbor) indices.push_back(j);
    }
    counts.push_back(static_cast<std::int64_t>(indices.size() - before));
    rowQueries.push_back(static_cast<int>(i - first));
  }
}

// Cells are split into one contiguous block per thread (equal numbers of points); each block
// writes its rows to its own buffers, which are concatenated in block order.
void UniformGridNeighborSearch::neighborLists(std::size_t first, std::size_t last, double radius,
                                              NeighborLists& out,
                                              std::size_t maxNeighbor) const {
  if (first > last || last > points_.size())
    throw std::invalid_argument("UniformGridNeighborSearch::neighborLists: bad query range");
  const std::int64_t cells = static_cast<std::int64_t>(cellStart_.size()) - 1;
  const std::int64_t n = static_cast<std::int64_t>(points_.size());
  std::vector<unsigned char> interesting;
  if (maxNeighbor < points_.size()) {
    interesting.assign(cells, 0);
    for (std::int64_t c = 0; c < cells; ++c)
      for (std::int64_t s = cellStart_[c]; s < cellStart_[c + 1] && !interesting[c]; ++s)
        interesting[c] = static_cast<std::size_t>(sortedIndex_[s]) < maxNeighbor;
  }
  const int threads = (last - first) >= static_cast<std::size_t>(kParallelMinItems)
                          ? omp_get_max_threads() : 1;
  struct Block {
    std::vector<int> indices, rowQueries;
    std::vector<std::int64_t> counts;
  };
  std::vector<Block> blocks(threads);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    auto cellAtSlot = [&](std::int64_t slot) {
      return static_cast<std::int64_t>(
          std::upper_bound(cellStart_.begin(), cellStart_.end(), slot) - cellStart_.begin() - 1);
    };
    const std::int64_t c0 = t == 0 ? 0 : cellAtSlot(n * t / nt);
    const std::int64_t c1 = t == nt - 1 ? cells : cellAtSlot(n * (t + 1) / nt);
    Block& b = blocks[t];
    b.indices.reserve(static_cast<std::size_t>((last - first) / nt + 1) * 48);
    std::vector<CandidateRange> ranges;
    std::vector<std::int64_t> scratch;
    for (std::int64_t c = c0; c < c1; ++c) {
      if (cellStart_[c] == cellStart_[c + 1]) continue;
      const std::int64_t cx = c % n_[0], cy = (c / n_[0]) % n_[1], cz = c / (std::int64_t(n_[0]) * n_[1]);
      candidateRanges({int(cx), int(cy), int(cz)}, radius, interesting.empty() ? nullptr : &interesting,
                      ranges);
      listCellQueries(c, first, last, radius, maxNeighbor, ranges, b.indices, b.counts,
                      b.rowQueries, scratch);
    }
  }
  std::size_t rows = 0, total = 0;
  for (const Block& b : blocks) rows += b.counts.size(), total += b.indices.size();
  out.offsets.assign(rows + 1, 0);
  out.indices.resize(total);
  out.rowOfQuery.assign(last - first, -1);
  std::size_t r = 0, at = 0;
  for (const Block& b : blocks) {
    std::copy(b.indices.begin(), b.indices.end(), out.indices.begin() + at);
    for (std::size_t k = 0; k < b.counts.size(); ++k, ++r) {
      out.offsets[r + 1] = out.offsets[r] + b.counts[k];
      out.rowOfQuery[b.rowQueries[k]] = static_cast<int>(r);
    }
    at += b.indices.size();
  }
}

}  // namespace fluidviz::sph
