#include "fieldviz/render/ImageOverlay.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTexture.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "fieldviz/render/OverlayDepth.h"

namespace fluidviz {

namespace {

// RGB texture image, bottom row first (vtkTexture's t runs up); alpha is dropped so that the
// actor stays opaque.
vtkSmartPointer<vtkImageData> textureImage(const RgbaImage& image) {
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<std::uint8_t*>(data->GetScalarPointer());
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* row = &image.pixels[4 * static_cast<std::size_t>(y) * image.width];
    std::uint8_t* dst = out + 3 * static_cast<std::size_t>(image.height - 1 - y) * image.width;
    for (int x = 0; x < image.width; ++x)
      std::memcpy(dst + 3 * x, row + 4 * x, 3);
  }
  return data;
}

}  // namespace

PixelRect addPixelAlignedImage(FieldImageScene& scene, const RgbaImage& image,
                               const Grid& fieldGrid) {
  if (image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("addPixelAlignedImage: empty image");
  const PixelRect field = scene.fieldPixels();
  const double x0 = fieldGrid.origin[0];
  const double y1 = fieldGrid.origin[1] + (fieldGrid.dims[1] - 1) * fieldGrid.spacing[1];
  const double pixelsPerUnit =
      (field.right - field.left) / ((fieldGrid.dims[0] - 1) * fieldGrid.spacing[0]);
  const PixelRect snapped{std::round(field.left), std::round(field.top),
                          std::round(field.left) + image.width,
                          std::round(field.top) + image.height};
  // World corners of the snapped rectangle (picture y runs down, world y up).
  const double left = x0 + (snapped.left - field.left) / pixelsPerUnit;
  const double top = y1 - (snapped.top - field.top) / pixelsPerUnit;
  const double right = left + image.width / pixelsPerUnit;
  const double bottom = top - image.height / pixelsPerUnit;
  const double z = overlayDepth(scene, 1);

  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(left, bottom, z);
  plane->SetPoint1(right, bottom, z);
  plane->SetPoint2(left, top, z);
  vtkNew<vtkTexture> texture;
  texture->SetInputData(textureImage(image));
  texture->InterpolateOff();  // picture pixel centres fall on texel centres: take them as they are
  texture->RepeatOff();
  texture->EdgeClampOn();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  scene.renderer().addProp(actor);
  return snapped;
}

}  // namespace fluidviz
