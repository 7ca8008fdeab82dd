#include <cmath>
#include <numbers>

#include "filters/lic/LicConvolver.h"

namespace fluidviz::lic {

double LicKernel::weight(int k) const {
  return hann ? 0.5 + 0.5 * std::cos(std::numbers::pi * k / (n + 1)) : 1.0;
}

// Cabral & Leedom 1993: trace n steps down- and upstream from each pixel centre and average the
// texture along the way with the kernel weights.
std::vector<double> ReferenceLic::convolve(const PixelVelocity& velocity,
                                           const NoiseTexture& texture,
                                           const LicKernel& kernel) const {
  const int W = velocity.width(), H = velocity.height();
  std::vector<double> weights(kernel.n + 1);
  for (int k = 0; k <= kernel.n; ++k) weights[k] = kernel.weight(k);
  std::vector<double> out(static_cast<std::size_t>(W) * H);
#pragma omp parallel for schedule(dynamic, 1)
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const double X = i + 0.5, Y = j + 0.5;
      double sum = weights[0] * texture.at(X, Y), wsum = weights[0];
      for (double sign : {1.0, -1.0}) {
        int k = 0;
        velocity.trace(X, Y, sign, kernel.step, kernel.n, [&](double x, double y) {
          const double w = weights[++k];
          sum += w * texture.at(x, y);
          wsum += w;
        });
      }
      out[static_cast<std::size_t>(j) * W + i] = sum / wsum;
    }
  return out;
}

}  // namespace fluidviz::lic
