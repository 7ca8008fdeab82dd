#pragma once
// Surge front of a collapsing water column (dam break) against Martin & Moyce (1952), shared by
// the validation test (tests/solvers/sph/DamBreak_test.cpp) and the trade-off bench
// (bench/sph_tradeoff.cpp).
//
// Geometry: column a wide and 2a high at the left wall (x = 0) of a tank with a floor at y = 0.
// Front Z = (x_front + dx/2) / a against T = t sqrt(2 g / a). The front is that of the water
// body: the largest x of a particle with at least two others within 1.5 dx (isolated spray drops
// are not counted); Ritter's dry-bed solution bounds every particle, spray included:
// Z < 1 + 2 T. Simulated T is shifted by +0.175 before the comparison (the time the gate took to
// open in the experiment, see the data file's header).
//
// References:
//   J. C. Martin, W. J. Moyce, "An experimental study of the collapse of liquid columns on a
//   rigid horizontal plane", Phil. Trans. R. Soc. Lond. A 244 (1952) 312-324.
//   A. Ritter, "Die Fortpflanzung der Wasserwellen", Z. Ver. Deutsch. Ing. 36 (1892) 947-954.
#include <string>
#include <utility>
#include <vector>

#include "fieldviz/core/Grid.h"

namespace fluidviz::sph {

class SphSolver;

struct SurgeFrontPoint {
  double T = 0.0, Z = 0.0;  ///< dimensionless time and front position
};

/// Martin & Moyce's (T, Z) points from their CSV (lines "T,Z"; '#' comments, a header line
/// starting with 'T'). Throws std::runtime_error naming the file when it cannot be read or holds
/// no point.
std::vector<SurgeFrontPoint> readMartinMoyce(const std::string& file);

/// Z at T on a curve sorted by T, linear between points, constant beyond the ends.
double interpolateFront(const std::vector<SurgeFrontPoint>& curve, double T);

/// T the experiment's gate took to open (the data file's header): simulated T + this is
/// compared with the data.
inline constexpr double kGateOpeningT = 0.175;

/// max |Z_sim(T - kGateOpeningT) - Z_data(T)| over the data points with T <= Tmax, Z_sim
/// interpolated on `simulated` (sorted by T).
double maxFrontDeviation(const std::vector<SurgeFrontPoint>& simulated,
                         const std::vector<SurgeFrontPoint>& data, double Tmax);

/// {body front, furthest particle}: the largest x of a particle with at least two others within
/// 1.5 dx, and the largest x of any particle.
std::pair<double, double> surgeFrontPositions(const std::vector<Vec3>& x, double dx);

/// The body front of particles `x` (spacing dx) at time t of a column of width a at x = 0
/// under gravity g, dimensionless: T = t sqrt(2 g / a), Z = (x_front + dx/2) / a.
SurgeFrontPoint dimensionlessFront(const std::vector<Vec3>& x, double dx, double a, double g,
                                   double t);

struct SurgeFrontComparison {
  double maxError = 0.0;          ///< max |Z_sim(T - 0.175) - Z_MM(T)| over the data, T <= Tmax
  double maxRitterExcess = -1.0;  ///< max over samples of Z_any - (1 + 2 T), unshifted T
  std::vector<SurgeFrontPoint> simulated;  ///< body front every 0.05 in T, from (0, 1)
};

/// Advances `solver` (a column of width a at x = 0, |gravity| = g) to T = Tmax - 0.175, sampling
/// the front every 0.05 in T, and compares with `data`. Lets InstabilityError through.
SurgeFrontComparison compareSurgeFront(SphSolver& solver, double a, double g,
                                       const std::vector<SurgeFrontPoint>& data,
                                       double Tmax = 2.5);

}  // namespace fluidviz::sph
