#pragma once
// The fused LBM time step in the pull scheme (Wittmann et al. 2013, "Comparison of different
// propagation steps for lattice Boltzmann methods", Comput. Math. Appl. 65(6)): each node gathers
// its incoming populations f_q(n - c_q) from the post-collision array of the previous step
// (streaming), then collides and writes to the other array. One read and one write per
// population per step: the minimum traffic of a two-array scheme (2 Q sizeof(T) bytes per node:
// 144 B for D2Q9 and 304 B for D3Q19 in double, half in float), which the streaming stores of
// streamCollideNodes achieve (no write-allocate read of the destination).
// ReferenceStreamCollide.h is the same step written as the equations, with plain loops; the test
// tests/solvers/lbm/ReferenceStep_test.cpp holds the two equal to round-off.
#include <algorithm>
#include <cstdint>

#include "solvers/lbm/boundaries/ZouHePressureOutlet.h"
#include "solvers/lbm/boundaries/ZouHeVelocityInlet.h"
#include "solvers/lbm/kernel/BoundaryLinkTable.h"
#include "solvers/lbm/kernel/KernelInline.h"
#include "solvers/lbm/kernel/LineVector.h"

namespace fluidviz::lbm {

/// The open sides in the form the kernel uses (lattice units).
struct OpenSideRule {
  OpenSideGeometry geometry;
  bool pressure = false;
  double velocity[3] = {0.0, 0.0, 0.0};  ///< velocity inlet
  double drho = 0.0;                     ///< pressure side: rho - 1
};

/// Everything the boundary-node gather needs besides the node itself.
template <class T>
struct BoundaryGatherData {
  const InterpolatedLink* interpolated = nullptr;
  const OpenSideRule* open = nullptr;  ///< 6 sides, indexed like BoxSides
  T gx = 0, gy = 0, gz = 0;            ///< lattice body acceleration (Zou-He momentum shift)
};

/// Incoming (pre-collision) populations of a boundary node: its PullLinks, then the Bouzidi
/// interpolations that replace some of them, then the Zou-He closure of an open side.
template <class L, class T>
inline void gatherBoundaryNode(const T* post, const BoundaryNode<L::Q>& b,
                               const BoundaryGatherData<T>& data, T* f) {
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) f[q] = post[b.links[q].source] + T(b.links[q].delta);
  for (std::int32_t k = b.interpolatedBegin; k < b.interpolatedEnd; ++k) {
    const InterpolatedLink& l = data.interpolated[k];
    const T halfway = f[l.q];  // the staircase (halfway bounce-back) value of this link
    f[l.q] = T(l.w1) * post[l.s1] + T(l.w2) * post[l.s2] + T(l.delta);
    f[0] += halfway - f[l.q];  // mass correction (BouzidiInterpolatedBounceBack.h)
  }
  if (b.openSide >= 0) {
    const OpenSideRule& rule = data.open[b.openSide];
    if (rule.pressure)
      zouHePressure<L, T>(f, rule.geometry, T(rule.drho), data.gx, data.gy, data.gz);
    else
      zouHeVelocity<L, T>(f, rule.geometry, T(rule.velocity[0] * b.inletFactor),
                          T(rule.velocity[1] * b.inletFactor), T(rule.velocity[2] * b.inletFactor),
                          data.gx, data.gy, data.gz);
  }
}

/// Everything the line kernel reads besides the two arrays' contents: the table of one step.
template <class L, class T>
struct StepTables {
  std::int64_t stride;                ///< values between planes (both arrays)
  const BulkRun* runs;                ///< sorted by node (BoundaryLinkTable)
  const RunPattern<L::Q>* patterns;
  const BoundaryNode<L::Q>* boundary;  ///< sorted by node
  BoundaryGatherData<T> gather;
  /// How far ahead (nodes) a mixed line prefetches its runs' sources: whole rows, so that the
  /// address is the same line of a later row, which has the same runs away from bodies
  /// (mixedLinePrefetchNodes).
  std::int64_t mixedPrefetch;
};

/// The nodes [begin, end) of one thread, with the runs [runBegin, runEnd) and boundary nodes
/// [boundaryBegin, boundaryEnd) that lie in it.
struct NodeRange {
  std::int64_t begin, end;
  std::int64_t runBegin, runEnd;
  std::int64_t boundaryBegin, boundaryEnd;
};

/// How far ahead (in nodes) streamCollideNodes prefetches its sources: measured best for D3Q19
/// 128^3 on 1 thread (lbm_bench-like A/B runs): 24 lines in double and 12 in float, both 192
/// nodes (1.5 KB resp. 768 B per plane); 4 lines were 12-16 % slower.
inline constexpr int kPrefetchNodes = 192;

