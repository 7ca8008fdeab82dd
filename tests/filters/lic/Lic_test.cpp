// Line Integral Convolution: noise statistics along and across the flow, FastLIC against the
// reference, determinism, masking, contrast, slices and errors.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "filters/lic/LineIntegralConvolution.h"
#include "tests/filters/lic/LicStatistics.h"
#include "tests/support/AnalyticFields.h"

using namespace fluidviz;
using namespace fluidviz::lic;
using namespace fluidviz::testing;

namespace {

LicParams rawParams(const std::string& method, int size, double length) {
  LicParams p;
  p.method = fluidviz::choiceNamed<fluidviz::lic::LicMethod>(method);
  p.width = size;
  p.height = size;
  p.length = length;
  p.contrast = false;  // raw convolution values: the statistics below are about those
  return p;
}

// v = (2, 1): pixel (i, j) and pixel (i + 2m, j + m) lie on the same straight streamline, lag
// m sqrt 5 px apart; (i - m, j + 2m) is m sqrt 5 px across the flow.
VectorField uniformDiagonal() { return uniformField(squareGrid(65, 0.0, 1.0), Vec3(2.0, 1.0, 0.0)); }

}  // namespace

// A box kernel of half-length L averages white noise over 2L px of streamline, so two pixels on
// the same line tau px apart share 2L - tau of it: correlation 1 - tau / 2L (> 0.9 for tau <= L/5).
// Lines >= 2 noise cells apart share no cells: correlation ~ 0. Bilinear noise is itself
// correlated over ~1 px along the line, which lifts the measured curve 0.01-0.025 above 1 - tau/2L.
TEST(Lic, UniformFieldIsCorrelatedAlongTheFlowAndNotAcross) {
  const VectorField v = uniformDiagonal();
  for (const std::string method : {"reference", "fast"}) {
    const LicImage img = computeLic(v, rawParams(method, 256, 15.0));
    const int margin = 20;  // full kernels only: L + 5 px from the border
    for (int m = 1; m <= 6; ++m) {
      const double tau = m * std::sqrt(5.0);
      const double along = offsetCorrelation(img, 2 * m, m, margin);
      std::printf("%s: along-flow correlation at lag %.2f px = %.3f (theory %.3f)\n",
                  method.c_str(), tau, along, 1 - tau / 30.0);
      EXPECT_NEAR(along, 1 - tau / 30.0, 0.04) << method << " lag " << tau;
      if (tau <= 15.0 / 5) {
        EXPECT_GT(along, 0.9);
      }
    }
    for (int m = 1; m <= 3; ++m) {
      const double across = offsetCorrelation(img, -m, 2 * m, margin);
      std::printf("%s: across-flow correlation at %.2f px = %.3f\n", method.c_str(),
                  m * std::sqrt(5.0), across);
      EXPECT_LT(std::abs(across), 0.2) << method;
    }
  }
}

// Pairs of pixel centres on the same circle (radii equal within 0.05 px) 1.5 - 3 px of arc
// apart, and pairs on the same ray 2 - 3 px (>= 2 noise cells) apart radially.
TEST(Lic, RotationFieldIsCorrelatedAlongCirclesAndNotAcross) {
  const VectorField v = rotationField(squareGrid(101, -1.0, 1.0));
  for (const std::string method : {"reference", "fast"}) {
    const LicImage img = computeLic(v, rawParams(method, 256, 20.0));
    PairSums along, across;
    for (int j = 0; j < 256; ++j)
      for (int i = 0; i < 256; ++i) {
        const double x = i + 0.5 - 128, y = j + 0.5 - 128, r = std::hypot(x, y);
        if (r < 30 || r > 100) continue;
        for (int dj = -4; dj <= 4; ++dj)
          for (int di = -4; di <= 4; ++di) {
            const double x2 = x + di, y2 = y + dj, r2 = std::hypot(x2, y2);
            const double arc = r * std::abs(std::remainder(std::atan2(y2, x2) - std::atan2(y, x),
                                                           2 * std::numbers::pi));
            if (std::abs(r2 - r) < 0.05 && arc >= 1.5 && arc <= 3.0)
              along.add(pixel(img, i, j), pixel(img, i + di, j + dj));
            if (arc < 0.25 && r2 - r >= 2.0 && r2 - r <= 3.0)
              across.add(pixel(img, i, j), pixel(img, i + di, j + dj));
          }
      }
    std::printf("%s rotation: along circles %.3f (%ld pairs), across %.3f (%ld pairs)\n",
                method.c_str(), along.correlation(), along.n, across.correlation(), across.n);
    ASSERT_GT(along.n, 1000);
    ASSERT_GT(across.n, 1000);
    EXPECT_GT(along.correlation(), 0.9) << method;
    EXPECT_LT(std::abs(across.correlation()), 0.2) << method;
  }
}

