#pragma once
// Fixed-radius neighbour search on a uniform cell grid (the "linked cell" method of Hockney &
// Eastwood, here with a counting sort instead of linked lists, as in Green 2010).
//
// build() bins the points into cells of edge >= cellSize and sorts them by cell with a counting
// sort (O(N + cells); x fastest), keeping a copy of the positions in cell order (in double, and
// in float relative to the box corner) so that a query reads memory contiguously. Rebuild
// whenever the points move. forEachWithin / pointsWithin answer arbitrary points (a
// resampler's grid nodes) for any radius by visiting the (2k+1)^d cells around them, k =
// ceil(radius / cell edge). neighborLists, the per-step path of the solver, sweeps the cells in
// order; the queries of one cell share one set of candidate ranges (with x fastest, the 3 cells
// of a stencil row are one contiguous range: 9 ranges in 3D, 3 in 2D for cells of edge =
// radius), copied once per cell into one contiguous tile so that every query of the cell runs
// one loop of the same length (no mispredicted exits per range). Candidates are tested 16
// (AVX-512), 8 (AVX2) or 4 (SSE) at a time on the float copy, against thresholds widened by a
// bound of the float rounding error; only the rare candidates inside that band are decided by
// the exact double distance, so the lists are exactly those of the double test r^2 < radius^2. Hits go to the rows with a compress (AVX-512) or a lane
// permutation (AVX2), without branches. Each thread writes its rows into its own block of the
// lists, kept between calls (the lists are written once, never gathered). Cells of edge = radius
// measured fastest (sph_bench).
//
// Periodic axes wrap: the cell grid tiles [lower, upper) exactly and distances use the minimum
// image. Points outside the box along non-periodic axes are clamped into the border cells, so
// queries stay exact for them too (only slower if many are far outside).
//
// References:
//   R. W. Hockney, J. W. Eastwood, "Computer simulation using particles", McGraw-Hill 1981, 8-4.
//   S. Green, "Particle simulation using CUDA", NVIDIA whitepaper 2010 (cell sort).
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "fieldviz/core/Grid.h"

namespace fluidviz::particles {

/// Neighbours of many points: of(q) is query q's row. Each thread of the search writes the rows
/// of its share of the cells into its own block (kept between calls, so no page faults and no
/// copy into one array: the lists of a step are written once). Rows that are neighbours in
/// space are neighbours in memory; within a row the neighbours are in cell order.
/// Deterministic. Movable, not copyable (rows point into the blocks).
struct NeighborLists {
  struct Row {
    const int* begin = nullptr;
    std::int64_t count = 0;
  };
  std::vector<Row> rows;                ///< row of query q (q counted from the first query)
  std::vector<std::vector<int>> blocks;  ///< storage, one block per thread
  std::size_t pairs = 0;                 ///< total number of neighbours listed

  NeighborLists() = default;
  NeighborLists(NeighborLists&&) = default;
  NeighborLists& operator=(NeighborLists&&) = default;
  NeighborLists(const NeighborLists&) = delete;
  NeighborLists& operator=(const NeighborLists&) = delete;

  std::span<const int> of(std::size_t q) const {
    return {rows[q].begin, static_cast<std::size_t>(rows[q].count)};
  }
  std::size_t size() const { return rows.size(); }
};

class UniformGridNeighborSearch {
 public:
  /// Cells of edge >= cellSize (m, > 0) over the box [lower, upper] (m); in 2D the z extent is
  /// ignored. Periodic axes need at least 3 cells (upper - lower >= 3 cellSize). Throws
  /// std::invalid_argument otherwise.
  UniformGridNeighborSearch(int dimension, const Vec3& lower, const Vec3& upper, double cellSize,
                            std::array<bool, 3> periodic = {false, false, false});

  /// Bins and sorts the points (kept by reference: they must outlive the queries and not move).
  void build(std::span<const Vec3> points);

  /// Calls f(j, d, r2) for every built point j with r2 = |d|^2 < radius^2, d = x - x_j (minimum
  /// image on periodic axes). radius must be < half the period on periodic axes.
  template <class F>
  void forEachWithin(const Vec3& x, double radius, F&& f) const;

  /// Indices of the built points within `radius` of x (appended to out after clearing it).
  void pointsWithin(const Vec3& x, double radius, std::vector<int>& out) const;

