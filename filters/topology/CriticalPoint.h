#pragma once
// A critical point (zero) of a planar vector field with its Poincaré index, its linearisation and
// its sector decomposition. Terminology follows Helman & Hesselink, "Representation and display
// of vector field topology in fluid flow data sets", IEEE Computer 22(8), 1989 (Morse points),
// and Tricoche, Scheuermann & Hagen, "Higher order singularities in piecewise linear vector
// fields", 2000, and Scheuermann et al., "Visualizing nonlinear vector field topology", IEEE TVCG
// 4(2), 1998 (non-Morse points, sectors).
#include <array>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "fieldviz/core/Grid.h"

namespace fluidviz::topology {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

enum class CriticalPointType {
  // Morse (det J != 0): the linearisation decides.
  Saddle,        ///< det < 0, index -1, four hyperbolic sectors
  Source,        ///< real eigenvalues > 0 (repelling node), index +1
  Sink,          ///< real eigenvalues < 0 (attracting node), index +1
  SpiralSource,  ///< complex eigenvalues, real part > 0, index +1
  SpiralSink,    ///< complex eigenvalues, real part < 0, index +1
  Centre,        ///< complex eigenvalues with |real| <= centre_tolerance * |imag|, index +1
  // Non-Morse (det J ~ 0): the index and the sectors decide.
  MonkeySaddle,  ///< index -2, six hyperbolic sectors (e.g. gradient of x^3 - 3xy^2)
  SaddleNode,    ///< index 0, two hyperbolic sectors and a parabolic one (e.g. (x^2, y))
  Cusp,          ///< index 0, two hyperbolic sectors, no parabolic one (e.g. (y, x^2))
  Dipole,        ///< index 2, two elliptic sectors (e.g. z^2 = (x^2 - y^2, 2xy))
  Degenerate,    ///< any other non-Morse point: see index and sectors
  Unknown,       ///< index could not be measured (point on the domain boundary) and det J ~ 0
  // On a no-slip wall at rest (WallPoints.h): where the wall shear stress changes sign. Half
  // saddles of the wall, with no linearisation of their own: index 0, index_measured false.
  Attachment,    ///< the flow along the wall leaves the point on both sides (flow meets the wall)
  Separation,    ///< the flow along the wall meets at the point and leaves the wall
};

/// Snake-case name used in reports and files: "saddle", "spiral_sink", "monkey_saddle", ...
std::string toString(CriticalPointType t);

enum class SectorType { Hyperbolic, Elliptic, Parabolic };

/// Number of sectors of each kind around a point. Bendixson's formula ties them to the index:
/// index = 1 + (elliptic - hyperbolic) / 2.
struct SectorCounts {
  int elliptic = 0;
  int hyperbolic = 0;
  int parabolic = 0;
  bool operator==(const SectorCounts&) const = default;
};

/// A direction in which the field is radial at the loop: the boundary between two sectors and
/// the start direction of a separatrix when it bounds a hyperbolic sector.
struct RadialDirection {
  Vec2 direction;        ///< unit vector in world space
  bool outflow = false;  ///< true: field points away from the point (unstable direction)
};

struct CriticalPoint {
  Vec3 position{0, 0, 0};        ///< world position (z = the slice's z)
  std::array<int, 2> cell{0, 0}; ///< (i, j) of the cell that contains the point
  int index = 0;                 ///< Poincaré index (winding number on a loop around the point)
  bool index_measured = false;   ///< false: no loop fits in the domain (point on the boundary);
                                 ///< index is then sign(det J) for Morse points, 0 otherwise
  CriticalPointType type = CriticalPointType::Unknown;
  bool morse = false;            ///< one zero, |det J| > det_threshold * G^2, index = sign(det J)
  /// Linearisation the type is read from, 1/s: the interpolant's exact Jacobian at an isolated
  /// zero (mean over the cells sharing it on an edge or node); central differences (step one
  /// cell) at the centre of a cluster of zeros.
  Mat2 jacobian = Mat2::Zero();
  Mat2 jacobian_interpolant = Mat2::Zero();  ///< of the bilinear interpolant in `cell`, 1/s
  double det = 0.0;              ///< det J (1/s^2)
  double trace = 0.0;            ///< tr J = divergence (1/s)
  double normalized_det = 0.0;   ///< det J / G^2 (G: local RMS Jacobian norm of the field)
  std::array<std::complex<double>, 2> eigenvalues{};  ///< of J, 1/s
  SectorCounts sectors;          ///< measured on the index loop
  bool bendixson_holds = false;  ///< index == 1 + (e - h) / 2 for the measured sectors
  /// Radial directions bounding hyperbolic sectors = separatrix start directions. For a Morse
  /// saddle these are the eigenvectors of J; otherwise measured on the loop.
  std::vector<RadialDirection> separatrix_directions;
  bool on_boundary = false;      ///< within 1e-6 cells of the domain boundary
  int cluster_size = 1;          ///< zeros of the interpolant merged into this point
  double loop_radius = 0.0;      ///< radius of the index loop, cells (0 if not measured)

  std::string typeName() const { return toString(type); }
};

}  // namespace fluidviz::topology
