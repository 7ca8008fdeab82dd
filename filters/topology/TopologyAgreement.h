#pragma once
// The two views of an incompressible planar flow must agree: the velocity v = (d psi/dy,
// -d psi/dx) is the gradient of the stream function psi turned by -90 degrees, so the zeros of v
// are the critical points of psi, with the same index, and
//   centre        <-> extremum of psi (maximum: counter-clockwise rotation, vorticity > 0;
//                     minimum: clockwise),
//   saddle        <-> saddle of psi,
//   monkey saddle <-> degenerate saddle of psi with index -2,
//   other non-Morse points <-> non-Morse points of psi with the same index.
// Points closer than `boundary_margin` cells to the domain boundary are left out (psi's points are
// searched at interior nodes only).
#include <vector>

#include "filters/topology/CriticalPoint.h"
#include "filters/topology/ScalarCriticalPoints.h"

namespace fluidviz::topology {

struct ViewMatch {
  int velocity = -1;         ///< index into the velocity critical points
  int stream_function = -1;  ///< index into psi's critical points
  double distance = 0.0;     ///< cells
  bool types_agree = false;
};

struct TopologyAgreement {
  std::vector<ViewMatch> matches;
  std::vector<int> unmatched_velocity;         ///< compared but without a partner
  std::vector<int> unmatched_stream_function;  ///< compared but without a partner
  /// Every compared point has a partner of the corresponding type.
  bool agree() const;
};

/// Whether a velocity critical point and a psi critical point are the same kind of point.
bool correspondingTypes(const CriticalPoint& velocity, const ScalarCriticalPoint& psi);

/// Pairs points closer than `max_distance` cells (closest pairs first) and checks their types.
TopologyAgreement compareVelocityAndStreamFunction(const std::vector<CriticalPoint>& velocity,
                                                   const std::vector<ScalarCriticalPoint>& psi,
                                                   const Grid& grid, double max_distance = 1.0,
                                                   double boundary_margin = 1.5);

}  // namespace fluidviz::topology