// FastLIC deposits values computed at samples anywhere inside a pixel, not at its centre, so it
// differs from the reference by the decorrelation over that sub-pixel offset. Measured on curved
// fields with the same noise and kernel (L = 15 px, grain 1, fast_min_hits 2, raw values whose
// std is ~0.045-0.055):
//   bilinear noise: mean |d| 0.0077-0.0096, p99 0.032-0.039, correlation 0.972-0.973
//   nearest noise:  mean |d| 0.019,         p99 0.068,       correlation 0.898
// (fast_min_hits 4 brings bilinear to mean 0.0072, p99 0.028, correlation 0.98.)
TEST(Lic, FastAgreesWithReferencePerPixel) {
  const Grid g = squareGrid(101, -1.0, 1.0);
  struct Case {
    const char* name;
    VectorField field;
    const char* kernel;
    const char* noise;
    double meanAbs, p99, correlation;  // tolerances
  };
  for (const Case& c : {Case{"rotation", rotationField(g), "box", "bilinear", 0.01, 0.045, 0.96},
                        Case{"saddle", saddleField(g), "box", "bilinear", 0.01, 0.045, 0.96},
                        Case{"saddle", saddleField(g), "hann", "bilinear", 0.011, 0.045, 0.96},
                        Case{"saddle", saddleField(g), "box", "nearest", 0.022, 0.08, 0.87}}) {
    LicParams p = rawParams("reference", 200, 15.0);
    p.kernel = fluidviz::choiceNamed<fluidviz::lic::KernelShape>(c.kernel);
    p.noise_interpolation = fluidviz::choiceNamed<fluidviz::lic::NoiseInterpolation>(c.noise);
    const LicImage ref = computeLic(c.field, p);
    p.method = fluidviz::lic::LicMethod::fast;
    const LicImage fast = computeLic(c.field, p);
    const Differences d = differences(ref.texture.values, fast.texture.values);
    PairSums corr;
    for (std::size_t q = 0; q < ref.texture.values.size(); ++q)
      corr.add(ref.texture.values[q], fast.texture.values[q]);
    std::printf("%s/%s/%s noise: fast vs reference mean |d| %.4f, p99 %.4f, max %.4f, ref std "
                "%.4f, correlation %.3f\n", c.name, c.kernel, c.noise, d.meanAbs, d.p99, d.max,
                standardDeviation(ref.texture.values), corr.correlation());
    EXPECT_LT(d.meanAbs, c.meanAbs) << c.name << " " << c.kernel << " " << c.noise;
    EXPECT_LT(d.p99, c.p99) << c.name << " " << c.kernel << " " << c.noise;
    EXPECT_GT(corr.correlation(), c.correlation) << c.name << " " << c.kernel << " " << c.noise;
  }
}

