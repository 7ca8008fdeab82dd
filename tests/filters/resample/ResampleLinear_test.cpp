// The first-order option of the resampler (order = linear, filters/resample/LinearResample.h):
// moving least squares with the basis (1, x - x_node) weighted by the SPH kernel, the
// reproducing-kernel correction of Liu, Jun & Zhang (1995) and Bonet & Lok (1999). The reference
// is the analytic property of that method: a field f = a + b.x is reproduced exactly (to
// rounding) by any arrangement whose moment matrix is invertible, while Shepard's estimate
// (Shepard 1968) carries the error grad f . m1 of the kernel's first moment on jittered
// particles (ResampleAnalytic_test.cpp). Where the moment matrix is singular (particles on one
// line in 2D) the node must keep Shepard's value and say so in resample_order.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include <Eigen/LU>

#include "filters/resample/LinearResample.h"
#include "filters/resample/ParticleResampler.h"
#include "tests/filters/resample/ParticleClouds.h"

using namespace fluidviz;
using namespace fluidviz::resample;
using fluidviz::testing::addScalar;
using fluidviz::testing::jitteredBox;

namespace {

// The required accuracy of the first-order option (issue 22). Rounding gives ~1e-14: a
// tolerance far above it, and far below Shepard's error (> 1e-4 on the same particles).
constexpr double kLinearTolerance = 1e-6;
constexpr double kShepardMinimumError = 1e-4;

const Vec3 kGradient(2.0, -1.0, 0.5);
double linearField(const Vec3& p) { return 1.5 + kGradient.dot(p); }

// Particles on [0, 1]^d, spacing 1/n, jittered by up to a quarter spacing per axis (fixed
// seed), carrying linearField and (3D) a linear vector field; nodes 1/n apart, h = 1.3 / n.
particles::ParticleSet jitteredLinearBox(int dimension, int n) {
  particles::ParticleSet ps = jitteredBox(dimension, 0.0, 1.0, 1.0 / n, 0.25, 2022);
  addScalar(ps, "f", linearField);
  if (dimension == 3) {
    particles::ParticleVectors v{"velocity", {}};
    for (const Vec3& x : ps.positions) v.values.push_back(Vec3(x.y(), 2.0 - x.z(), x.x() + x.y()));
    ps.vectors.push_back(std::move(v));
  }
  return ps;
}

ParticleResampleParams boxParams(int dimension, int n, ResampleOrder order) {
  ParticleResampleParams p;
  p.order = order;
  p.spacing = 1.0 / n;
  p.smoothing_length = 1.3 / n;
  p.particle_volume = std::pow(1.0 / n, dimension);
  return p;
}

// "Interior": nodes in [0.25, 0.75]^d, farther than the support 2h = 2.6/n (n >= 16) from the
// edges of the particle cloud.
bool interior(const Vec3& x, int dimension) {
  for (int a = 0; a < dimension; ++a)
    if (x[a] < 0.25 || x[a] > 0.75) return false;
  return true;
}

struct Interior {
  double relativeError = 0.0;  // max |A - f| / max |f| over interior nodes
  int nodes = 0;
  int firstOrder = 0;  // interior nodes with resample_order 1
};

Interior interiorError(const ResampleResult& r, int dimension) {
  const ScalarField& a = *r.fields.findScalar("f");
  const ScalarField* order = r.fields.findScalar(kResampleOrderArray);
  const Grid& g = a.grid;
  double maxError = 0.0, maxF = 0.0;
  Interior e;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const Vec3 x = g.position(i, j, k);
        if (!interior(x, dimension)) continue;
        const std::size_t n = g.index(i, j, k);
        maxError = std::max(maxError, std::abs(a.values[n] - linearField(x)));
        maxF = std::max(maxF, std::abs(linearField(x)));
        ++e.nodes;
        if (order && order->values[n] == 1.0) ++e.firstOrder;
      }
  e.relativeError = maxError / maxF;
  return e;
}

// Both NaN, or the same bits.
bool identical(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}

void expectIdenticalArray(const ResampleResult& a, const ResampleResult& b,
                          const std::string& name) {
  const ScalarField& x = *a.fields.findScalar(name);
  const ScalarField& y = *b.fields.findScalar(name);
  ASSERT_EQ(x.values.size(), y.values.size()) << name;
  for (std::size_t n = 0; n < x.values.size(); ++n)
    ASSERT_TRUE(identical(x.values[n], y.values[n]))
        << name << " node " << n << ": " << x.values[n] << " vs " << y.values[n];
}

