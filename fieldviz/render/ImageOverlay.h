#pragma once
// A picture-sized RGB image (e.g. a blended LIC texture) drawn over the field of a
// FieldImageScene, one image pixel per picture pixel, without resampling.
#include "fieldviz/core/Grid.h"
#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/RgbaImage.h"

namespace fluidviz {

/// Draws `image` (top row first, covering the extent of `fieldGrid`, the grid the scene was
/// built with) so that each of its pixels covers exactly one picture pixel: its top-left corner
/// goes to the picture pixel corner nearest to the field's top-left corner (at most half a pixel
/// away), nearest-texel lookup, no lighting. Returns the picture pixels it covers (whole numbers).
PixelRect addPixelAlignedImage(FieldImageScene& scene, const RgbaImage& image,
                               const Grid& fieldGrid);

}  // namespace fluidviz
