#include "filters/topology/CriticalPointClassifier.h"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace fluidviz::topology {

Linearization linearize(const Mat2& jacobian) {
  Linearization l;
  l.jacobian = jacobian;
  l.det = jacobian.determinant();
  l.trace = jacobian.trace();
  const std::complex<double> half = l.trace / 2;
  const std::complex<double> root = std::sqrt(std::complex<double>(half * half - l.det));
  l.eigenvalues = {half + root, half - root};
  if (l.eigenvalues[1].real() > l.eigenvalues[0].real()) std::swap(l.eigenvalues[0], l.eigenvalues[1]);
  return l;
}

bool isNonDegenerate(const Linearization& l, double gradient_scale, double det_threshold) {
  return std::abs(l.det) > det_threshold * gradient_scale * gradient_scale && l.det != 0.0;
}

Linearization linearizeZero(const PlanarField& field, const Vec2& q) {
  return linearize(field.toWorldJacobian(field.jacobianAtPoint(q)));
}

bool isMorseZero(const PlanarField& field, const Vec2& q, double gradient_scale_radius,
                 double det_threshold) {
  return isNonDegenerate(linearizeZero(field, q), field.gradientScale(q, gradient_scale_radius),
                         det_threshold);
}

CriticalPointType classifyMorse(const Linearization& l, double centre_tolerance) {
  if (l.det < 0) return CriticalPointType::Saddle;
  const double discriminant = l.trace * l.trace - 4 * l.det;
  if (discriminant >= 0) return l.trace > 0 ? CriticalPointType::Source : CriticalPointType::Sink;
  const double re = l.trace / 2, im = std::sqrt(-discriminant) / 2;
  if (std::abs(re) <= centre_tolerance * im) return CriticalPointType::Centre;
  return re > 0 ? CriticalPointType::SpiralSource : CriticalPointType::SpiralSink;
}

CriticalPointType classifyNonMorse(int index, const SectorCounts& s) {
  if (index == -2 && s.hyperbolic == 6 && s.elliptic == 0) return CriticalPointType::MonkeySaddle;
  if (index == 0 && s.hyperbolic == 2 && s.elliptic == 0)
    return s.parabolic > 0 ? CriticalPointType::SaddleNode : CriticalPointType::Cusp;
  if (index == 2 && s.elliptic == 2 && s.hyperbolic == 0) return CriticalPointType::Dipole;
  return CriticalPointType::Degenerate;
}

bool bendixsonHolds(int index, const SectorCounts& s) {
  return 2 * (index - 1) == s.elliptic - s.hyperbolic;
}

std::vector<RadialDirection> saddleEigenDirections(const Linearization& l) {
  Eigen::EigenSolver<Mat2> solver(l.jacobian);
  std::vector<RadialDirection> out;
  for (int k = 0; k < 2; ++k) {
    const bool unstable = solver.eigenvalues()[k].real() > 0;
    const Vec2 e = solver.eigenvectors().col(k).real().normalized();
    out.push_back({e, unstable});
    out.push_back({-e, unstable});
  }
  return out;
}

}  // namespace fluidviz::topology
