#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>
#include <numeric>

#include "filters/lic/LicConvolver.h"

namespace fluidviz::lic {

namespace {

// Lines traced in parallel per round; the result does not depend on it (see FastLic::convolve).
constexpr std::size_t kBatch = 256;

// Sliding kernel means over a line by prefix sums: O(1) per sample for box and Hann.
class SlidingKernel {
 public:
  explicit SlidingKernel(const LicKernel& k)
      : n_(k.n), hann_(k.hann), w_(std::numbers::pi / (k.n + 1)) {}

  void prepare(const std::vector<double>& t) {
    const std::size_t len = t.size();
    box_.assign(len + 1, 0.0);
    for (std::size_t m = 0; m < len; ++m) box_[m + 1] = box_[m] + t[m];
    if (!hann_) return;
    osc_.assign(len + 1, 0.0);
    unit_.assign(len + 1, 0.0);
    for (std::size_t m = 0; m < len; ++m) {
      const std::complex<double> e = std::polar(1.0, w_ * double(m));
      osc_[m + 1] = osc_[m] + t[m] * e;
      unit_[m + 1] = unit_[m] + e;
    }
  }

  /// Weighted mean over samples [m - n, m + n] clipped to [0, len).
  double mean(int m, int len) const {
    const int a = std::max(0, m - n_), b = std::min(len - 1, m + n_);
    const double count = b - a + 1, boxSum = box_[b + 1] - box_[a];
    if (!hann_) return boxSum / count;
    const std::complex<double> back = std::polar(1.0, -w_ * m);
    const double s = 0.5 * boxSum + 0.5 * std::real(back * (osc_[b + 1] - osc_[a]));
    const double wsum = 0.5 * count + 0.5 * std::real(back * (unit_[b + 1] - unit_[a]));
    return s / wsum;
  }

 private:
  int n_;
  bool hann_;
  double w_;
  std::vector<double> box_;
  std::vector<std::complex<double>> osc_, unit_;
};

// What one long streamline contributes: (pixel, kernel mean) per deposited sample.
struct LineDeposits {
  std::vector<std::uint32_t> pixel;
  std::vector<double> value;
};

// Traces the long line through a pixel centre and computes its deposits (thread-local buffers).
class LineConvolver {
 public:
  LineConvolver(const PixelVelocity& v, const NoiseTexture& tex, const LicKernel& k,
                int stepsPerSide)
      : v_(v), tex_(tex), k_(k), M_(stepsPerSide), sliding_(k) {}

  void run(std::uint32_t seedPixel, LineDeposits& out) {
    const int W = v_.width(), H = v_.height();
    const double X0 = seedPixel % W + 0.5, Y0 = seedPixel / W + 0.5;
    bx_.clear(), by_.clear(), x_.clear(), y_.clear();
    const int nb = v_.trace(X0, Y0, -1.0, k_.step, M_, [&](double x, double y) {
      bx_.push_back(x);
      by_.push_back(y);
    });
    for (int m = nb - 1; m >= 0; --m) x_.push_back(bx_[m]), y_.push_back(by_[m]);
    x_.push_back(X0);
    y_.push_back(Y0);
    const int nf = v_.trace(X0, Y0, 1.0, k_.step, M_, [&](double x, double y) {
      x_.push_back(x);
      y_.push_back(y);
    });
    const int len = static_cast<int>(x_.size());
    t_.resize(len);
    for (int m = 0; m < len; ++m) t_[m] = tex_.at(x_[m], y_[m]);
    sliding_.prepare(t_);
    // Where the line was only cut by the M-step limit, windows must not reach past the cut;
    // where it really ended (border, |v| = 0), truncated windows are what the reference does.
    const int lo = nb < M_ ? 0 : k_.n;
    const int hi = len - 1 - (nf < M_ ? 0 : k_.n);
    out.pixel.clear();
    out.value.clear();
    for (int m = lo; m <= hi; ++m) {
      const int i = std::min(static_cast<int>(x_[m]), W - 1);
      const int j = std::min(static_cast<int>(y_[m]), H - 1);
      out.pixel.push_back(static_cast<std::uint32_t>(j) * W + i);
      out.value.push_back(sliding_.mean(m, len));
    }
  }

 private:
  const PixelVelocity& v_;
  const NoiseTexture& tex_;
  const LicKernel& k_;
  int M_;
  SlidingKernel sliding_;
  std::vector<double> bx_, by_, x_, y_, t_;
};

// A fixed scattered visiting order p -> (p * a) mod N with gcd(a, N) = 1: consecutive seeds lie
// far apart, so lines traced in the same round rarely cover each other's seed pixels.
std::uint64_t scatterMultiplier(std::uint64_t n) {
  std::uint64_t a = static_cast<std::uint64_t>(0.6180339887 * n) | 1;  // golden-ratio stride
  while (std::gcd(a, n) != 1) a += 2;
  return a;
}

}  // namespace

std::vector<double> FastLic::convolve(const PixelVelocity& velocity, const NoiseTexture& texture,
                                      const LicKernel& kernel) const {
  const std::uint64_t pixels = static_cast<std::uint64_t>(velocity.width()) * velocity.height();
  const int stepsPerSide = std::max(kernel.n, static_cast<int>(std::ceil(lineFactor_ * kernel.n)));
  const std::uint64_t stride = scatterMultiplier(pixels);
  std::vector<double> sum(pixels, 0.0);
  std::vector<std::int32_t> hits(pixels, 0);
  std::vector<std::uint32_t> seeds;
  std::vector<LineDeposits> lines(kBatch);

  std::uint64_t cursor = 0;
  while (cursor < pixels) {
    // Next pixels of the visiting order that still lack hits (as of the last round).
    seeds.clear();
    while (seeds.size() < kBatch && cursor < pixels) {
      const auto p = static_cast<std::uint32_t>((cursor++ * stride) % pixels);
      if (hits[p] < minHits_) seeds.push_back(p);
    }
    const long n = static_cast<long>(seeds.size());
#pragma omp parallel
    {
      LineConvolver line(velocity, texture, kernel, stepsPerSide);
#pragma omp for schedule(dynamic, 1)
      for (long s = 0; s < n; ++s) line.run(seeds[s], lines[s]);
    }
    // Commit in visiting order, skipping a line whose seed an earlier line of this round has
    // satisfied: exactly what the serial algorithm would have done.
    for (long s = 0; s < n; ++s) {
      if (hits[seeds[s]] >= minHits_) continue;
      const LineDeposits& d = lines[s];
      for (std::size_t k = 0; k < d.pixel.size(); ++k) {
        sum[d.pixel[k]] += d.value[k];
        ++hits[d.pixel[k]];
      }
    }
  }
  std::vector<double> out(pixels);
  for (std::uint64_t p = 0; p < pixels; ++p) out[p] = sum[p] / hits[p];
  return out;
}

}  // namespace fluidviz::lic
