// Resampling of analytic fields carried by particles, against the fields themselves.
//
// Error model of the Shepard-normalised estimate (ParticleResampler.h, eq. 2) at a node x:
//   A(x) - f(x) = grad f . m1(x) + 1/2 m2(x) : grad grad f + O(h^3),
// m1, m2 = first and second moments of the normalised weights V_j W_j / c about x. On a regular
// lattice m1 = 0 by symmetry, so linear fields come out exact and the error of curved fields is
// second order (m2 ~ h^2; h = 1.3 dx here). On jittered particles m1 ~ jitter * dx does not
// vanish: the error is first order, and curved fields show order 2 -> 1 as dx falls.
// "Interior" = nodes in [0.25, 0.75]^d, farther than the support 2h = 2.6 dx from the edges of
// the particle cloud [0, 1]^d for every dx used (dx <= 1/12).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "filters/resample/ParticleResampler.h"
#include "tests/filters/resample/ParticleClouds.h"

using namespace fluidviz;
using namespace fluidviz::resample;
using fluidviz::testing::addScalar;
using fluidviz::testing::jitteredBox;

namespace {

constexpr double kPi = std::numbers::pi;
double linear(const Vec3& p) { return 1.0 + 2.0 * p.x() - p.y() + 0.5 * p.z(); }
double quadratic(const Vec3& p) { return p.x() * p.x() + p.y() * p.z(); }
double sine(const Vec3& p) { return std::sin(2 * kPi * p.x()) * std::cos(kPi * p.y()) + p.z(); }

struct Errors {
  double rms = 0.0, max = 0.0;
};

// Particles on [0, 1]^d with spacing 1/n (jittered), resampled onto nodes 1/n apart.
ResampleResult resampleBox(int dimension, int n, double jitter, const std::string& kernel = "cubic_spline") {
  const double dx = 1.0 / n;
  particles::ParticleSet ps = jitteredBox(dimension, 0.0, 1.0, dx, jitter);
  addScalar(ps, "linear", linear);
  addScalar(ps, "quadratic", quadratic);
  addScalar(ps, "sine", sine);
  ParticleResampleParams p;
  p.kernel = fluidviz::choiceNamed<fluidviz::resample::ResampleKernel>(kernel);
  p.spacing = dx;
  p.smoothing_length = 1.3 * dx;
  p.particle_volume = std::pow(dx, dimension);
  return resampleParticles(ps, p);
}

Errors interiorError(const ResampleResult& r, const std::string& name,
                     double (*f)(const Vec3&)) {
  const ScalarField& s = *r.fields.findScalar(name);
  const Grid& g = s.grid;
  const int dimension = g.is2D() ? 2 : 3;
  Errors e;
  long count = 0;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const Vec3 p = g.position(i, j, k);
        bool inside = true;
        for (int a = 0; a < dimension; ++a) inside = inside && p[a] >= 0.25 && p[a] <= 0.75;
        if (!inside) continue;
        const double d = std::abs(s.values[g.index(i, j, k)] - f(p));
        e.rms += d * d, e.max = std::max(e.max, d), ++count;
      }
  e.rms = std::sqrt(e.rms / count);
  return e;
}

}  // namespace

// On a lattice the first moment vanishes: linear fields are reproduced to rounding (every
// kernel, 2D and 3D).
TEST(ResampleAnalytic, LatticeReproducesLinearFieldsExactly) {
  for (int dimension : {2, 3})
    for (const std::string& kernel : choiceNames<ResampleKernel>()) {
      const Errors e = interiorError(resampleBox(dimension, 24, 0.0, kernel), "linear", linear);
      EXPECT_LT(e.max, 1e-12) << dimension << "D " << kernel;
    }
}

// Issue acceptance: linear field on particles jittered by up to 10% of their spacing, 48^3
// particles: interior error within 1e-3 of the field's range over the box (3.5). Measured:
// 7.6e-4. The error halves with dx (first order, m1 ~ jitter dx): ratio 24 -> 48 in [1.7, 2.4]
// (measured 2.05 on the RMS).
TEST(ResampleAnalytic, JitteredLinearWithin1e3OfRangeAndFirstOrder) {
  const double range = 3.5;
  const Errors coarse = interiorError(resampleBox(3, 24, 0.1), "linear", linear);
  const Errors fine = interiorError(resampleBox(3, 48, 0.1), "linear", linear);
  EXPECT_LT(fine.max / range, 1e-3);
  EXPECT_GT(coarse.rms / fine.rms, 1.7);
  EXPECT_LT(coarse.rms / fine.rms, 2.4);
}

// Curved fields on a lattice: second order. RMS error ratio per halving of dx, 24 -> 48:
// 4.00 (quadratic: m2 is exactly proportional to h^2), 3.95 (sine, h^4 terms still visible).
TEST(ResampleAnalytic, LatticeErrorOfCurvedFieldsIsSecondOrder) {
  const ResampleResult coarse = resampleBox(3, 24, 0.0), fine = resampleBox(3, 48, 0.0);
  using Field = double (*)(const Vec3&);
  for (auto [name, f] : {std::pair<const char*, Field>{"quadratic", quadratic},
                         std::pair<const char*, Field>{"sine", sine}}) {
    const double ratio = interiorError(coarse, name, f).rms / interiorError(fine, name, f).rms;
    EXPECT_NEAR(ratio, 4.0, 0.15) << name;
  }
}

