#pragma once
// Per-node kernel functions are forced inline so that each instruction-set clone of the row
// kernel (LbmSolverImpl.cpp, target_clones) compiles its own copy of them with wide vectors.
#if defined(__GNUC__)
#define FLUIDVIZ_LBM_INLINE inline __attribute__((always_inline))
#else
#define FLUIDVIZ_LBM_INLINE inline
#endif
