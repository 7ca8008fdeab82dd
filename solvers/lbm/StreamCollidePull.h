#pragma once
// The fused LBM time step in the pull scheme (Wittmann et al. 2013, "Comparison of different
// propagation steps for lattice Boltzmann methods", Comput. Math. Appl. 65(6)): each node gathers
// its incoming populations f_q(n - c_q) from the post-collision array of the previous step
// (streaming), then collides and writes to the other array. One read and one write per
// population per step: the minimum traffic of a two-array scheme (144 bytes per D2Q9 node in
// double precision, not counting write-allocate).
#include <algorithm>
#include <cstdint>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "solvers/lbm/BoundaryLinkTable.h"
#include "solvers/lbm/KernelInline.h"

namespace fluidviz::lbm {

/// `count` consecutive bulk nodes from node `first`: population q of node first + i is pulled
/// from post[source[q] + first + i] and written, after collision, to out[q * outStride + i].
/// Fixed offsets, no branches per direction, unit stride in every plane, so the compiler
/// vectorises across nodes. (`ivdep` + `__restrict` rather than `omp simd`: with the latter
/// GCC 12 keeps f[] in memory and does not vectorise; the q loops must be fully unrolled.)
template <class L, class Collision, bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideBulkNodes(const double* __restrict post,
                                                const std::int64_t (&source)[L::Q],
                                                std::int64_t first, std::int64_t count,
                                                double* __restrict out, std::int64_t outStride,
                                                const Collision& collision) {
  std::int64_t src[L::Q];  // local copy: lives in registers after unrolling
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) src[q] = source[q] + first;
  const Collision c = collision;
#pragma GCC ivdep
  for (std::int64_t i = 0; i < count; ++i) {
    double f[L::Q];
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) f[q] = post[src[q] + i];
    c.template collide<L, Forced>(f);
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) out[q * outStride + i] = f[q];
  }
}

/// Where plane q of a bulk node n is pulled from: q * stride - (c_qx + c_qy nx) (+ n).
template <class L>
FLUIDVIZ_LBM_INLINE void bulkSources(std::int64_t stride, const std::int64_t (&offset)[L::Q],
                                     std::int64_t (&source)[L::Q]) {
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) source[q] = q * stride - offset[q];
}

/// A run of bulk nodes, results stored normally (they stay in cache for the next step).
template <class L, class Collision, bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideBulkRun(const double* __restrict post,
                                              double* __restrict next, std::int64_t stride,
                                              const std::int64_t (&offset)[L::Q], BulkRun run,
                                              const Collision& collision) {
  std::int64_t source[L::Q];
  bulkSources<L>(stride, offset, source);
  streamCollideBulkNodes<L, Collision, Forced>(post, source, run.begin, run.end - run.begin,
                                               next + run.begin, stride, collision);
}

/// A run of bulk nodes whose results go to memory with non-temporal (streaming) stores. For
/// lattices larger than the cache this removes the write-allocate read of every written line
/// (216 -> 144 bytes of traffic per node) and keeps 9 write streams from competing with the 9
/// read streams for the cache; see lbm_bench. Chunks of nodes are collided into an L1 buffer
/// first, because GCC does not emit streaming stores from vectorised loops. Requires the planes
/// to be 16-byte aligned (PopulationArrays). Callers issue _mm_sfence() before the next step.
template <class L, class Collision, bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideBulkRunStreaming(const double* __restrict post,
                                                       double* __restrict next,
                                                       std::int64_t stride,
                                                       const std::int64_t (&offset)[L::Q],
                                                       BulkRun run, const Collision& collision) {
#if defined(__SSE2__)
  constexpr std::int64_t kChunk = 64;  // 9 x 64 doubles = 4.5 KiB, stays in L1
  alignas(64) double buffer[L::Q * kChunk];
  std::int64_t source[L::Q];
  bulkSources<L>(stride, offset, source);
  std::int64_t n = run.begin;
  if (n % 2 != 0) {  // odd start: one node with normal stores, then 16-byte aligned pairs
    streamCollideBulkNodes<L, Collision, Forced>(post, source, n, 1, next + n, stride, collision);
    ++n;
  }
  while (run.end - n >= 2) {
    const std::int64_t count = std::min<std::int64_t>(kChunk, (run.end - n) & ~std::int64_t(1));
    streamCollideBulkNodes<L, Collision, Forced>(post, source, n, count, buffer, kChunk,
                                                 collision);
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q)
      for (std::int64_t i = 0; i < count; i += 2)
        _mm_stream_pd(next + q * stride + n + i, _mm_load_pd(buffer + q * kChunk + i));
    n += count;
  }
  if (n < run.end)
    streamCollideBulkNodes<L, Collision, Forced>(post, source, n, 1, next + n, stride, collision);
#else
  streamCollideBulkRun<L, Collision, Forced>(post, next, stride, offset, run, collision);
#endif
}

/// A boundary node: populations come through its precomputed PullLinks.
template <class L, class Collision, bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideBoundaryNode(const double* __restrict post, double* __restrict next,
                                      std::int64_t stride, const BoundaryNode& b,
                                      const Collision& collision) {
  double f[L::Q];
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) f[q] = post[b.links[q].source] + b.links[q].delta;
  collision.template collide<L, Forced>(f);
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) next[q * stride + b.node] = f[q];
}

/// Pre-collision populations of every fluid node of row j (the gather half of the step, without
/// collision): visit(node, f). Used for moments, mass and diagnostics.
template <class L, class Visit>
inline void gatherRow(const BoundaryLinkTable& table, const double* post, int j, Visit&& visit) {
  const RowPlan& row = table.rows()[j];
  const std::int64_t stride = table.stride();
  double f[L::Q];
  for (std::int64_t r = row.runBegin; r < row.runEnd; ++r)
    for (std::int64_t n = table.runs()[r].begin; n < table.runs()[r].end; ++n) {
#pragma GCC unroll 32
      for (int q = 0; q < L::Q; ++q) f[q] = post[q * stride + n - table.bulkOffset(q)];
      visit(n, static_cast<const double*>(f));
    }
  for (std::int64_t b = row.boundaryBegin; b < row.boundaryEnd; ++b) {
    const BoundaryNode& node = table.boundaryNodes()[b];
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) f[q] = post[node.links[q].source] + node.links[q].delta;
    visit(node.node, static_cast<const double*>(f));
  }
}

}  // namespace fluidviz::lbm
