#pragma once
// 1D separatrices of 3D saddles: the one-dimensional invariant manifold of a Morse saddle, along
// the eigenvector of its single eigenvalue whose real part has the sign the other two lack
// (Globus, Levit & Lasinski 1991; Theisel et al., "Saddle connectors", IEEE Vis 2003):
//   saddle_1, spiral_saddle_1  one positive eigenvalue: the unstable manifold, traced forward;
//   saddle_2, spiral_saddle_2  one negative eigenvalue: the stable manifold, traced backward.
// Two lines per saddle, starting separatrix_offset cells from the point along +- that
// eigenvector (cells measured in index space, as in 2D), traced with the shared streamline
// integrator (trilinear interpolation) and ending as the 2D separatrices do (Separatrices.h):
// near another critical point (separatrix_stop_radius cells), at the boundary, at the length
// limit, at stagnation or at masked (NaN) nodes. The 2D separatrices of 3D saddles (separating
// surfaces, spanned by the other two eigenvectors) are not computed here.
#include <optional>
#include <utility>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/streamlines/Streamline.h"
#include "filters/topology/CriticalPoint3D.h"
#include "filters/topology/Separatrices.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz::topology {

struct Separatrix3D {
  int origin = -1;                 ///< index of the saddle it starts at
  Vec3 direction{0, 0, 0};         ///< world unit vector of the start direction
  bool outgoing = false;           ///< true: unstable manifold, traced forward
  std::vector<Vec3> points;        ///< world, from the saddle outwards
  SeparatrixEnd end = SeparatrixEnd::Other;
  int end_point = -1;              ///< critical point reached (end == CriticalPoint)
  streamlines::TerminationReason reason = streamlines::TerminationReason::not_traced;
};

/// Saddle1, Saddle2 and their spiral variants.
bool isMorseSaddle(CriticalPointType3D t);

/// Distance in cells (index space) between two world points.
double cellsBetween(const Grid& g, const Vec3& a, const Vec3& b);

/// Nearest critical point within r cells of p, skipping `skip`; -1 if none. A linear scan: the
/// points of a field are few next to the steps of its separatrices and surfaces.
int nearestCriticalPoint(const Grid& g, const std::vector<CriticalPoint3D>& points, const Vec3& p,
                 double r, int skip);

/// The single eigendirection of a Morse saddle's Jacobian (world unit vector) and whether it is
/// unstable; nullopt for points that are not Morse saddles.
std::optional<std::pair<Vec3, bool>> saddleAxis(const CriticalPoint3D& p);

/// 1D separatrices of all Morse saddles of `points` (from findCriticalPoints3D on `field`),
/// traced in parallel, two per saddle (fewer when a seed falls outside the grid).
std::vector<Separatrix3D> computeSeparatrices3D(const VectorField& field,
                                                const std::vector<CriticalPoint3D>& points,
                                                const TopologyParams& params);

}  // namespace fluidviz::topology
