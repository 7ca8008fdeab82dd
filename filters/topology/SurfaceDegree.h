#pragma once
// Index of a zero of a 3D vector field: the degree of the map v/|v| from a closed surface
// around it to the unit sphere (Milnor, "Topology from the differentiable viewpoint", 1965, §6;
// the 3D counterpart of the winding number of PoincareIndex.h). With the surface triangulated
// and each triangle mapped to the spherical triangle spanned by the unit field vectors at its
// corners, the degree is the sum of the signed solid angles of those spherical triangles over
// 4 pi. The solid angle of the triangle (a, b, c) of unit vectors is
//     Omega = 2 atan2(a . (b x c), 1 + a.b + b.c + c.a)
// (Van Oosterom & Strackee, "The solid angle of a plane triangle", IEEE Trans. Biomed. Eng.
// 30(2), 1983). The sum is exactly 4 pi times an integer for any closed triangulated surface as
// long as no edge joins two antipodal vectors; it is the degree of v/|v| itself when the
// triangulation is fine enough that the field turns by little along every edge. The surfaces
// are therefore refined uniformly (a conforming mesh, so the sum stays closed) until the field
// turns by less than kMaxEdgeTurn along every edge.
//
// By the Poincaré–Hopf theorem the degree on a surface on which v does not vanish equals the
// sum of the indices of the zeros it encloses; a Morse zero has index sign(det J).
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "fieldviz/core/Grid.h"

namespace fluidviz::topology {

struct TriangleSurface {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
};

/// Unit icosphere: the icosahedron with every triangle split in four `level` times, the new
/// vertices pushed onto the sphere (20 * 4^level triangles).
TriangleSurface icosphere(int level);

/// Surface of the box [lo, hi], each face split into divisions[a] x divisions[b] rectangles of
/// two triangles (vertices on shared edges coincide exactly).
TriangleSurface boxSurface(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& divisions);

/// Signed solid angle of the spherical triangle of the unit vectors a, b, c (Van Oosterom &
/// Strackee 1983).
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c);

struct DegreeMeasurement {
  int degree = 0;
  double max_edge_turn = 0.0;  ///< largest angle (rad) the field turns along an edge
  int triangles = 0;           ///< of the finest surface used
  /// The field turns by less than the refinement limit (pi / 8) along every edge. False after
  /// the finest refinement: v nearly vanishes on the surface (a zero on it, or a line or plane
  /// of zeros crossing it), and the degree is not to be trusted.
  bool resolved = false;
};

using FieldAt = std::function<Vec3(const Vec3&)>;

/// Degree of v/|v| on the sphere of `radius` around `centre` (same units as `field`'s argument).
/// nullopt if v vanishes or is not finite at a vertex.
std::optional<DegreeMeasurement> degreeOnSphere(const FieldAt& field, const Vec3& centre,
                                                double radius);

/// Degree of v/|v| on the surface of the box [lo, hi], starting from `divisions` rectangles per
/// face side and doubling them as needed. nullopt if v vanishes or is not finite at a vertex.
std::optional<DegreeMeasurement> degreeOnBox(const FieldAt& field, const Vec3& lo, const Vec3& hi,
                                             const std::array<int, 3>& divisions);

/// Degree on a given surface (no refinement); nullopt as above.
std::optional<DegreeMeasurement> degreeOnSurface(const FieldAt& field,
                                                 const TriangleSurface& surface);

}  // namespace fluidviz::topology
