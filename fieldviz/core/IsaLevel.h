#pragma once
// Run-time choice of the x86-64 instruction-set level for hot loops compiled several times
// (GCC's target attribute): the libraries stay portable (x86-64-v2 baseline, no -march=native)
// yet use AVX2/FMA or AVX-512 where the CPU has them. Used by the LBM step kernel
// (solvers/lbm/kernel/LbmSolverImpl.cpp) and the SPH-to-grid scatter (filters/resample).
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__clang__)
#define FLUIDVIZ_MULTI_ISA 1
#endif

// Functions a multi-ISA kernel calls are forced inline, so that each instruction-set copy of
// the kernel compiles its own copy of them with wide vectors.
#if defined(__GNUC__)
#define FLUIDVIZ_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define FLUIDVIZ_ALWAYS_INLINE inline
#endif

namespace fluidviz {

/// The widest level the running CPU offers: 4 (x86-64-v4, AVX-512), 3 (x86-64-v3, AVX2 + FMA)
/// or 0 (the baseline the code was compiled for). The caller runs the matching copy, compiled
/// with __attribute__((target("arch=x86-64-v4"))) resp. "arch=x86-64-v3".
inline int bestIsaLevel() {
#if defined(FLUIDVIZ_MULTI_ISA)
  static const int level = [] {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("x86-64-v4")) return 4;
    if (__builtin_cpu_supports("x86-64-v3")) return 3;
    return 0;
  }();
  return level;
#else
  return 0;
#endif
}

}  // namespace fluidviz
