#pragma once
// A critical point (zero) of a 3D vector field with its index (degree of v/|v| on a sphere
// around it) and its linearisation. Morse types after the eigenvalues of the Jacobian as in
// Helman & Hesselink, "Visualizing vector field topology in fluid flows", IEEE CG&A 11(3), 1991,
// and Globus, Levit & Lasinski, "A tool for visualizing the topology of three-dimensional vector
// fields", IEEE Visualization 1991; the names of the saddles count the positive eigenvalues (real
// parts) as in VTK's vtkVectorFieldTopology (Bujack et al., "State of the art in time-dependent
// flow topology", 2020): a 1-saddle has one, a 2-saddle two.
#include <array>
#include <complex>
#include <string>

#include "filters/topology/VolumeField.h"

namespace fluidviz::topology {

enum class CriticalPointType3D {
  // Morse (det J != 0); the index is sign(det J).
  Source,         ///< three eigenvalues with positive real part, real; index +1
  Sink,           ///< three with negative real part, real; index -1
  Saddle1,        ///< real, one positive and two negative; index +1
  Saddle2,        ///< real, two positive and one negative; index -1
  SpiralSource,   ///< a complex pair and a real eigenvalue, all real parts > 0; index +1
  SpiralSink,     ///< all real parts < 0; index -1
  SpiralSaddle1,  ///< complex pair with real part < 0, real eigenvalue > 0; index +1
  SpiralSaddle2,  ///< complex pair with real part > 0, real eigenvalue < 0; index -1
  Centre,         ///< complex pair a +- ib with |a| <= centre_tolerance * |b| (swirl without
                  ///< radial motion, e.g. a vortex core on a symmetry plane); index sign(det J)
  // Non-Morse.
  Degenerate,     ///< det J ~ 0 or several zeros merged: the measured index says what it is
  Unknown,        ///< det J ~ 0 and no sphere fits (on or next to the domain boundary), or no
                  ///< sphere resolves the degree (v nearly vanishes on every one: not isolated)
};

/// Snake-case name used in reports and files: "source", "saddle_1", "spiral_saddle_2", ...
std::string toString(CriticalPointType3D t);

struct CriticalPoint3D {
  Vec3 position{0, 0, 0};           ///< world position
  std::array<int, 3> cell{0, 0, 0}; ///< cell that contains the point
  int index = 0;                    ///< degree of v/|v| on the sphere around the point
  bool index_measured = false;      ///< false: no sphere fits in the domain; index is then
                                    ///< sign(det J) for non-degenerate points, 0 otherwise
  CriticalPointType3D type = CriticalPointType3D::Unknown;
  bool morse = false;               ///< one zero, |det J| > det_threshold G^3, index = sign det
  /// Linearisation the type is read from, world units (1/s): at an isolated zero the Jacobian of
  /// the piecewise-linear interpolant, i.e. the linear fit of the tetrahedron holding it (mean of
  /// the tetrahedra sharing it when it lies on a face, edge or node); at the centre of a cluster
  /// of zeros central differences with a step of one cell.
  Mat3 jacobian = Mat3::Zero();
  double det = 0.0;                 ///< det J (1/s^3)
  double trace = 0.0;               ///< tr J = divergence (1/s)
  double normalized_det = 0.0;      ///< det J / G^3 (G: local RMS Jacobian norm)
  std::array<std::complex<double>, 3> eigenvalues{};  ///< of J, larger real part first
  bool on_boundary = false;         ///< within 1e-6 cells of the domain boundary
  int cluster_size = 1;             ///< zeros of the interpolant merged into this point
  double sphere_radius = 0.0;       ///< radius of the index sphere, cells (0: not measured)

  std::string typeName() const { return toString(type); }
};

}  // namespace fluidviz::topology
