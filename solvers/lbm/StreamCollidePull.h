#pragma once
// The fused LBM time step in the pull scheme (Wittmann et al. 2013, "Comparison of different
// propagation steps for lattice Boltzmann methods", Comput. Math. Appl. 65(6)): each node gathers
// its incoming populations f_q(n - c_q) from the post-collision array of the previous step
// (streaming), then collides and writes to the other array. One read and one write per
// population per step: the minimum traffic of a two-array scheme (2 Q sizeof(T) bytes per node:
// 144 B for D2Q9 and 304 B for D3Q19 in double, half in float; write-allocate not counted).
#include <cstdint>

#include "solvers/lbm/BoundaryLinkTable.h"
#include "solvers/lbm/KernelInline.h"
#include "solvers/lbm/ZouHePressureOutlet.h"
#include "solvers/lbm/ZouHeVelocityInlet.h"

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

/// The nodes [run.begin, run.end) of a run: fixed source offsets (RunPattern), no branches per
/// direction, unit stride in every plane, so the compiler vectorises across nodes. (`ivdep` +
/// `__restrict` rather than `omp simd`: with the latter GCC 12 keeps f[] in memory and does not
/// vectorise; the q loops must be fully unrolled for the node loop to vectorise.) WithDelta: the
/// pattern adds moving-wall momentum (rows along a moving wall).
template <class L, class T, class Collision, bool Forced, bool WithDelta>
FLUIDVIZ_LBM_INLINE void streamCollideRun(const T* __restrict post, T* __restrict next,
                                          std::int64_t stride, const RunPattern<L::Q>& pattern,
                                          BulkRun run, const Collision& collision) {
  // Offsets in local arrays whose address does not escape: after unrolling over q they live in
  // registers (or are rematerialised) and the node loop has only unit-stride accesses.
  std::int64_t source[L::Q];
  T delta[L::Q];
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) {
    source[q] = pattern.source[q];
    delta[q] = WithDelta ? T(pattern.delta[q]) : T(0);
  }
  const Collision c = collision;
#pragma GCC ivdep
  for (std::int64_t n = run.begin; n < run.end; ++n) {
    T f[L::Q];
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) {
      f[q] = post[source[q] + n];
      if constexpr (WithDelta) f[q] += delta[q];
    }
    c.template collide<L, Forced, T>(f);
#pragma GCC unroll 32
    for (int q = 0; q < L::Q; ++q) next[q * stride + n] = f[q];
  }
}

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
      zouHeVelocity<L, T>(f, rule.geometry, T(rule.velocity[0]), T(rule.velocity[1]),
                          T(rule.velocity[2]), data.gx, data.gy, data.gz);
  }
}

/// A boundary node: gather, collide, store.
template <class L, class T, class Collision, bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideBoundaryNode(const T* __restrict post, T* __restrict next,
                                                   std::int64_t stride,
                                                   const BoundaryNode<L::Q>& b,
                                                   const BoundaryGatherData<T>& data,
                                                   const Collision& collision) {
  T f[L::Q];
  gatherBoundaryNode<L, T>(post, b, data, f);
  collision.template collide<L, Forced, T>(f);
#pragma GCC unroll 32
  for (int q = 0; q < L::Q; ++q) next[q * stride + b.node] = f[q];
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