TEST(Lic, SameSeedGivesTheSameImageForAnyThreadCount) {
  const VectorField v = saddleField(squareGrid(51, -1.0, 1.0));
  for (const std::string method : {"reference", "fast"}) {
    LicParams p = rawParams(method, 128, 10.0);
    const LicImage a = computeLic(v, p);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const LicImage b = computeLic(v, p);
    omp_set_num_threads(threads);
    EXPECT_EQ(a.texture.values, b.texture.values) << method;
    p.noise_seed = 2;
    const LicImage c = computeLic(v, p);
    const Differences d = differences(a.texture.values, c.texture.values);
    // Independent noise: |difference| of two values with std ~0.045 averages ~0.05.
    EXPECT_GT(d.meanAbs, 0.02) << method;
  }
}

// With v = 0 every streamline stops at once, so each pixel keeps its noise value.
TEST(Lic, ZeroFieldGivesPlainNoise) {
  const VectorField v = uniformField(squareGrid(33, 0.0, 1.0), Vec3::Zero());
  const NoiseTexture noise = NoiseTexture::white(64, 64, 1.0, 7);
  for (const std::string method : {"reference", "fast"}) {
    LicParams p = rawParams(method, 64, 10.0);
    p.noise_seed = 7;
    const LicImage img = computeLic(v, p);
    double maxDiff = 0;
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i)
        maxDiff = std::max(maxDiff, std::abs(pixel(img, i, j) - noise.at(i + 0.5, j + 0.5)));
    EXPECT_LT(maxDiff, 1e-9) << method;  // fast: 32.32 fixed-point deposits
  }
}

TEST(Lic, NanInTheFieldIsAnErrorNamingTheArrayAndNode) {
  VectorField v = uniformDiagonal();
  v.name = "u_sph";
  v.values[v.grid.index(3, 4)].y() = std::nan("");
  try {
    computeLic(v, rawParams("fast", 32, 5.0));
    FAIL() << "NaN accepted";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'u_sph'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(3, 4, 0)"), std::string::npos) << msg;
  }
}

TEST(Lic, BadParametersNameTheKey) {
  const VectorField v = uniformDiagonal();
  auto keyOf = [&](LicParams p) -> std::string {
    try {
      computeLic(v, p);
    } catch (const ParamError& e) {
      return e.key();
    }
    return "<none>";
  };
  LicParams p;
  p.length = 0.5;
  EXPECT_EQ(keyOf(p), "length");
  p = {};
  p.kernel = static_cast<KernelShape>(7);
  EXPECT_EQ(keyOf(p), "kernel");
  p = {};
  p.noise_grain = 0.5;
  EXPECT_EQ(keyOf(p), "noise_grain");
  p = {};
  p.mask_speed = 1.0;
  EXPECT_EQ(keyOf(p), "mask_speed");
}

TEST(Lic, ResolutionFollowsTheGridAspect) {
  Grid g;
  g.dims = {81, 41, 1};
  g.spacing = {0.5, 0.5, 1.0};  // 40 m x 20 m
  LicParams p;
  EXPECT_EQ(licResolution(g, p), std::make_pair(81, 41));
  p.width = 300;
  EXPECT_EQ(licResolution(g, p), std::make_pair(300, 150));
  p.width = 0;
  p.height = 100;
  EXPECT_EQ(licResolution(g, p), std::make_pair(200, 100));
  const LicImage img = computeLic(uniformField(g, Vec3(1, 0, 0)), p);
  EXPECT_EQ(img.texture.grid.dims, (std::array<int, 3>{200, 100, 1}));
  EXPECT_DOUBLE_EQ(img.texture.grid.spacing[0], 0.2);
  EXPECT_DOUBLE_EQ(img.texture.grid.origin[0], 0.1);  // pixel centres
  EXPECT_DOUBLE_EQ(img.texture.grid.origin[1], 0.1);
}

