#pragma once
// Attachment and separation points on the no-slip walls at rest of a 2D flow, and the wall layer
// in which the zeros found by the critical-point search are the wall itself.
//
// On a no-slip wall the velocity vanishes along the whole wall, so a search for isolated zeros
// finds arbitrary points scattered along it (spiral "sources" with det J > 0 and tr J > 0 in an
// incompressible flow, "unknown" and "degenerate" points). The topology of a wall is instead read
// from the wall shear stress, tau_w = mu du_t/dn (Helman & Hesselink 1991; Tobak & Peake 1982,
// "Topology of three-dimensional separated flows"): its zeros are the wall's critical points,
// half saddles where a dividing streamline meets the wall. On the lattice, the sign of tau_w is
// the sign of the tangential velocity u_t at the first fluid node off the wall (u_t = 0 on the
// wall, so du_t/dn ~ u_t / d).
//
// The wall is traced as the chain of cell faces between a resting solid node and a fluid node
// (halfway bounce-back puts the wall there), in order, with the solid on the left. Along each
// chain u_t (the fluid node's velocity along the chain's tangent, smoothed over +-2 faces) changes
// sign at the wall's critical points: from - to + (the flow along the wall diverges) an
// attachment, from + to - a separation. Sign changes closer than kWallClusterCells along the
// chain are merged and count with their signs, as zeros of a 1D field do: an attachment between
// two separations is one separation, a pair of opposite signs (a staircase wiggle) none. Sign
// changes next to a concave corner (a box's corner, a step's foot) count together in the same
// way: the corner's eddies are not resolved there.
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/PointMask.h"
#include "fieldviz/core/RestingWalls.h"
#include "filters/topology/CriticalPoint.h"

namespace fluidviz::topology {

/// Sign changes of the wall shear this close along a wall (cells) are one wall point or none.
inline constexpr double kWallClusterCells = 2.0;
/// Sign changes this close to a concave corner of a wall (cells along it) are the corner's
/// unresolved eddies: they count together, with their signs, as one point or none
/// (WallPoints.cpp, markCornerZeros).
inline constexpr double kWallCornerCells = 4.0;
/// Separatrices of a wall point start this far into the fluid along the wall normal (cells):
/// outside the first fluid node, where the lattice resolves the flow leaving or meeting the wall.
inline constexpr double kWallSeparatrixOffsetCells = 1.0;

/// Attachment and separation points of the resting walls of the 2D field `v` (fluid nodes: not
/// in `mask`, finite). Each lies on the wall (between its solid and fluid node) with
/// separatrix_directions = the wall normal into the fluid, outflow for a separation.
std::vector<CriticalPoint> findWallPoints(const VectorField& v, const PointMask& mask,
                                          const RestingWalls& walls);

/// 1 on the nodes of the wall layer: the resting solid nodes and the fluid nodes next to a
/// resting wall (4-neighbours of a resting solid node, edge nodes of a resting side).
PointMask restingWallLayer(const Grid& g, const PointMask& mask, const RestingWalls& walls);

/// True when a corner of the cell of 2D position p is in `layer`: a zero found there is the
/// wall's line of zeros, not a point of the flow.
bool inWallLayer(const Grid& g, const PointMask& layer, const Vec3& p);

}  // namespace fluidviz::topology