/// The prefetch distance of mixed lines: whole rows, about kPrefetchNodes. Why: a mixed line at
/// a wall pulls its bounce-back populations from a line that no bulk load of nearby rows has
/// touched yet (the outgoing populations of the wall node; the bulk reads that line one plane
/// later), so without a prefetch every such line waits for memory. D3Q19 float with x walls,
/// 1 thread (A/B): 48^3 73 -> 185 MLUPS, 128^3 160 -> 240, 200^3 220 -> 251; one row ahead at
/// 64^3 was 10 % slower than three.
inline std::int64_t mixedLinePrefetchNodes(int nx) {
  return std::int64_t(nx) * std::max(1, kPrefetchNodes / nx);
}

/// The prefetches of one link of a mixed line: kPrefetchNodes ahead like the bulk lines (the
/// prefetch streams of the bulk must go on through the row ends: without it each row had two
/// bulk lines nobody prefetched), and a reflected link also rows ahead (mixedLinePrefetchNodes).
template <class L, class T>
FLUIDVIZ_LBM_INLINE void prefetchMixedSource(const T* source, const RunPattern<L::Q>& p, int q,
                                             const StepTables<L, T>& t) {
  __builtin_prefetch(source + kPrefetchNodes);
  if (p.reflected >> q & 1) __builtin_prefetch(source + t.mixedPrefetch);
}

/// Pre-collision populations of the W nodes of the line starting at `line` that is NOT inside a
/// single run (the ends of rows): the first run overlapping [lo, hi) is loaded as a whole line
/// with its offsets, then the links in which each further run differs from it are blended into
/// that run's lanes, then the boundary nodes are gathered one by one (they are rare: bodies and
/// open sides). Lanes of solid nodes and of nodes outside [lo, hi) are 0 (the rest state; their
/// results are dropped or land in solid nodes, which nobody reads).
/// A run's line load also reads up to W - 1 values beyond its nodes' sources, which stay inside
/// the allocation: sources lie in [0, Q stride) (PullLink), and PopulationArrays allocates a
/// spare line after the last plane. Advances the boundary cursor `b`.
template <class L, class T>
inline void gatherMixedLine(const T* post, const StepTables<L, T>& t, const NodeRange& range,
                            std::int64_t line, std::int64_t lo, std::int64_t hi, std::int64_t k,
                            std::int64_t& b, LineOf<T>* f) {
  using V = LineOf<T>;
  constexpr int W = V::width;
  const RunPattern<L::Q>* base = nullptr;  // the first run, loaded for the whole line
  typename V::Mask covered{};                // lanes of the runs so far
  int coveredLanes = 0;
  for (; k < range.runEnd && t.runs[k].begin < hi; ++k) {
    const RunPattern<L::Q>& p = t.patterns[t.runs[k].pattern];
    const int from = static_cast<int>(std::max(lo, t.runs[k].begin) - line);
    const int to = static_cast<int>(std::min(hi, t.runs[k].end) - line);
    const typename V::Mask inside = V::lanes(from, to);
    covered |= inside;
    coveredLanes += to - from;
    if (!base) {
#pragma GCC unroll 32
      for (int q = 0; q < L::Q; ++q) prefetchMixedSource(post + p.source[q] + line, p, q, t);
#pragma GCC unroll 32
      for (int q = 0; q < L::Q; ++q) f[q] = V::load(post + p.source[q] + line);
      if (p.hasDelta)
#pragma GCC unroll 32
        for (int q = 0; q < L::Q; ++q) f[q] += V::broadcast(T(p.delta[q]));
      base = &p;
      continue;
    }
    // Only the links that differ from the first run's: the others already hold the right
    // values in these lanes (same offset, same delta). A wall or periodic run differs in the
    // Q/4 to Q/2 links that cross the side.
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) {
      if (p.source[q] == base->source[q] && p.delta[q] == base->delta[q]) continue;
      prefetchMixedSource(post + p.source[q] + line, p, q, t);
      f[q] = V::select(inside, V::load(post + p.source[q] + line) + V::broadcast(T(p.delta[q])), f[q]);
    }
  }
  if (coveredLanes < W)  // solid nodes, boundary nodes or the other thread's nodes: rest state
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) f[q] = V::keep(covered, base ? f[q] : V::broadcast(T(0)));
  if (b >= range.boundaryEnd || t.boundary[b].node >= hi) return;
  alignas(kCacheLineBytes) T lanes[L::Q][W];
  for (int q = 0; q < L::Q; ++q) f[q].store(lanes[q]);
  for (; b < range.boundaryEnd && t.boundary[b].node < hi; ++b) {
    T g[L::Q];
    gatherBoundaryNode<L, T>(post, t.boundary[b], t.gather, g);
    for (int q = 0; q < L::Q; ++q) lanes[q][t.boundary[b].node - line] = g[q];
  }
  for (int q = 0; q < L::Q; ++q) f[q] = V::load(lanes[q]);
}

