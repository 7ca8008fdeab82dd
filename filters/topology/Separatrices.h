#pragma once
// Separatrices: the streamlines that bound the hyperbolic sectors of saddle-like critical points
// (Helman & Hesselink 1989 for Morse saddles; Scheuermann et al. 1998 for higher-order points).
// They are traced with the project's shared streamline integrator (filters/streamlines).
//
// Start: for a Morse saddle, along its four eigenvector directions at separatrix_offset cells;
// for a non-Morse point, along the radial directions bounding its hyperbolic sectors, on its
// index loop (where they were measured; inside the loop the interpolant's spurious zeros may
// lie). Outgoing directions (outflow) are traced forward, incoming ones backward.
// End: within separatrix_stop_radius of another critical point (or of its own after leaving it
// by more than twice that: a homoclinic loop), at the domain boundary, at the length or step
// limit, or at stagnation.
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/streamlines/Streamline.h"
#include "filters/topology/CriticalPoint.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz::topology {

/// Mask: the line reached a masked node (NaN velocity: a solid, missing data, outside a plane
/// slice) and ends at its last point in the fluid.
enum class SeparatrixEnd { CriticalPoint, Boundary, Length, Stagnation, Other, Mask };
std::string toString(SeparatrixEnd e);
/// How a separatrix ended, from why its integration stopped (2D and 3D alike).
SeparatrixEnd separatrixEnd(streamlines::TerminationReason reason);

struct Separatrix {
  int origin = -1;              ///< index of the critical point it starts at
  RadialDirection start;        ///< start direction (world unit vector) and outgoing flag
  std::vector<Vec3> points;     ///< world, from the critical point outwards
  SeparatrixEnd end = SeparatrixEnd::Other;
  int end_point = -1;           ///< critical point reached (end == CriticalPoint)
  streamlines::TerminationReason reason = streamlines::TerminationReason::not_traced;
};

/// Separatrices of all points of `points` that have separatrix directions (saddles, monkey
/// saddles, saddle-nodes, cusps, ...), traced in parallel. `points` must come from
/// findCriticalPoints on the same field and params.slice_index.
std::vector<Separatrix> computeSeparatrices(const VectorField& field,
                                            const std::vector<CriticalPoint>& points,
                                            const TopologyParams& params);

}  // namespace fluidviz::topology
