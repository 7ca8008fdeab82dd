#include "filters/topology/CriticalPointClassifier3D.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace fluidviz::topology {

Linearization3 linearize(const Mat3& jacobian) {
  Linearization3 l;
  l.jacobian = jacobian;
  l.det = jacobian.determinant();
  l.trace = jacobian.trace();
  const Eigen::EigenSolver<Mat3> solver(jacobian, false);
  double scale = 0.0;
  for (int k = 0; k < 3; ++k) {
    l.eigenvalues[k] = solver.eigenvalues()[k];
    scale = std::max(scale, std::abs(l.eigenvalues[k]));
  }
  // A real matrix's eigenvalues are real or one conjugate pair; round-off imaginary parts of
  // real ones are dropped.
  for (auto& e : l.eigenvalues)
    if (std::abs(e.imag()) <= 1e-12 * scale) e = e.real();
  l.complexPair = std::any_of(l.eigenvalues.begin(), l.eigenvalues.end(),
                              [](const std::complex<double>& e) { return e.imag() != 0.0; });
  std::sort(l.eigenvalues.begin(), l.eigenvalues.end(),
            [](const std::complex<double>& a, const std::complex<double>& b) {
              return a.real() > b.real() || (a.real() == b.real() && a.imag() > b.imag());
            });
  return l;
}

bool isNonDegenerate(const Linearization3& l, double gradient_scale, double det_threshold) {
  return std::abs(l.det) > det_threshold * gradient_scale * gradient_scale * gradient_scale &&
         l.det != 0.0;
}

CriticalPointType3D classifyMorse(const Linearization3& l, double centre_tolerance) {
  int positive = 0;
  for (const auto& e : l.eigenvalues) positive += e.real() > 0;
  if (!l.complexPair) {
    constexpr CriticalPointType3D byPositive[4] = {
        CriticalPointType3D::Sink, CriticalPointType3D::Saddle1, CriticalPointType3D::Saddle2,
        CriticalPointType3D::Source};
    return byPositive[positive];
  }
  const auto pair = std::find_if(l.eigenvalues.begin(), l.eigenvalues.end(),
                                 [](const std::complex<double>& e) { return e.imag() != 0.0; });
  if (std::abs(pair->real()) <= centre_tolerance * std::abs(pair->imag()))
    return CriticalPointType3D::Centre;
  constexpr CriticalPointType3D byPositive[4] = {
      CriticalPointType3D::SpiralSink, CriticalPointType3D::SpiralSaddle1,
      CriticalPointType3D::SpiralSaddle2, CriticalPointType3D::SpiralSource};
  return byPositive[positive];
}

}  // namespace fluidviz::topology
