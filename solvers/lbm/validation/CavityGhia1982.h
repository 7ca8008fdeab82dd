#pragma once
// Lid-driven square cavity against Ghia, Ghia & Shin (1982), shared by the validation test
// (tests/solvers/lbm/LidDrivenCavity_test.cpp) and the trade-off bench (bench/lbm_tradeoff.cpp).
//
// Tables I and II: u on the vertical centreline x = 0.5 and v on the horizontal centreline
// y = 0.5 of the unit cavity with the lid y = 1 moving in +x, normalised by the lid speed. The
// table rows on the walls (y = 0, 1 and x = 0, 1) are boundary values, not results: they are
// left out. The solver's node-centred field is sampled bilinearly at the table's positions.
//
// Reference: U. Ghia, K. N. Ghia, C. T. Shin, "High-Re solutions for incompressible flow using
// the Navier-Stokes equations and a multigrid method", J. Comput. Phys. 48 (1982) 387-411.
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"

namespace fluidviz::lbm {

struct GhiaPoint {
  double position = 0.0;  ///< y (u table) or x (v table), in (0, 1)
  double re100 = 0.0;     ///< velocity / lid speed at Re 100
};

/// The interior rows of one of Ghia's tables from its CSV ("position,Re100,Re400" after '#'
/// comments and one header line). Throws std::runtime_error naming the file when it cannot be
/// read or holds no interior row.
std::vector<GhiaPoint> readGhiaCentreline(const std::string& file);

/// RMS of |u / lid - table| (and of v) that a Re 100 cavity of 64^2 nodes or more stays below
/// (measured 0.002-0.0035, LidDrivenCavity_test.cpp): the tolerance of the Ghia comparisons.
inline constexpr double kGhiaRmsTolerance = 0.02;

struct GhiaComparison {
  double uRms = 0, uMax = 0;  ///< |u / lid - table| on the vertical centreline
  double vRms = 0, vMax = 0;  ///< |v / lid - table| on the horizontal centreline
  double rms = 0;             ///< over both tables' points together
};

/// Differences of `velocity` (unit cavity, lid speed `lid`) to the Re 100 columns of the u and
/// v tables. Throws std::invalid_argument if a table point lies outside the field's grid.
GhiaComparison compareWithGhia(const VectorField& velocity, double lid,
                               const std::vector<GhiaPoint>& uTable,
                               const std::vector<GhiaPoint>& vTable);

}  // namespace fluidviz::lbm
