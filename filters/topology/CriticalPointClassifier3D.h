#pragma once
// Classification of a 3D critical point from its linearisation J (world units).
//
// Degeneracy is judged against the field's own scale, as in 2D (CriticalPointClassifier.h) with
// the power matching the dimension: |det J| <= det_threshold * G^3, G the RMS Jacobian norm over
// a cube of half-width gradient_scale_radius cells (VolumeField::gradientScale). For a linear
// field with eigenvalues l1, l2, l3 this is |l1 l2 l3| / (l1^2 + l2^2 + l3^2)^(3/2): the default
// 1e-2 accepts (1, 1, 0.03) and rejects (1, 1, 0.02).
//
// Morse types (det J != 0; Helman & Hesselink 1991, Globus et al. 1991): count the eigenvalues
// with positive real part (a complex pair counts twice):
//   real eigenvalues:           3 source, 0 sink, 1 saddle_1, 2 saddle_2;
//   complex pair a +- ib and c: |a| <= centre_tolerance |b| centre, otherwise
//                               3 spiral_source, 0 spiral_sink, 1 spiral_saddle_1 (a < 0 < c),
//                               2 spiral_saddle_2 (c < 0 < a).
// The index of a Morse point is sign(det J): +1 for sources and 1-saddles, -1 for sinks and
// 2-saddles (with their spiral variants); a centre has sign(c).
#include <array>
#include <complex>

#include "filters/topology/CriticalPoint3D.h"

namespace fluidviz::topology {

struct Linearization3 {
  Mat3 jacobian = Mat3::Zero();
  double det = 0.0, trace = 0.0;
  std::array<std::complex<double>, 3> eigenvalues{};  ///< larger real part first
  bool complexPair = false;  ///< eigenvalues[?] has a non-zero imaginary part
};

Linearization3 linearize(const Mat3& jacobian);

/// True when |det J| > det_threshold * G^3.
bool isNonDegenerate(const Linearization3& l, double gradient_scale, double det_threshold);

/// Morse type of a non-degenerate linearisation (see header comment).
CriticalPointType3D classifyMorse(const Linearization3& l, double centre_tolerance);

}  // namespace fluidviz::topology
