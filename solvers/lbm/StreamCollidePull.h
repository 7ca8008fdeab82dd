#pragma once
// The fused LBM time step in the pull scheme (Wittmann et al. 2013, "Comparison of different
// propagation steps for lattice Boltzmann methods", Comput. Math. Appl. 65(6)): each node gathers
// its incoming populations f_q(n - c_q) from the post-collision array of the previous step
// (streaming), then collides and writes to the other array. One read and one write per
// population per step: the minimum traffic of a two-array scheme (144 bytes per D2Q9 node in
// double precision, not counting write-allocate).
#include <cstdint>

#include "solvers/lbm/BoundaryLinkTable.h"
#include "solvers/lbm/KernelInline.h"

namespace fluidviz::lbm {

/// Bulk nodes [run.begin, run.end): fixed neighbour offsets, no branches per direction, unit
/// stride in every plane, so the compiler vectorises across nodes. (`ivdep` + `__restrict`
/// rather than `omp simd`: with the latter GCC 12 keeps f[] in memory and does not vectorise;
/// the q loops must be fully unrolled for the node loop to vectorise.)
template <class L, class Collision, bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideBulkRun(const double* __restrict post,
                                              double* __restrict next, std::int64_t stride,
                                              const std::int64_t (&offset)[L::Q], BulkRun run,
                                              const Collision& collision) {
  // Plane offsets in a local array whose address does not escape: after unrolling over q they
  // live in registers and the node loop has only unit-stride accesses.
  std::int64_t source[L::Q];
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) source[q] = q * stride - offset[q];
  const Collision c = collision;
#pragma GCC ivdep
  for (std::int64_t n = run.begin; n < run.end; ++n) {
    double f[L::Q];
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) f[q] = post[source[q] + n];
    c.template collide<L, Forced>(f);
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) next[q * stride + n] = f[q];
  }
}

/// A boundary node: populations come through its precomputed PullLinks.
template <class L, class Collision, bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideBoundaryNode(const double* __restrict post,
                                                   double* __restrict next, std::int64_t stride,
                                                   const BoundaryNode& b,
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
