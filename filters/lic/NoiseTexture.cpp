#include "filters/lic/NoiseTexture.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace fluidviz::lic {

NoiseTexture NoiseTexture::white(int width, int height, double grain, std::uint64_t seed,
                                 NoiseInterpolation interpolation) {
  if (width < 1 || height < 1 || !(grain >= 1.0))
    throw std::invalid_argument("noise texture: size " + std::to_string(width) + " x " +
                                std::to_string(height) + " px and grain " + std::to_string(grain) +
                                " px must be >= 1");
  NoiseTexture t;
  t.bilinear_ = interpolation == NoiseInterpolation::bilinear;
  t.invGrain_ = 1.0 / grain;
  t.nx_ = static_cast<int>(std::ceil(width / grain));
  t.ny_ = static_cast<int>(std::ceil(height / grain));
  std::mt19937_64 rng(seed);
  t.values_.resize(static_cast<std::size_t>(t.nx_) * t.ny_);
  // Not std::uniform_real_distribution: its algorithm differs between standard libraries.
  for (double& v : t.values_) v = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return t;
}

NoiseTexture NoiseTexture::fromImage(int width, int height, std::vector<double> values,
                                     NoiseInterpolation interpolation) {
  if (width < 1 || height < 1 || values.size() != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("noise texture: " + std::to_string(values.size()) +
                                " values for " + std::to_string(width) + " x " +
                                std::to_string(height) + " px");
  NoiseTexture t;
  t.bilinear_ = interpolation == NoiseInterpolation::bilinear;
  t.nx_ = width;
  t.ny_ = height;
  t.values_ = std::move(values);
  return t;
}

}  // namespace fluidviz::lic
