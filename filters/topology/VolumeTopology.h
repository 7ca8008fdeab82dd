#pragma once
// Critical points of a 3D vector field on a regular grid: the volume counterpart of
// VectorFieldTopology.h. Pipeline:
//   VolumeField                 index space, piecewise-linear interpolant on the Kuhn split
//   -> zeroInTetrahedron        the zero of each tetrahedron's linear interpolant (exact)
//   -> merging                  one zero found by several tetrahedra (on a shared face, edge or
//                               node) is one zero; its Jacobian the mean of theirs
//   -> clustering               zeros that are not Morse on their own, closer than
//                               cluster_radius, form one point (single linkage, diameter at most
//                               3 cluster_radius): near a degenerate zero the interpolant has
//                               several spurious zeros, or a zero whose tetrahedra disagree
//   -> SurfaceDegree            index = degree of v/|v| on a sphere around the point or cluster
//   -> CriticalPointClassifier3D  Jacobian, eigenvalues, Morse type or "degenerate".
//
// Parameters are TopologyParams' (lengths in cells): cluster_radius; loop_radius (the sphere's
// radius beyond the cluster's extent, shrunk so that it stays inside the domain and encloses no
// other zero); det_threshold (in 3D against G^3: CriticalPointClassifier3D.h);
// gradient_scale_radius; centre_tolerance. slice_index and the 2D detection settings (Newton,
// subdivision, loop samples, sectors) are not used: the zeros of a tetrahedron's linear
// interpolant are solved for exactly.
//
// Like the 2D filter, a point within 1e-6 cells of the domain boundary is flagged on_boundary, a
// point whose sphere does not fit gets index_measured = false. A tetrahedron whose linear
// interpolant is singular (det of its vertex differences zero: a line or plane of zeros such as
// a no-slip wall, or none) or has a non-finite vertex value yields no zero, nor does one with a
// vertex where v = 0 exactly next to another such node (a region of zeros: a wall's corner).
#include <array>
#include <optional>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/topology/CriticalPoint3D.h"
#include "filters/topology/TopologyParams.h"
#include "filters/topology/VolumeField.h"

namespace fluidviz::topology {

/// The zero of the linear interpolant of one tetrahedron.
struct TetrahedronZero {
  Vec3 q;                       ///< index-space position (cells)
  Mat3 jacobian_index;          ///< of the tetrahedron's linear interpolant, index space
  std::array<int, 3> cell;      ///< cell of the tetrahedron
};

/// The zero of `tet`'s linear interpolant if it lies in the closed tetrahedron (barycentric
/// coordinates >= -1e-10), nullopt otherwise or when the interpolant is singular or not finite.
std::optional<TetrahedronZero> zeroInTetrahedron(const VolumeField& field,
                                                 const KuhnTetrahedron& tet);

/// Critical points of a 3D field (every axis at least 2 nodes). Throws ParamError for invalid
/// params, std::invalid_argument for an unusable field. Ordered by the first zero found
/// (cell k, j, i).
std::vector<CriticalPoint3D> findCriticalPoints3D(const VectorField& field,
                                                  const TopologyParams& params);
std::vector<CriticalPoint3D> findCriticalPoints3D(const VolumeField& field,
                                                  const TopologyParams& params);

/// Degree of v/|v| on the boundary of the box of nodes [lo, hi] (index space, inclusive) of the
/// piecewise-linear interpolant: by Poincaré–Hopf the sum of the indices of the zeros inside.
/// nullopt if the field vanishes or is not finite at a sample of the box surface.
std::optional<int> degreeOnNodeBox(const VolumeField& field, const std::array<int, 3>& lo,
                                   const std::array<int, 3>& hi);

}  // namespace fluidviz::topology
