// Kernel properties (SPlisHSPlasH-style), each in 2D and 3D with h = 1 (support 2):
//   normalisation        int W dV = 1                         within 1e-4
//   zero mean gradient   |int grad W dV| h = 0                 within 1e-4
//   first moment         int x_a dW/dx_b dV = -delta_ab        within 1e-4 (checks that the
//                        gradient is the derivative of the normalised W)
//   Laplacian            int r^2 lap W dV = 2 d                within 1e-4 (poly6, viscosity)
//   derivative           dW/dr = central difference of W       within 1e-6 relative
// Quadrature: midpoint rule on a Cartesian grid of spacing 0.01 (2D) / 0.02 (3D) whose cells are
// shifted off the origin by a fraction of a cell (so that odd integrands do not cancel by
// symmetry). The viscosity kernel W ~ 1/r is singular at 0: its normalisation and first moment
// use Gauss-Legendre quadrature in r with the r^(d-1) Jacobian instead.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "fieldviz/particles/KernelCubicSpline.h"
#include "fieldviz/particles/KernelWendlandC2.h"
#include "fieldviz/particles/KernelsMuller2003.h"

namespace fluidviz::particles {
namespace {

constexpr double kTol = 1e-4;

struct Moments {
  double integral = 0.0;        // int W
  Vec3 gradient = Vec3::Zero();  // int grad W
  Eigen::Matrix3d first = Eigen::Matrix3d::Zero();  // int x_a dW/dx_b
};

// Midpoint quadrature over [-R, R]^d on an offset grid.
template <class K>
Moments integrate(const K& k, int dim) {
  const double R = k.support(), d = dim == 2 ? 0.01 : 0.02;
  const Vec3 offset(0.31, 0.17, 0.43);
  const int n = static_cast<int>(std::ceil(R / d)) + 1;
  const double cell = std::pow(d, dim);
  Moments m;
  const int nz = dim == 3 ? n : 0;
  for (int iz = -nz; iz <= nz; ++iz)
    for (int iy = -n; iy <= n; ++iy)
      for (int ix = -n; ix <= n; ++ix) {
        const Vec3 x = d * (Vec3(ix, iy, iz) + offset).cwiseProduct(Vec3(1, 1, dim == 3 ? 1 : 0));
        const double r = x.norm();
        if (r >= R) continue;
        const Vec3 g = k.gradW(x, r);
        m.integral += k.W(r) * cell;
        m.gradient += g * cell;
        m.first += x * g.transpose() * cell;
      }
  return m;
}

// int_0^R f(r) S_d r^(d-1) dr, composite 8-point Gauss-Legendre on 200 panels.
double radialIntegral(const std::function<double(double)>& f, double R, int dim) {
  static const double xg[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                               0.9602898564975363};
  static const double wg[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                               0.1012285362903763};
  const double surface = dim == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
  const int panels = 200;
  const double w = R / panels;
  double sum = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double mid = (p + 0.5) * w;
    for (int q = 0; q < 4; ++q)
      for (int s : {-1, 1}) {
        const double r = mid + s * 0.5 * w * xg[q];
        sum += 0.5 * w * wg[q] * f(r) * surface * std::pow(r, dim - 1);
      }
  }
  return sum;
}

template <class K>
void expectGridProperties(const K& k, int dim) {
  const Moments m = integrate(k, dim);
  EXPECT_NEAR(m.integral, 1.0, kTol) << "normalisation, d = " << dim;
  EXPECT_LT(m.gradient.norm(), kTol) << "int grad W, d = " << dim;
  for (int a = 0; a < dim; ++a)
    for (int b = 0; b < dim; ++b)
      EXPECT_NEAR(m.first(a, b), a == b ? -1.0 : 0.0, kTol)
          << "first moment (" << a << ", " << b << "), d = " << dim;
}

template <class K>
void expectDerivativeMatchesW(const K& k) {
  const double e = 1e-6;
  for (double r = 0.05; r < k.support() - 2 * e; r += 0.0937) {
    const double fd = (k.W(r + e) - k.W(r - e)) / (2 * e);
    EXPECT_NEAR(k.dWdr(r), fd, 1e-6 * std::max(1.0, std::abs(fd))) << "r = " << r;
  }
}

TEST(KernelCubicSpline, IntegratesToOneWithConsistentGradient) {
  for (int dim : {2, 3}) {
    const KernelCubicSpline k(1.0, dim);
    expectGridProperties(k, dim);
    expectDerivativeMatchesW(k);
  }
}

TEST(KernelWendlandC2, IntegratesToOneWithConsistentGradient) {
  for (int dim : {2, 3}) {
    const KernelWendlandC2 k(1.0, dim);
    expectGridProperties(k, dim);
    expectDerivativeMatchesW(k);
  }
}

TEST(KernelPoly6, IntegratesToOneWithConsistentGradientAndLaplacian) {
  for (int dim : {2, 3}) {
    const KernelPoly6 k(1.0, dim);
    expectGridProperties(k, dim);
    expectDerivativeMatchesW(k);
    // lap W = W'' + (d-1) W'/r against finite differences, and int r^2 lap W = 2 d.
    for (double r = 0.1; r < 1.95; r += 0.173) {
      const double e = 1e-5;
      const double fd = (k.dWdr(r + e) - k.dWdr(r - e)) / (2 * e) + (dim - 1) * k.dWdr(r) / r;
      EXPECT_NEAR(k.laplacianW(r), fd, 1e-6 * std::max(1.0, std::abs(fd))) << "r = " << r;
    }
    EXPECT_NEAR(radialIntegral([&](double r) { return r * r * k.laplacianW(r); }, k.support(), dim),
                2.0 * dim, kTol);
    EXPECT_NEAR(radialIntegral([&](double r) { return k.laplacianW(r); }, k.support(), dim), 0.0,
                kTol);
  }
}

TEST(KernelSpiky, IntegratesToOneWithConsistentGradient) {
  for (int dim : {2, 3}) {
    const KernelSpiky k(1.0, dim);
    expectGridProperties(k, dim);
    expectDerivativeMatchesW(k);
  }
}

TEST(KernelViscosity, IntegratesToOneAndLaplacianHasSecondMoment2d) {
  for (int dim : {2, 3}) {
    const KernelViscosity k(1.0, dim);
    EXPECT_NEAR(radialIntegral([&](double r) { return k.W(r); }, k.support(), dim), 1.0, kTol)
        << "d = " << dim;
    // Its gradient ~ 1/r^2 is not integrable on a grid: first moment in radial form,
    // int r dW/dr dV = -d (the trace of int x grad W^T = -I).
    EXPECT_NEAR(radialIntegral([&](double r) { return r * k.dWdr(r); }, k.support(), dim),
                -double(dim), kTol);
    expectDerivativeMatchesW(k);
    EXPECT_NEAR(radialIntegral([&](double r) { return r * r * k.laplacianW(r); }, k.support(), dim),
                2.0 * dim, kTol);
    EXPECT_GT(k.laplacianW(0.5 * k.support()), 0.0);  // only damps
  }
  // In 3D the linear Laplacian is the exact one: W'' + 2 W'/r.
  const KernelViscosity k(1.0, 3);
  for (double r = 0.2; r < 1.95; r += 0.173) {
    const double e = 1e-5;
    const double exact = (k.dWdr(r + e) - k.dWdr(r - e)) / (2 * e) + 2.0 * k.dWdr(r) / r;
    EXPECT_NEAR(k.laplacianW(r), exact, 1e-5 * std::abs(exact)) << "r = " << r;
  }
}

TEST(Kernels, RejectInvalidArguments) {
  EXPECT_THROW(KernelCubicSpline(0.0, 2), std::invalid_argument);
  EXPECT_THROW(KernelWendlandC2(1.0, 4), std::invalid_argument);
  EXPECT_THROW(KernelPoly6(-1.0, 3), std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz::particles
