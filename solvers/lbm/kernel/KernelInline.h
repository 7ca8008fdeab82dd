#pragma once
// Per-node kernel functions are forced inline so that each instruction-set copy of the row
// kernel (LbmSolverImpl.cpp) compiles its own copy of them with wide vectors.
#include "fieldviz/core/IsaLevel.h"

#define FLUIDVIZ_LBM_INLINE FLUIDVIZ_ALWAYS_INLINE
