#pragma once
// The 2D double-precision solver under its original name. New code: LbmSolver.h
// (createLbmSolver picks lattice and precision from the scene) or LbmSolverImpl.h.
#include "solvers/lbm/kernel/LbmSolverImpl.h"
