#include "solvers/surface/validation/SphericalHarmonics.h"

#include <cmath>
#include <stdexcept>

namespace fluidviz::surface {

double associatedLegendre(int l, int m, double x) {
  if (m < 0 || m > l) throw std::invalid_argument("associatedLegendre needs 0 <= m <= l");
  // P_m^m = (2m - 1)!! (1 - x^2)^(m/2); P_{m+1}^m = x (2m + 1) P_m^m;
  // (l - m) P_l^m = x (2l - 1) P_{l-1}^m - (l + m - 1) P_{l-2}^m.
  const double s = std::sqrt(std::max(0.0, 1.0 - x * x));
  double pmm = 1.0;
  for (int i = 1; i <= m; ++i) pmm *= (2.0 * i - 1.0) * s;
  if (l == m) return pmm;
  double prev = pmm, cur = x * (2.0 * m + 1.0) * pmm;
  for (int n = m + 2; n <= l; ++n) {
    const double next = (x * (2.0 * n - 1.0) * cur - (n + m - 1.0) * prev) / (n - m);
    prev = cur;
    cur = next;
  }
  return cur;
}

double realSphericalHarmonic(int l, int m, const Eigen::Vector3d& p) {
  const double r = p.norm();
  const double phi = std::atan2(p.y(), p.x());
  const double legendre = associatedLegendre(l, std::abs(m), p.z() / r);
  return m >= 0 ? legendre * std::cos(m * phi) : legendre * std::sin(-m * phi);
}

Eigen::VectorXd sampleSphericalHarmonic(const TriangleMesh& mesh, int l, int m) {
  Eigen::VectorXd y(mesh.vertexCount());
  for (int i = 0; i < mesh.vertexCount(); ++i) y[i] = realSphericalHarmonic(l, m, mesh.vertices[i]);
  return y;
}

}  // namespace fluidviz::surface
