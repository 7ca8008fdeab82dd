#pragma once
// LIC texture <-> vtkImageData: the image has a node at every pixel centre (dims width x height
// x 1, spacing = pixel size, origin = centre of pixel (0, 0) at the slice height) and point
// arrays `lic` (double in [0, 1], active scalars) and `lic_mask` (unsigned char, 1 = masked).
#include <vtkSmartPointer.h>

#include "filters/lic/LineIntegralConvolution.h"

class vtkImageData;

namespace fluidviz::lic {

vtkSmartPointer<vtkImageData> licToImageData(const LicImage& image);

/// The pixel-centre grid computeLic produces for `field` (licResolution, the slice height), so
/// that a VTK pipeline can announce the output geometry before computing it.
Grid licPixelGrid(const Grid& field, const LicParams& params);

}  // namespace fluidviz::lic
