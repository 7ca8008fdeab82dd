#include "filters/lic/vtk/LicImageData.h"

#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>

namespace fluidviz::lic {

vtkSmartPointer<vtkImageData> licToImageData(const LicImage& image) {
  const Grid& g = image.texture.grid;
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(g.dims[0], g.dims[1], 1);
  out->SetOrigin(g.origin.data());
  out->SetSpacing(g.spacing.data());
  vtkNew<vtkDoubleArray> lic;
  lic->SetName("lic");
  lic->SetNumberOfTuples(static_cast<vtkIdType>(image.texture.values.size()));
  std::copy(image.texture.values.begin(), image.texture.values.end(), lic->GetPointer(0));
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("lic_mask");
  mask->SetNumberOfTuples(static_cast<vtkIdType>(image.mask.size()));
  std::copy(image.mask.begin(), image.mask.end(), mask->GetPointer(0));
  out->GetPointData()->SetScalars(lic);
  out->GetPointData()->AddArray(mask);
  return out;
}

Grid licPixelGrid(const Grid& field, const LicParams& params) {
  const auto [W, H] = licResolution(field, params);
  double z = field.origin[2];
  if (!field.is2D())
    z = params.slice_height ? *params.slice_height : 0.5 * (field.origin[2] + field.upperCorner().z());
  Grid px;
  px.dims = {W, H, 1};
  px.spacing = {(field.dims[0] - 1) * field.spacing[0] / W,
                (field.dims[1] - 1) * field.spacing[1] / H, 1.0};
  px.origin = {field.origin[0] + 0.5 * px.spacing[0], field.origin[1] + 0.5 * px.spacing[1], z};
  return px;
}

}  // namespace fluidviz::lic