// Jittered particles: the sine's error still falls ~h^2 at these resolutions (ratio 3.6-3.7
// measured for 12 -> 24 -> 48) while the jitter's first-order term grows in share; the
// quadratic's error is already dominated by it (ratios 3.3, 2.6). Both stay above 2 (order > 1).
TEST(ResampleAnalytic, JitteredErrorFallsBetweenFirstAndSecondOrder) {
  const ResampleResult r12 = resampleBox(3, 12, 0.1), r24 = resampleBox(3, 24, 0.1),
                       r48 = resampleBox(3, 48, 0.1);
  const double sine1 = interiorError(r12, "sine", sine).rms / interiorError(r24, "sine", sine).rms;
  const double sine2 = interiorError(r24, "sine", sine).rms / interiorError(r48, "sine", sine).rms;
  EXPECT_GT(sine1, 3.2);
  EXPECT_GT(sine2, 3.2);
  EXPECT_LT(sine2, 4.3);
  const double quad = interiorError(r24, "quadratic", quadratic).rms /
                      interiorError(r48, "quadratic", quadratic).rms;
  EXPECT_GT(quad, 2.0);
  EXPECT_LT(quad, 4.3);
}

// Shepard normalisation reproduces a constant at every supported node, also at the edge of the
// particle cloud where the colour field has dropped to the threshold; unsupported nodes are
// flagged (mask 0) and hold NaN, never 0.
TEST(ResampleAnalytic, ConstantIsExactWhereSupportedAndUnsupportedNodesAreMasked) {
  particles::ParticleSet ps = jitteredBox(3, 0.0, 1.0, 1.0 / 12, 0.25);
  addScalar(ps, "constant", [](const Vec3&) { return 2.5; });
  ParticleResampleParams p;
  p.padding = 0.5;  // nodes far beyond the support of any particle
  const ResampleResult r = resampleParticles(ps, p);
  const auto& v = r.fields.findScalar("constant")->values;
  const auto& mask = r.fields.findScalar("mask")->values;
  const auto& color = r.fields.findScalar("color")->values;
  std::size_t masked = 0;
  for (std::size_t n = 0; n < v.size(); ++n) {
    if (mask[n] == 1.0) {
      EXPECT_NEAR(v[n], 2.5, 1e-13);
      EXPECT_GE(color[n], p.support_threshold);
    } else {
      ASSERT_EQ(mask[n], 0.0);
      EXPECT_TRUE(std::isnan(v[n]));
      EXPECT_LT(color[n], p.support_threshold);
      ++masked;
    }
  }
  EXPECT_GT(masked, v.size() / 2);  // the 0.5 m padding is mostly out of reach
  EXPECT_EQ(masked, r.report.unsupportedNodes);
}

// Interior colour field c = sum_j V_j W_j is 1 within the kernel's discretisation error on a
// lattice with V_j = dx^3: the cubic spline's lattice sum at h = 1.3 dx is 0.99726 at the
// particles (the grid nodes here); tolerance 3e-3. Summation density = (m / V) c.
TEST(ResampleAnalytic, ColourFieldIsOneInsideAndSummationDensityIsMassOverVolume) {
  const double dx = 1.0 / 24;
  particles::ParticleSet ps = jitteredBox(3, 0.0, 1.0, dx, 0.0);
  ps.scalars.push_back({"mass", std::vector<double>(ps.size(), 1000.0 * dx * dx * dx)});
  ps.scalars.push_back({"density", std::vector<double>(ps.size(), 1000.0)});
  const ResampleResult r = resampleParticles(ps, ParticleResampleParams{});
  const Grid& g = r.fields.grid;
  const auto& c = r.fields.findScalar("color")->values;
  const auto& rho = r.fields.findScalar("summation_density")->values;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const Vec3 x = g.position(i, j, k);
        if ((x.array() < 0.25).any() || (x.array() > 0.75).any()) continue;
        EXPECT_NEAR(c[g.index(i, j, k)], 1.0, 3e-3);
        EXPECT_NEAR(rho[g.index(i, j, k)], 1000.0 * c[g.index(i, j, k)], 1e-9);
      }
}

// Every node sums the same terms in the same order whatever the thread count: bitwise equal.
TEST(ResampleAnalytic, ResultDoesNotDependOnThreadCount) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const ResampleResult one = resampleBox(3, 20, 0.25);
  omp_set_num_threads(std::max(2, threads));
  const ResampleResult many = resampleBox(3, 20, 0.25);
  omp_set_num_threads(threads);
  for (const char* name : {"sine", "color"}) {
    const auto& a = one.fields.findScalar(name)->values;
    const auto& b = many.fields.findScalar(name)->values;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << name;
  }
}
