#include "filters/lic/LineIntegralConvolution.h"

#include "fieldviz/core/PointMask.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fluidviz::lic {

namespace {

double defaultSliceHeight(const Grid& g, const LicParams& p) {
  if (g.is2D()) return g.origin[2];
  return p.slice_height ? *p.slice_height : 0.5 * (g.origin[2] + g.upperCorner().z());
}

Grid pixelCentres(const Grid& g, int W, int H, double z) {
  Grid px;
  px.dims = {W, H, 1};
  const double lx = (g.dims[0] - 1) * g.spacing[0], ly = (g.dims[1] - 1) * g.spacing[1];
  px.spacing = {lx / W, ly / H, 1.0};
  px.origin = {g.origin[0] + 0.5 * px.spacing[0], g.origin[1] + 0.5 * px.spacing[1], z};
  return px;
}

std::vector<std::uint8_t> slowPixelMask(const PixelVelocity& v, double maskSpeed) {
  const int W = v.width(), H = v.height();
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(W) * H, 0);
  if (maskSpeed <= 0.0) return mask;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i)
      mask[static_cast<std::size_t>(j) * W + i] = v.relativeSpeed(i + 0.5, j + 0.5) <= maskSpeed;
  return mask;
}

}  // namespace

std::pair<int, int> licResolution(const Grid& g, const LicParams& p) {
  const double lx = (g.dims[0] - 1) * g.spacing[0], ly = (g.dims[1] - 1) * g.spacing[1];
  int w = p.width, h = p.height;
  if (w == 0 && h == 0) w = g.dims[0];
  if (h == 0) h = std::max(1, static_cast<int>(std::lround(w * ly / lx)));
  if (w == 0) w = std::max(1, static_cast<int>(std::lround(h * lx / ly)));
  return {w, h};
}

LicKernel licKernel(const LicParams& p) {
  LicKernel k;
  k.step = p.step;
  k.n = std::max(1, static_cast<int>(std::lround(p.length / p.step)));
  k.hann = p.kernel == KernelShape::hann;
  return k;
}

std::unique_ptr<LicConvolver> makeLicConvolver(const LicParams& p) {
  if (p.method == LicMethod::reference) return std::make_unique<ReferenceLic>();
  return std::make_unique<FastLic>(p.fast_min_hits, p.fast_line_factor);
}

void stretchContrast(std::vector<double>& values, const std::vector<std::uint8_t>& mask,
                     double sigmas) {
  double sum = 0, sum2 = 0;
  std::size_t n = 0;
  for (std::size_t p = 0; p < values.size(); ++p)
    if (!mask[p]) sum += values[p], sum2 += values[p] * values[p], ++n;
  if (n == 0) return;
  const double mean = sum / n, var = std::max(0.0, sum2 / n - mean * mean);
  const double sd = std::sqrt(var);
  for (double& v : values)
    v = sd > 0 ? std::clamp(0.5 + (v - mean) / (2 * sigmas * sd), 0.0, 1.0) : 0.5;
}

LicImage computeLic(const VectorField& field, const LicParams& params) {
  return computeLic(field, params, {});
}

namespace {

void addNodeMask(std::vector<std::uint8_t>& pixels, const Grid& px, const Grid& g,
                 const std::vector<std::uint8_t>& mask) {
  for (int j = 0; j < px.dims[1]; ++j)
    for (int i = 0; i < px.dims[0]; ++i)
      if (maskFraction(g, mask, px.position(i, j)) >= 0.5)
        pixels[static_cast<std::size_t>(j) * px.dims[0] + i] = 1;
}

}  // namespace

LicImage computeLic(const VectorField& input, const LicParams& params,
                    const std::vector<std::uint8_t>& nodeMask) {
  const bool masked = !nodeMask.empty();
  if (masked && !input.grid.is2D())
    throw std::invalid_argument("LIC: a node mask needs a 2D field, got " +
                                input.grid.describe());
  VectorField zeroed;
  if (masked) zeroed = withMaskedValue(input, nodeMask, Vec3::Zero());
  const VectorField& field = masked ? zeroed : input;
  validateLicParams(params);
  field.grid.validate();
  const auto [W, H] = licResolution(field.grid, params);
  const double z = defaultSliceHeight(field.grid, params);
  const PixelVelocity velocity(field, W, H, z, params.vectors == LicVectors::speed);
  const LicKernel kernel = licKernel(params);
  const auto convolver = makeLicConvolver(params);

  const auto interpolation = params.noise_interpolation == NoiseInterpolation::bilinear
                                 ? NoiseInterpolation::bilinear
                                 : NoiseInterpolation::nearest;
  std::vector<double> values = convolver->convolve(
      velocity, NoiseTexture::white(W, H, params.noise_grain, params.noise_seed, interpolation),
      kernel);
  LicImage img;
  img.mask = slowPixelMask(velocity, params.mask_speed);
  if (masked) addNodeMask(img.mask, pixelCentres(field.grid, W, H, z), field.grid, nodeMask);
  if (params.enhance) {
    // Okada & Kao 1997: convolving the first LIC image again lengthens and sharpens the streaks;
    // the first pass is stretched so that the second pass sees full-contrast input.
    stretchContrast(values, img.mask, params.contrast_sigmas);
    values = convolver->convolve(
        velocity, NoiseTexture::fromImage(W, H, std::move(values), interpolation), kernel);
  }
  if (params.contrast) stretchContrast(values, img.mask, params.contrast_sigmas);
  for (std::size_t p = 0; p < values.size(); ++p)
    if (img.mask[p]) values[p] = 0.0;
  img.texture = ScalarField{"lic", pixelCentres(field.grid, W, H, z), std::move(values)};
  return img;
}

}  // namespace fluidviz::lic