/// The fused step for the nodes of one thread, a cache line of nodes (W = 8 doubles or 16
/// floats) at a time: pull the Q incoming populations of W nodes, collide them as W-wide vectors
/// (LineVector.h), write the Q result lines with streaming stores.
///
/// Why this shape (lbm_bench, 2-core Zen 5, D3Q19 128^3 double, a copy of the step's access
/// pattern without arithmetic, fraction of the streaming-store triad bandwidth): ordinary stores
/// 0.38-0.50, because every written line is first read (write-allocate: 3 Q instead of 2 Q values
/// moved) and the 2 Q = 38 concurrent streams defeat the prefetchers; full-line streaming stores
/// issued in the same interleaved order 0.80-0.88. Collecting a block of nodes in an L1 buffer
/// first and streaming it out plane by plane was worse (0.57-0.68), and so were 16-byte streaming
/// stores (0.53, the line is written back in pieces), so each line is stored whole, in one
/// instruction where the CPU has AVX-512. Stores must cover whole, aligned lines: the planes of
/// PopulationArrays are line-aligned, so node n starts a line in every plane iff n % W == 0.
/// Lines wholly inside one run (the bulk of every row) load with the run's fixed offsets; the few
/// other lines (the ends of rows, boundary nodes, bodies) blend their runs line-wise and gather
/// their boundary nodes node by node (gatherMixedLine). Lines shared with the neighbouring thread's range are stored lane by lane
/// with ordinary stores. The caller fences the streaming stores (fenceStreamingStores) before
/// the barrier that ends the step.

template <class Isa, class L, class T, class Collision, bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideNodes(const T* __restrict post, T* __restrict next,
                                            const StepTables<L, T>& t, const NodeRange& range,
                                            const Collision& collision) {
  using V = LineOf<T>;
  constexpr int W = V::width;
  const std::int64_t stride = t.stride;
  const Collision c = collision;
  std::int64_t k = range.runBegin, b = range.boundaryBegin;
  std::int64_t line = range.begin - range.begin % W;
  while (line < range.end) {
    const std::int64_t lo = std::max(line, range.begin), hi = std::min(line + W, range.end);
    while (k < range.runEnd && t.runs[k].end <= lo) ++k;
    V f[L::Q];
    if (k < range.runEnd && t.runs[k].begin <= line && t.runs[k].end >= line + W) {
      // A line inside one run: the run's offsets. Software prefetch in every source plane:
      // one line's collision is ~400 instructions, so the out-of-order window holds about one
      // line and would not reach the next line's loads before this line's are served (CPU-time
      // rate of the D3Q19 step, 1 thread: about half that of the plain copy without it).
      const RunPattern<L::Q>& p = t.patterns[t.runs[k].pattern];
#pragma GCC unroll 32
      for (int q = 0; q < L::Q; ++q) __builtin_prefetch(post + p.source[q] + line + kPrefetchNodes);
#pragma GCC unroll 32
      for (int q = 0; q < L::Q; ++q) f[q] = V::load(post + p.source[q] + line);
      if (p.hasDelta)
#pragma GCC unroll 32
        for (int q = 0; q < L::Q; ++q) f[q] += V::broadcast(T(p.delta[q]));
    } else {
      gatherMixedLine<L, T>(post, t, range, line, lo, hi, k, b, f);
    }
    c.template collide<L, Forced, V>(f);
    if (lo == line && hi == line + W) [[likely]] {
#pragma GCC unroll 32
      for (int q = 0; q < L::Q; ++q) Isa::streamLine(next + q * stride + line, f[q]);
    } else {  // shared with the neighbouring thread: only this thread's nodes
      for (int q = 0; q < L::Q; ++q) {
        alignas(kCacheLineBytes) T out[W];
        f[q].store(out);
        for (std::int64_t n = lo; n < hi; ++n) next[q * stride + n] = out[n - line];
      }
    }
    line += W;
  }
}

/// Pre-collision populations of every fluid node of row r (the gather half of the step, without
/// collision): visit(node, f). Used for moments, mass and diagnostics.
template <class L, class T, class Visit>
inline void gatherRow(const BoundaryLinkTable<L>& table, const BoundaryGatherData<T>& data,
                      const T* post, int r, Visit&& visit) {
  const RowPlan& row = table.rows()[r];
  T f[L::Q];
  for (std::int64_t k = row.runBegin; k < row.runEnd; ++k) {
    const BulkRun& run = table.runs()[k];
    const RunPattern<L::Q>& p = table.runPatterns()[run.pattern];
    for (std::int64_t n = run.begin; n < run.end; ++n) {
#pragma GCC unroll 32
      for (int q = 0; q < L::Q; ++q) f[q] = post[p.source[q] + n] + T(p.delta[q]);
      visit(n, static_cast<const T*>(f));
    }
  }
  for (std::int64_t b = row.boundaryBegin; b < row.boundaryEnd; ++b) {
    const auto& node = table.boundaryNodes()[b];
    gatherBoundaryNode<L, T>(post, node, data, f);
    visit(node.node, static_cast<const T*>(f));
  }
}

}  // namespace fluidviz::lbm
