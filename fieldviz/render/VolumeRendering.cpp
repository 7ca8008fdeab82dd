#include "fieldviz/render/VolumeRendering.h"

#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFixedPointVolumeRayCastMapper.h>
#include <vtkGPUVolumeRayCastMapper.h>
#include <vtkImageData.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fieldviz/render/ArrayColoring.h"
#include "fieldviz/core/ParamRanges.h"

namespace fluidviz {

namespace {

constexpr int kColorSamples = 64;  // control points taken from the colour map

void requireVolumeArray(vtkImageData* image, const std::string& name) {
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
    throw std::invalid_argument("volume rendering needs a 3D grid (at least 2 nodes per axis)");
  vtkDataArray* a = image->GetPointData()->GetArray(name.c_str());
  if (a != nullptr && a->GetNumberOfComponents() != 1)
    throw std::invalid_argument("array '" + name + "' has " +
                                std::to_string(a->GetNumberOfComponents()) +
                                " components; volume rendering needs 1");
  finitePointArrayRange(image, name);  // missing array -> message listing the arrays present
}

// The image to render: `image` itself, or a copy whose non-finite values (resampled nodes
// without particle support) are replaced by `below`, a value under the colour range that the
// clamped opacity ramp draws fully transparent.
vtkSmartPointer<vtkImageData> withTransparentHoles(vtkImageData* image, const std::string& name,
                                                   double below) {
  vtkDataArray* a = image->GetPointData()->GetArray(name.c_str());
  vtkIdType holes = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) holes += !std::isfinite(a->GetComponent(i, 0));
  vtkSmartPointer<vtkImageData> result = image;
  if (holes == 0) return result;
  result = vtkSmartPointer<vtkImageData>::New();
  result->CopyStructure(image);
  auto filled = vtkSmartPointer<vtkDoubleArray>::New();
  filled->SetName(name.c_str());
  filled->SetNumberOfValues(a->GetNumberOfTuples());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
    const double v = a->GetComponent(i, 0);
    filled->SetValue(i, std::isfinite(v) ? v : below);
  }
  result->GetPointData()->AddArray(filled);
  return result;
}

vtkSmartPointer<vtkVolumeMapper> makeMapper(VolumeMapper kind) {
  if (kind == VolumeMapper::gpu) return vtkSmartPointer<vtkGPUVolumeRayCastMapper>::New();
  if (kind == VolumeMapper::cpu) return vtkSmartPointer<vtkFixedPointVolumeRayCastMapper>::New();
  return vtkSmartPointer<vtkSmartVolumeMapper>::New();
}

vtkSmartPointer<vtkColorTransferFunction> colorFunction(const ColorMap& map, double lo,
                                                        double hi) {
  auto f = vtkSmartPointer<vtkColorTransferFunction>::New();
  for (int i = 0; i < kColorSamples; ++i) {
    const double t = static_cast<double>(i) / (kColorSamples - 1);
    const ColorMap::Color c = map.map(t);
    f->AddRGBPoint(lo + t * (hi - lo), c[0], c[1], c[2]);
  }
  f->ClampingOn();
  return f;
}

vtkSmartPointer<vtkPiecewiseFunction> opacityRamp(const VolumeStyle& s, double lo, double hi) {
  auto f = vtkSmartPointer<vtkPiecewiseFunction>::New();
  const double start = lo + s.opacity_start * (hi - lo);
  f->AddPoint(lo, 0.0);
  if (start > lo) f->AddPoint(start, 0.0);
  f->AddPoint(hi, s.opacity);
  f->ClampingOn();
  return f;
}

}  // namespace

VolumeProp makeVolume(vtkImageData* image, const std::string& array, const VolumeStyle& style) {
  params::checkRanges(style);
  requireVolumeArray(image, array);
  const std::array<double, 2> r = colorRange(image, array, style.range_min, style.range_max);
  VolumeProp v;
  v.range[0] = r[0], v.range[1] = r[1];
  v.title = array;
  v.colors = colorFunction(ColorMap::byName(style.colormap), r[0], r[1]);
  vtkSmartPointer<vtkVolumeMapper> mapper = makeMapper(style.mapper);
  mapper->SetInputData(withTransparentHoles(image, array, r[0] - (r[1] - r[0])));
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectScalarArray(array.c_str());
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(v.colors);
  property->SetScalarOpacity(opacityRamp(style, r[0], r[1]));
  const double* spacing = image->GetSpacing();
  property->SetScalarOpacityUnitDistance(std::min({spacing[0], spacing[1], spacing[2]}));
  property->SetInterpolationTypeToLinear();
  property->SetShade(style.shade);
  v.volume = vtkSmartPointer<vtkVolume>::New();
  v.volume->SetMapper(mapper);
  v.volume->SetProperty(property);
  return v;
}

}  // namespace fluidviz
