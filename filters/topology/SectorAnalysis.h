#pragma once
// Sector decomposition of the neighbourhood of a critical point, measured on a loop around it.
//
// Let phi(theta) be the angle of the field w relative to the radial direction at polar angle
// theta on a circle around the point. The field is radial where phi is a multiple of pi:
// outflow where phi = 0 (mod 2 pi), inflow where phi = pi (mod 2 pi). These radial directions
// bound the sectors (Bendixson; e.g. Andronov et al., "Qualitative theory of second-order
// dynamic systems", 1973, ch. 8):
//   phi passes from k pi to (k-1) pi  -> hyperbolic sector (flow passes by the point; the field
//                                        turns against the loop's sense, by -pi);
//   phi passes from k pi to (k+1) pi  -> elliptic sector (orbits leave and return to the point;
//                                        the field turns by +pi relative to the radial);
//   phi leaves k pi and returns to it -> parabolic (all orbits enter, or all leave).
// Adjacent parabolic pieces form one parabolic sector. Over the whole loop phi changes by
// 2 pi (index - 1), which is Bendixson's index formula index = 1 + (e - h) / 2.
// A crossing counts only when phi passes the multiple of pi by more than the hysteresis.
#include <vector>

#include "filters/topology/PoincareIndex.h"

namespace fluidviz::topology {

/// Radial direction on the loop, index-space polar angle.
struct SectorBoundary {
  double theta = 0.0;    ///< polar angle, rad, in [0, 2 pi)
  bool outflow = false;  ///< field points away from the centre
};

struct Sector {
  SectorType type;
  int begin = -1, end = -1;  ///< indices into SectorDecomposition::boundaries (counter-clockwise)
};

struct SectorDecomposition {
  std::vector<SectorBoundary> boundaries;  ///< counter-clockwise
  std::vector<Sector> sectors;             ///< parabolic runs merged
  SectorCounts counts;
  int index = 0;  ///< 1 + (total change of phi) / 2 pi, = winding number of the loop
  /// Boundaries of hyperbolic sectors: the start directions of separatrices.
  std::vector<SectorBoundary> hyperbolicBoundaries() const;
};

/// Sectors of the field on the circle of `radius` cells around `centre`; `loop` must be
/// sampleCircle(field, centre, radius, ...). Crossing angles are refined by bisection on the
/// interpolant. `hysteresis` in rad.
SectorDecomposition analyzeSectors(const PlanarField& field, const Vec2& centre, double radius,
                                   const std::vector<LoopSample>& loop, double hysteresis);

}  // namespace fluidviz::topology