void expectLinearExactWhereShepardIsNot(int dimension, int n) {
  const particles::ParticleSet ps = jitteredLinearBox(dimension, n);
  const ResampleResult linear = resampleParticles(ps, boxParams(dimension, n, ResampleOrder::linear));
  const ResampleResult shepard =
      resampleParticles(ps, boxParams(dimension, n, ResampleOrder::shepard));
  const Interior l = interiorError(linear, dimension), s = interiorError(shepard, dimension);
  std::printf("%dD, %zu particles: interior relative error linear %.3g, shepard %.3g; first "
              "order at %zu of %zu supported nodes\n",
              dimension, ps.size(), l.relativeError, s.relativeError,
              linear.report.firstOrderNodes, linear.report.supportedNodes);
  ASSERT_GT(l.nodes, 0);
  EXPECT_EQ(l.firstOrder, l.nodes) << "an interior node fell back to Shepard";
  EXPECT_LE(l.relativeError, kLinearTolerance);
  EXPECT_GT(s.relativeError, kShepardMinimumError) << "the data would not reveal a fallback";
  if (dimension == 3) {  // every component of a vector array, at every first-order node
    const VectorField& v = *linear.fields.findVector("velocity");
    const ScalarField& order = *linear.fields.findScalar(kResampleOrderArray);
    const Grid& g = v.grid;
    double worst = 0.0;
    for (int k = 0; k < g.dims[2]; ++k)
      for (int j = 0; j < g.dims[1]; ++j)
        for (int i = 0; i < g.dims[0]; ++i) {
          const std::size_t m = g.index(i, j, k);
          if (order.values[m] != 1.0) continue;
          const Vec3 x = g.position(i, j, k);
          worst = std::max(worst, (v.values[m] - Vec3(x.y(), 2.0 - x.z(), x.x() + x.y()))
                                      .lpNorm<Eigen::Infinity>());
        }
    EXPECT_LE(worst, kLinearTolerance);
  }
}

}  // namespace

TEST(ResampleLinear, LinearFieldExactOnJitteredParticles2D) {
  expectLinearExactWhereShepardIsNot(2, 40);
}

TEST(ResampleLinear, LinearFieldExactOnJitteredParticles3D) {
  expectLinearExactWhereShepardIsNot(3, 16);
}

// Particles on one straight line in 2D: p_j = (1, u_x, u_y) with u_y the same for every j, so M
// is singular at every node. Every node keeps the Shepard value, bit for bit, with order 0.
TEST(ResampleLinear, ParticlesOnALineFallBackToShepard) {
  particles::ParticleSet ps;
  ps.dimension = 2;
  for (int i = 0; i < 40; ++i) ps.positions.push_back(Vec3(0.1 + 0.025 * i + 0.004 * std::sin(i), 0.5, 0.0));
  addScalar(ps, "f", linearField);
  ParticleResampleParams p = boxParams(2, 40, ResampleOrder::linear);
  const ResampleResult linear = resampleParticles(ps, p);
  p.order = ResampleOrder::shepard;
  const ResampleResult shepard = resampleParticles(ps, p);
  ASSERT_GT(linear.report.supportedNodes, 0u);
  EXPECT_EQ(linear.report.firstOrderNodes, 0u);
  const ScalarField& order = *linear.fields.findScalar(kResampleOrderArray);
  for (double o : order.values) ASSERT_EQ(o, 0.0);
  expectIdenticalArray(linear, shepard, "f");
}

// order = shepard is the existing path: no resample_order array, and the values of eq. (2)
// computed here by brute force (to 1e-12 relative). The linear run leaves colour and mask as
// they are.
TEST(ResampleLinear, ShepardOptionIsTheShepardEstimate) {
  const int n = 12;
  particles::ParticleSet ps = jitteredLinearBox(2, n);
  const ParticleResampleParams p = boxParams(2, n, ResampleOrder::shepard);
  EXPECT_EQ(ParticleResampleParams{}.order, ResampleOrder::shepard);
  const ResampleResult r = resampleParticles(ps, p);
  EXPECT_EQ(r.fields.findScalar(kResampleOrderArray), nullptr);
  const ScalarField& a = *r.fields.findScalar("f");
  const ScalarField& mask = *r.fields.findScalar(kMaskArray);
  const auto kernel = makeInterpolationKernel(p.kernel, *p.smoothing_length, 2);
  const Grid& g = a.grid;
  int compared = 0;
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      const std::size_t m = g.index(i, j);
      if (mask.values[m] != 1.0) continue;
      double c = 0.0, s = 0.0;
      for (std::size_t q = 0; q < ps.size(); ++q) {
        const double w = *p.particle_volume * evaluate(kernel, (ps.positions[q] - g.position(i, j)).norm());
        c += w, s += w * ps.scalars[0].values[q];
      }
      EXPECT_NEAR(a.values[m], s / c, 1e-12 * std::abs(s / c)) << "node " << i << " " << j;
      ++compared;
    }
  EXPECT_GT(compared, 100);
  const ResampleResult linear = resampleParticles(ps, boxParams(2, n, ResampleOrder::linear));
  expectIdenticalArray(linear, r, kColorArray);
  expectIdenticalArray(linear, r, kMaskArray);
}

