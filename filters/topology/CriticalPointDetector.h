#pragma once
// Zeros of the bilinear interpolant of a planar field, cell by cell.
//
// 1. Candidate cells: a component of a bilinear function takes its extremes over a rectangle at
//    the corners, so a cell (or sub-rectangle) can hold a zero only if both components have
//    min <= 0 <= max over its corners (inclusive: a zero exactly on a node or edge is kept).
// 2. Uniqueness: det of the interpolant's Jacobian is affine in (s, t); if it has one strict
//    sign at the four corners, the rectangle holds at most one zero (two zeros p1, p2 of a
//    bilinear map force det J = 0 at (p1 + p2) / 2). Newton's method from the centre then
//    locates it.
// 3. Otherwise (det J may vanish: two zeros, or a degenerate one) or when Newton fails, the
//    rectangle is split in four, down to `subdivision_depth`; a rectangle at the deepest level
//    that still passes the test yields its centre as an approximate zero.
// 4. The same zero found from several cells (on a shared node or edge) is reported once: zeros
//    closer than max(1e-6, 3 * 2^-depth) cells are merged.
// Non-isolated zeros are skipped: a cell that has an edge whose two end nodes are exactly zero
// (no-slip wall, solid obstacle) holds a segment of zeros, not a critical point. Cells with a
// non-finite corner value are skipped too.
#include <vector>

#include "filters/topology/PlanarField.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz::topology {

struct InterpolantZero {
  Vec2 q;                      ///< index-space position (cells)
  std::array<int, 2> cell;     ///< cell it was found in (the lowest-index one if shared)
  bool approximate = false;    ///< from the deepest subdivision level, not from Newton
};

/// All isolated zeros of the bilinear interpolant, merged as described above, ordered by
/// (cell j, cell i).
std::vector<InterpolantZero> findInterpolantZeros(const PlanarField& field,
                                                  const TopologyParams& params);

/// Zeros of one cell's patch (before merging); exposed for tests.
std::vector<InterpolantZero> findZerosInCell(const PlanarField& field, int i, int j,
                                             const TopologyParams& params);

}  // namespace fluidviz::topology