// Relative speed of the rotation at a pixel centre is r / r_max (r_max at the image corner).
TEST(Lic, MaskMarksSlowPixelsAndZeroesThem) {
  const VectorField v = rotationField(squareGrid(101, -1.0, 1.0));
  LicParams p = rawParams("fast", 128, 10.0);
  p.mask_speed = 0.2;
  const LicImage img = computeLic(v, p);
  const double rMax = std::hypot(64.0, 64.0);
  int masked = 0;
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i) {
      const double rel = std::hypot(i + 0.5 - 64, j + 0.5 - 64) / rMax;
      if (std::abs(rel - 0.2) < 1e-9) continue;
      const bool m = img.mask[static_cast<std::size_t>(j) * 128 + i];
      EXPECT_EQ(m, rel < 0.2) << i << "," << j;
      if (m) {
        EXPECT_EQ(pixel(img, i, j), 0.0);
      }
      masked += m;
    }
  // Disc of radius 0.2 r_max: pi (0.2 * 90.5)^2 ~ 1029 pixels.
  EXPECT_NEAR(masked, std::numbers::pi * std::pow(0.2 * rMax, 2), 30);
}

TEST(Lic, ContrastStretchMapsMeanToHalfAndSigmasToTheRange) {
  const VectorField v = saddleField(squareGrid(51, -1.0, 1.0));
  LicParams p = rawParams("fast", 128, 10.0);
  p.contrast = true;
  p.contrast_sigmas = 2.5;
  const LicImage img = computeLic(v, p);
  double mean = 0;
  for (double x : img.texture.values) mean += x;
  mean /= img.texture.values.size();
  // Clamping the 1.2 % of a normal distribution beyond 2.5 sigma lowers the std slightly.
  EXPECT_NEAR(mean, 0.5, 0.01);
  EXPECT_NEAR(standardDeviation(img.texture.values), 1.0 / (2 * 2.5), 0.01);
  for (double x : img.texture.values) ASSERT_TRUE(x >= 0.0 && x <= 1.0);
}

// The xy slice of a 3D field at a node layer gives the same image as that layer as a 2D field.
TEST(Lic, SliceOfA3DFieldEqualsThe2DLayer) {
  Grid g3;
  g3.dims = {41, 41, 3};
  g3.origin = {-1, -1, 0};
  g3.spacing = {0.05, 0.05, 0.5};
  const VectorField v3 = sampleField(g3, [](const Vec3& p) -> Vec3 {  // not an Eigen expression
    return (1 - p.z()) * Vec3(-p.y(), p.x(), 0.3) + p.z() * Vec3(1, 0, 0);
  });
  Grid g2 = g3;
  g2.dims[2] = 1;
  const VectorField v2 = rotationField(g2);
  LicParams p = rawParams("reference", 96, 8.0);
  p.slice_height = 0.0;
  const LicImage a = computeLic(v3, p), b = computeLic(v2, p);
  EXPECT_EQ(a.texture.values, b.texture.values);
  EXPECT_EQ(a.texture.grid.origin[2], 0.0);
  p.slice_height = 1.5;
  try {
    computeLic(v3, p);
    FAIL();
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "slice_height");
    EXPECT_NE(std::string(e.what()).find("[0, 1]"), std::string::npos) << e.what();
  }
}

// A second pass convolves the first: box * box = triangle of half-width a = 2L, whose
// autocorrelation at lag tau is 1 - 1.5 (tau/a)^2 + 0.75 (tau/a)^3 (0.767 at tau = 8.94, L = 10)
// instead of the box's 1 - tau / 2L (0.553): the streaks get longer.
TEST(Lic, EnhancedSecondPassLengthensTheStreaks) {
  const VectorField v = uniformDiagonal();
  LicParams p = rawParams("fast", 192, 10.0);
  const double once = offsetCorrelation(computeLic(v, p), 8, 4, 30);  // lag 8.94 px
  p.enhance = true;
  const double twice = offsetCorrelation(computeLic(v, p), 8, 4, 30);
  std::printf("correlation at lag 8.94 px: one pass %.3f (box 0.553), enhanced %.3f (triangle "
              "0.767)\n", once, twice);
  EXPECT_NEAR(once, 0.553, 0.04);
  EXPECT_NEAR(twice, 0.767, 0.04);
}
