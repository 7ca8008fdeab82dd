#pragma once
// Classification of a critical point from its linearisation (Morse points) or from its index and
// sectors (non-Morse points).
//
// Morse (Helman & Hesselink 1989): with J the Jacobian at the point, det J != 0,
//   det < 0                         -> saddle (real eigenvalues of opposite sign), index -1;
//   det > 0, tr^2 >= 4 det          -> source (tr > 0) / sink (tr < 0): real eigenvalues;
//   det > 0, tr^2 <  4 det          -> complex a +- ib: centre if |a| <= centre_tolerance * |b|,
//                                      else spiral source (a > 0) / spiral sink (a < 0).
// "Centre" on numerical data: the divergence (= tr J = 2a) of sampled incompressible flow is
// never exactly zero, so a point is a centre when the real part of its eigenvalues is at most
// centre_tolerance times the imaginary part, i.e. the orbit's radius changes by less than
// about 2 pi * centre_tolerance per turn (factor exp(2 pi a / b)).
//
// The linearisation of an isolated zero is the EXACT Jacobian of the bilinear interpolant at the
// zero (PlanarField::jacobianAtPoint), the field whose zero it is: central differences over the
// neighbouring nodes add O(h^2 v''') to it, enough to flip the sign of a small trace (a weak
// spiral sink read as a spiral source, issue 15). A cluster of zeros around a degenerate point
// has no such zero; it is linearised by central differences at its centre.
//
// Degeneracy ("det ~ 0") is judged against the field's own scale: |det J| <= det_threshold * G^2
// with G the RMS Jacobian norm over a window of gradient_scale_radius cells around the point
// (PlanarField::gradientScale). A point is Morse only if it is one zero of the interpolant,
// non-degenerate, and its measured index equals sign(det J) (Morse points have index +-1).
//
// Non-Morse (Tricoche, Scheuermann & Hagen 2000; Scheuermann et al. 1998): named by the index
// and the sector counts (e elliptic, h hyperbolic, p parabolic; Bendixson: index = 1 + (e-h)/2):
//   index -2, h = 6, e = 0         -> monkey saddle
//   index  0, h = 2, e = 0, p >= 1 -> saddle-node
//   index  0, h = 2, e = 0, p = 0  -> cusp
//   index  2, e = 2, h = 0         -> dipole
//   otherwise                      -> degenerate (see index and sectors).
#include <array>
#include <complex>
#include <vector>

#include "filters/topology/CriticalPoint.h"
#include "filters/topology/PlanarField.h"

namespace fluidviz::topology {

struct Linearization {
  Mat2 jacobian = Mat2::Zero();
  double det = 0.0, trace = 0.0;
  std::array<std::complex<double>, 2> eigenvalues{};  ///< larger real part first
};

Linearization linearize(const Mat2& jacobian);

/// True when |det J| > det_threshold * G^2.
bool isNonDegenerate(const Linearization& l, double gradient_scale, double det_threshold);

/// World-space linearisation of the interpolant at its isolated zero q (index space).
Linearization linearizeZero(const PlanarField& field, const Vec2& q);

/// The interpolant's zero q is a Morse point on its own: |det J| > det_threshold * G^2 with J
/// its exact Jacobian at q and G the field scale there (gradient_scale_radius).
bool isMorseZero(const PlanarField& field, const Vec2& q, double gradient_scale_radius,
                 double det_threshold);

/// Morse type of a non-degenerate linearisation (see header comment).
CriticalPointType classifyMorse(const Linearization& l, double centre_tolerance);

/// Name of a non-Morse point from its index and sectors (see header comment).
CriticalPointType classifyNonMorse(int index, const SectorCounts& sectors);

/// Bendixson's index formula index = 1 + (e - h) / 2.
bool bendixsonHolds(int index, const SectorCounts& sectors);

/// Separatrix start directions of a Morse saddle: the unit eigenvectors of J (world space),
/// +- the unstable one (outflow) and +- the stable one (inflow).
std::vector<RadialDirection> saddleEigenDirections(const Linearization& l);

}  // namespace fluidviz::topology