  /// Neighbour lists of the first `queryCount` built points (each point's own index excluded),
  /// within `radius`; parallel (OpenMP), deterministic.
  void neighborLists(std::size_t queryCount, double radius, NeighborLists& out) const {
    neighborLists(0, queryCount, radius, out);
  }
  /// The same for the built points first .. last-1 (of(k) lists point first + k); only
  /// neighbours j with j < maxNeighbor are kept, and queries whose cells have no such point
  /// nearby are skipped quickly (wall particles far from any fluid).
  /// Traverses the cells in order with, per cell, one set of candidate ranges pruned to the
  /// cells that can hold points within `radius`. Not safe to call concurrently on one object
  /// (it reuses its per-thread row buffers between calls).
  void neighborLists(std::size_t first, std::size_t last, double radius, NeighborLists& out,
                     std::size_t maxNeighbor = static_cast<std::size_t>(-1)) const;

  /// a - b with the minimum image on periodic axes (exact for |a - b| < 1.5 periods, e.g.
  /// points wrapped into the box; beyond that the nearest image is found by rounding).
  Vec3 displacement(const Vec3& a, const Vec3& b) const {
    Vec3 d = a - b;
    if (!anyPeriodic_) return d;
    for (int k = 0; k < dim_; ++k) {
      if (!periodic_[k]) continue;
      const double L = period_[k];
      if (d[k] > 0.5 * L)
        d[k] -= L;
      else if (d[k] < -0.5 * L)
        d[k] += L;
      if (std::abs(d[k]) > 0.5 * L) d[k] -= L * std::nearbyint(d[k] / L);
    }
    return d;
  }
  /// Brings a point into [lower, upper) along the periodic axes.
  Vec3 wrap(Vec3 x) const {
    for (int k = 0; k < dim_; ++k)
      if (periodic_[k]) x[k] -= period_[k] * std::floor((x[k] - lower_[k]) / period_[k]);
    return x;
  }

  int dimension() const { return dim_; }
  const std::array<int, 3>& cellCounts() const { return n_; }
  const Vec3& cellEdge() const { return edge_; }
  std::size_t size() const { return points_.size(); }

 private:
  [[noreturn]] void throwRadiusTooLarge(double radius, int axis) const;
  int cellCoord(double x, int axis) const {
    int c = static_cast<int>(std::floor((x - lower_[axis]) * invEdge_[axis]));
    if (periodic_[axis]) return ((c % n_[axis]) + n_[axis]) % n_[axis];
    return c < 0 ? 0 : (c >= n_[axis] ? n_[axis] - 1 : c);
  }
  std::int64_t cellIndex(int cx, int cy, int cz) const {
    return (static_cast<std::int64_t>(cz) * n_[1] + cy) * n_[0] + cx;
  }
  // Visits the sorted range of cells [cx0, cx1] in row (cy, cz); handles wrap-around in x.
  template <class F>
  void visitRow(int cx0, int cx1, int cy, int cz, const Vec3& x, double r2max, F& f) const;

  int dim_;
  Vec3 lower_, upper_, edge_, invEdge_, period_;
  std::array<bool, 3> periodic_;
  bool anyPeriodic_ = false;
  std::array<int, 3> n_{1, 1, 1};
  std::span<const Vec3> points_;
  // A contiguous run of sorted slots to test against a query, and the periodic image shift of
  // its points (added to their positions).
  struct CandidateRange {
    std::int64_t begin, end;
    Vec3 shift;
  };
  struct StencilRow {
    int dy, dz, m;  ///< row offset from the query cell; x run from -m to +m
  };
  std::vector<StencilRow> stencilRows(double radius) const;
  void candidateRanges(const std::array<int, 3>& cell, const std::vector<StencilRow>& rows,
                       const std::vector<unsigned char>* interesting,
                       std::vector<CandidateRange>& out) const;
  // The candidates of one cell's ranges, copied into one contiguous run so that each query
  // scans them in one loop (of the same length for every query of the cell): float
  // coordinates (box-relative, with the range's shift) and original indices, padded by
  // kFloatPadding zeros for vector loads; per range its start in the tile, its first sorted
  // slot and its shift (for the exact test of the rare candidates in the rounding band).
  struct CandidateTile {
    std::vector<float> x, y, z;
    std::vector<int> index;
    std::vector<std::int64_t> rangeStart;  ///< size ranges + 1
    std::vector<std::int64_t> rangeSlot;
    std::vector<Vec3> rangeShift;
    std::int64_t ownCell = -1;  ///< tile position of the query cell's first point, or -1
  };
  void fillTile(const std::vector<CandidateRange>& ranges, std::int64_t ownSlot,
                CandidateTile& tile) const;
  // One thread's rows in neighborLists: the queries and lengths in order, the block (owned by
  // the lists) they are written to, and the thread's candidate tile. Cache-line aligned: the
  // threads update their own blocks all the time (no false sharing).
  struct alignas(64) RowBlock {
    CandidateTile tile;
    std::vector<int>* indices = nullptr;
    std::vector<int> rowQueries;
    std::vector<std::int64_t> counts;
    std::size_t used = 0;  ///< valid entries of *indices
  };
  void listCellQueries(std::int64_t cell, std::size_t first, std::size_t last, double radius,
                       std::size_t maxNeighbor, float inner, float outer,
                       const std::vector<CandidateRange>& ranges, RowBlock& block) const;

