#pragma once
// 2D separatrices of 3D saddles: the separating surfaces, i.e. the two-dimensional invariant
// manifold of a Morse saddle, tangent at the point to the plane of the two eigenvectors whose
// eigenvalues share a sign (Globus, Levit & Lasinski 1991; Theisel et al., "Saddle connectors",
// IEEE Vis 2003):
//   saddle_1, spiral_saddle_1  two eigenvalues with negative real part: the stable manifold,
//                              traced backward;
//   saddle_2, spiral_saddle_2  two with positive real part: the unstable manifold, traced forward.
// For a complex pair the plane is spanned by the real and imaginary parts of its eigenvector.
//
// Each surface is a stream surface grown by an advancing front (Hultquist, "Constructing stream
// surfaces in steady 3D vector fields", IEEE Vis 1992; Garth et al., "Surface techniques for
// vortex visualization", VisSym 2004): the front starts on a closed curve separatrix_offset
// cells from the saddle in its eigenplane, and each step carries the front along the flow for
// one time step dt = d / max|v| over the front (d = max_edge / 4 cells): every point travels the
// arc length |v| dt, |v| taken at its start (the shared streamline integrator), so the fronts
// are, to first order in dt, images of the seed curve under the flow. (Equal arc lengths for
// all points would not be: in a spiral, slow inner points would wind faster than outer ones
// and the strips would fold over earlier ones.) The strip between the old and the new front is
// triangulated; where a new front edge is longer than max_edge / 2, its old edge is split into
// as many pieces and their points are carried by the same step (so the strip stays the image
// of the old edge: Hultquist's insertion). Old edges <= max_edge / 2 and arcs <= d keep the
// triangle edges near max_edge / 2 where the flow stretches the front smoothly (the chord of
// an arc is not longer than the arc). max_length bounds the arc of the fastest point.
// A front point ends where a separatrix would (Separatrices3D.h): at the boundary (its last
// point ON it), at stagnation, at masked (NaN) nodes, within separatrix_stop_radius cells of
// another critical point; the front breaks there into open pieces that go on growing. Converging
// fronts are not coarsened (triangles thin out instead). Known limit: where the front turns
// much faster than it grows (a weakly unstable spiral saddle, Re/Im of 0.05) its polygon's
// sagitta e^2/8r exceeds a step's outward motion and strips lie partly over earlier ones (the
// sheet stays in its manifold but covers it 2.5 times over); refining the front by its
// curvature would remove that.
#include <array>
#include <optional>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/topology/CriticalPoint3D.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz::topology {

/// Why a surface stopped growing.
enum class SurfaceEnd {
  front_ended,    ///< every front point ended (boundary, stagnation, mask, critical point)
  max_length,     ///< the front travelled separating_surface.max_length cells
  max_triangles,  ///< the surface reached separating_surface.max_triangles
};
const char* toString(SurfaceEnd e);

/// The eigenplane of a Morse saddle: an orthonormal world basis and the sense of its manifold.
struct SaddlePlane {
  Vec3 u{1, 0, 0}, w{0, 1, 0};
  bool outgoing = false;  ///< unstable manifold (2-saddles), traced forward
  Vec3 normal() const { return u.cross(w); }
};

/// The plane of the two eigenvalues sharing a sign; nullopt for points that are not Morse saddles.
std::optional<SaddlePlane> saddlePlane(const CriticalPoint3D& p);

struct SeparatingSurface {
  int origin = -1;                         ///< index of the saddle it starts at
  bool outgoing = false;                   ///< unstable manifold, traced forward
  std::vector<Vec3> points;                ///< world
  std::vector<std::array<int, 3>> triangles;  ///< oriented consistently along the front
  SurfaceEnd end = SurfaceEnd::front_ended;
};

/// One separating surface per Morse saddle of `points` (from findCriticalPoints3D on `field`).
std::vector<SeparatingSurface> computeSeparatingSurfaces(const VectorField& field,
                                                         const std::vector<CriticalPoint3D>& points,
                                                         const TopologyParams& params);

}  // namespace fluidviz::topology
