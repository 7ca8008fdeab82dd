#pragma once
// Critical points of a planar vector field with Morse and non-Morse classification — the entry
// point of the topology core. Pipeline:
//   PlanarField (2D field or z-slice, index space)
//   -> CriticalPointDetector   zeros of the bilinear interpolant (sign test, Newton, subdivision)
//   -> IndexLoopPlacement      clusters of nearby degenerate zeros, one loop around each
//   -> PoincareIndex           winding number on the loop
//   -> SectorAnalysis          hyperbolic / elliptic / parabolic sectors on the loop
//   -> CriticalPointClassifier Jacobian (det, trace, eigenvalues), Morse or non-Morse type.
// Boundary: a point within 1e-6 cells of the domain edge is flagged on_boundary; a point whose
// cluster does not fit in a loop inside the domain gets index_measured = false (its index is
// sign(det J) if it is non-degenerate, else 0 and type Unknown).
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/PointMask.h"
#include "fieldviz/core/RestingWalls.h"
#include "filters/topology/CriticalPoint.h"
#include "filters/topology/PlanarField.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz::topology {

/// Critical points of slice params.slice_index of `field` (a 2D field: its only slice).
/// Throws ParamError for invalid params, std::invalid_argument for an unusable field.
std::vector<CriticalPoint> findCriticalPoints(const VectorField& field,
                                              const TopologyParams& params);
std::vector<CriticalPoint> findCriticalPoints(const PlanarField& field,
                                              const TopologyParams& params);

/// Critical points of a 2D field with masked nodes (solids, missing data; PointMask.h), `analysed`
/// being the field with its mask prepared (withWallLayerContinued: the wall layer continued from
/// the fluid side, the rest NaN): none in a cell whose corners are all masked, since a mask's
/// interior holds none. An empty mask keeps every point.
/// Next to no-slip walls at rest (`walls`, RestingWalls.h) the velocity is zero along the whole
/// wall: the points found in their wall layer (restingWallLayer) are replaced by the walls'
/// attachment and separation points (findWallPoints, WallPoints.h).
std::vector<CriticalPoint> findCriticalPointsInFluid(const VectorField& analysed,
                                                     const PointMask& mask,
                                                     const TopologyParams& params,
                                                     const RestingWalls& walls = {});

}  // namespace fluidviz::topology
