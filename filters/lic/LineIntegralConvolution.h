#pragma once
// Line Integral Convolution of a 2D vector field (or an xy slice of a 3D one) into a grey
// texture. Entry point of the LIC core; VTK-free (the VTK wrapper converts vtkImageData to a
// VectorField, calls computeLic and wraps `texture` and `mask` as point arrays).
//
//   LicImage img = computeLic(field, params);   // params: LicParams.h
//
// Pipeline: white noise (NoiseTexture) -> one convolution pass (LicConvolver: reference or
// fast) -> optional second pass over the stretched first pass (enhance) -> mask of slow pixels ->
// optional contrast stretch -> masked pixels set to 0.
// Errors: ParamError naming the key for bad parameters; std::invalid_argument naming the array
// (and the node) for NaN/inf values - LIC does not guess what a non-finite vector means.
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/lic/LicConvolver.h"
#include "filters/lic/LicParams.h"

namespace fluidviz::lic {

struct LicImage {
  /// "lic": one value in [0, 1] per pixel; its grid has a node at every pixel CENTRE (dims
  /// width x height x 1, spacing = pixel size in m, z = the slice height), row 0 = lowest y.
  ScalarField texture;
  /// Per pixel: 1 = masked (|v| <= mask_speed max|v| at the pixel centre), 0 = valid.
  std::vector<std::uint8_t> mask;

  int width() const { return texture.grid.dims[0]; }
  int height() const { return texture.grid.dims[1]; }
};

/// Output size: width/height as given, a zero one from the other and the grid's xy aspect
/// ratio, both zero = one pixel per node along x.
std::pair<int, int> licResolution(const Grid& grid, const LicParams& params);

/// The kernel for params.length and params.step (n = max(1, round(L / step)) samples each way).
LicKernel licKernel(const LicParams& params);

/// ReferenceLic or FastLic as params.method says.
std::unique_ptr<LicConvolver> makeLicConvolver(const LicParams& params);

/// Maps the unmasked values' mean to 0.5 and mean +- sigmas * std to 0 and 1, clamped; all 0.5
/// when they do not vary.
void stretchContrast(std::vector<double>& values, const std::vector<std::uint8_t>& mask,
                     double sigmas);

LicImage computeLic(const VectorField& field, const LicParams& params);

/// LIC of a 2D field with masked nodes (nodeMask: 1 per masked node, Grid::index; empty = none):
/// masked nodes count as zero velocity, whatever their value (NaN allowed there), and a pixel is
/// masked, drawn in the picture's mask colour instead of noise, where the bilinear interpolation
/// of the node mask at its centre is >= 1/2. NaN/inf at unmasked nodes is still refused.
LicImage computeLic(const VectorField& field, const LicParams& params,
                    const std::vector<std::uint8_t>& nodeMask);

}  // namespace fluidviz::lic