  std::vector<std::int64_t> cellStart_;  ///< size cells + 1: sorted range of each cell
  std::vector<int> sortedIndex_;         ///< original index of each sorted slot
  std::vector<Vec3> sortedPoints_;       ///< positions in sorted order (wrapped on periodic axes)
  /// The same in float, relative to lower_, one array per axis (copied into the tiles).
  std::vector<float> floatX_, floatY_, floatZ_;
  double floatExtent_ = 0.0;  ///< bound of |float coordinate| (+ a period): rounding error scale
  bool scanZ_ = true;         ///< z enters distances (3D, or 2D points with z != 0)
  std::vector<std::int64_t> cellOfPoint_;
  mutable std::vector<RowBlock> rowBlocks_;  ///< neighborLists scratch (not thread-safe)
};

template <class F>
void UniformGridNeighborSearch::visitRow(int cx0, int cx1, int cy, int cz, const Vec3& x,
                                         double r2max, F& f) const {
  auto visitRange = [&](int a, int b) {
    const std::int64_t begin = cellStart_[cellIndex(a, cy, cz)];
    const std::int64_t end = cellStart_[cellIndex(b, cy, cz) + 1];
    for (std::int64_t s = begin; s < end; ++s) {
      const Vec3 d = anyPeriodic_ ? displacement(x, sortedPoints_[s]) : Vec3(x - sortedPoints_[s]);
      const double r2 = d.squaredNorm();
      if (r2 < r2max) f(sortedIndex_[s], d, r2);
    }
  };
  if (!periodic_[0] || (cx0 >= 0 && cx1 < n_[0])) {
    visitRange(cx0, cx1);
  } else {  // wraps: visit cell by cell
    for (int c = cx0; c <= cx1; ++c) {
      const int w = ((c % n_[0]) + n_[0]) % n_[0];
      visitRange(w, w);
    }
  }
}

template <class F>
void UniformGridNeighborSearch::forEachWithin(const Vec3& x, double radius, F&& f) const {
  std::array<int, 3> c{0, 0, 0}, k{0, 0, 0};
  for (int a = 0; a < dim_; ++a) {
    c[a] = cellCoord(x[a], a);
    k[a] = static_cast<int>(std::ceil(radius * invEdge_[a]));
  }
  const double r2max = radius * radius;
  auto axisRange = [&](int a, int& lo, int& hi) {
    lo = c[a] - k[a];
    hi = c[a] + k[a];
    if (!periodic_[a]) {
      lo = lo < 0 ? 0 : lo;
      hi = hi >= n_[a] ? n_[a] - 1 : hi;
    } else if (2 * k[a] + 1 > n_[a]) {
      throwRadiusTooLarge(radius, a);
    }
  };
  int x0, x1, y0, y1, z0 = 0, z1 = 0;
  axisRange(0, x0, x1);
  axisRange(1, y0, y1);
  if (dim_ == 3) axisRange(2, z0, z1);
  for (int cz = z0; cz <= z1; ++cz) {
    const int wz = periodic_[2] ? ((cz % n_[2]) + n_[2]) % n_[2] : cz;
    for (int cy = y0; cy <= y1; ++cy) {
      const int wy = periodic_[1] ? ((cy % n_[1]) + n_[1]) % n_[1] : cy;
      visitRow(x0, x1, wy, wz, x, r2max, f);
    }
  }
}

}  // namespace fluidviz::particles