// A curved field, which the linear fit does not reproduce, so that every particle of the
// neighbourhood counts: at every first-order node the resampler's value is eq. (4) evaluated
// here by brute force over all particles (Eigen's full-pivot LU instead of LDLT; to 1e-10 of
// the field's scale). A particle missed or counted twice by the neighbour search would show.
TEST(ResampleLinear, CurvedFieldMatchesBruteForceMovingLeastSquares) {
  const int n = 10;
  particles::ParticleSet ps = jitteredBox(3, 0.0, 1.0, 1.0 / n, 0.25, 11);
  addScalar(ps, "g", [](const Vec3& x) { return std::sin(3 * x.x()) * std::cos(2 * x.y()) + x.z() * x.z(); });
  const ParticleResampleParams p = boxParams(3, n, ResampleOrder::linear);
  const ResampleResult r = resampleParticles(ps, p);
  const auto kernel = makeInterpolationKernel(p.kernel, *p.smoothing_length, 3);
  const ScalarField& g = *r.fields.findScalar("g");
  const ScalarField& order = *r.fields.findScalar(kResampleOrderArray);
  const Grid& grid = g.grid;
  const double h = *p.smoothing_length;
  int compared = 0;
  for (int k = 0; k < grid.dims[2]; ++k)
    for (int j = 0; j < grid.dims[1]; ++j)
      for (int i = 0; i < grid.dims[0]; ++i) {
        const std::size_t node = grid.index(i, j, k);
        if (order.values[node] != 1.0) continue;
        const Vec3 x = grid.position(i, j, k);
        Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
        Eigen::Vector4d b = Eigen::Vector4d::Zero();
        for (std::size_t q = 0; q < ps.size(); ++q) {
          const double w = *p.particle_volume * evaluate(kernel, (ps.positions[q] - x).norm());
          Eigen::Vector4d pj;
          pj << 1.0, (ps.positions[q] - x) / h;
          m += w * pj * pj.transpose();
          b += w * pj * ps.scalars[0].values[q];
        }
        const double expected = m.fullPivLu().solve(b)[0];
        ASSERT_NEAR(g.values[node], expected, 1e-10) << "node " << i << " " << j << " " << k;
        ++compared;
      }
  EXPECT_GT(compared, 1000);
}

// Each node is independent of the others: the same bits with 1 and 2 threads.
TEST(ResampleLinear, SameResultForAnyThreadCount) {
  const particles::ParticleSet ps = jitteredLinearBox(3, 12);
  const ParticleResampleParams p = boxParams(3, 12, ResampleOrder::linear);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const ResampleResult one = resampleParticles(ps, p);
  omp_set_num_threads(2);
  const ResampleResult two = resampleParticles(ps, p);
  omp_set_num_threads(threads);
  expectIdenticalArray(one, two, "f");
  expectIdenticalArray(one, two, kResampleOrderArray);
}

// The conditioning test is scale-free (offsets in units of h): the same particles in km or mm
// (positions, spacing, h and volume scaled together) fall back at the same nodes.
TEST(ResampleLinear, FallbackDoesNotDependOnTheLengthUnit) {
  const int n = 16;
  const particles::ParticleSet metres = jitteredLinearBox(2, n);
  ParticleResampleParams unscaled = boxParams(2, n, ResampleOrder::linear);
  unscaled.support_threshold = 0.0;  // every node the kernels reach: the fringe falls back
  const ResampleResult reference = resampleParticles(metres, unscaled);
  ASSERT_GT(reference.report.firstOrderNodes, 0u);
  ASSERT_LT(reference.report.firstOrderNodes, reference.report.supportedNodes);  // some fall back
  for (double scale : {1e3, 1e-3}) {
    particles::ParticleSet scaled = metres;
    for (Vec3& x : scaled.positions) x *= scale;
    ParticleResampleParams p = unscaled;
    p.spacing = *p.spacing * scale;
    p.smoothing_length = *p.smoothing_length * scale;
    p.particle_volume = *p.particle_volume * scale * scale;
    const ResampleResult r = resampleParticles(scaled, p);
    ASSERT_EQ(r.fields.grid.dims, reference.fields.grid.dims) << scale;
    expectIdenticalArray(r, reference, kResampleOrderArray);
  }
}
