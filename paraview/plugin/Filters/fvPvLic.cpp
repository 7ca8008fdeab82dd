#include "fvPvLic.h"

#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "fieldviz/core/PointMask.h"
#include "fieldviz/render/ColorMap.h"
#include "fieldviz/render/LicBlend.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/lic/LicParams.h"
#include "paraview/properties/LicProxyParams.h"
#include "paraview/properties/PropertyValues.h"

using SDDP = vtkStreamingDemandDrivenPipeline;
namespace pv = fluidviz::paraview;

vtkStandardNewMacro(fvPvLic);

fvPvLic::fvPvLic()
    : values_(std::make_unique<pv::PropertyValues>(
          fluidviz::scene::paramTable<pv::LicProxyParams>())),
      proxyParams_(std::make_unique<pv::LicProxyParams>()) {}

fvPvLic::~fvPvLic() = default;

void fvPvLic::ApplyProperties() {
  pv::LicProxyParams params;
  if (values_->tryRead(params, propertyError_)) {
    propertyError_.clear();
    *proxyParams_ = params;
    SetParams(params);
  } else {
    Modified();
  }
}

void fvPvLic::SetNumberParameter(const char* key, double value) {
  values_->setNumber(key, value);
  ApplyProperties();
}
void fvPvLic::SetIntegerParameter(const char* key, int value) {
  values_->setInteger(key, value);
  ApplyProperties();
}
void fvPvLic::SetChoiceParameter(const char* key, int index) {
  values_->setChoice(key, index);
  ApplyProperties();
}
void fvPvLic::SetFlagParameter(const char* key, int on) {
  values_->setFlag(key, on);
  ApplyProperties();
}
void fvPvLic::SetParameterGiven(const char* key, int given) {
  values_->setGiven(key, given != 0);
  ApplyProperties();
}
void fvPvLic::SetNumbers3Parameter(const char* key, double x, double y, double z) {
  values_->setNumbers(key, {x, y, z});
  ApplyProperties();
}
void fvPvLic::SetTextParameter(const char* key, const char* value) {
  values_->setText(key, value ? value : "");
  ApplyProperties();
}

// A property outside its range fails every pass: the parameters still hold the last valid
// values, and a texture made with them would pass for one made with the property set.
bool fvPvLic::PropertiesAreValid() {
  if (propertyError_.empty()) return true;
  vtkErrorMacro(<< propertyError_);
  return false;
}

int fvPvLic::RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
                                vtkInformationVector* outputVector) {
  if (!PropertiesAreValid()) return 0;
  if (!Superclass::RequestInformation(request, inputVector, outputVector)) return 0;
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  return 1;
}

int fvPvLic::RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                         vtkInformationVector* outputVector) {
  if (!PropertiesAreValid()) return 0;
  if (!Superclass::RequestData(request, inputVector, outputVector)) return 0;
  if (!proxyParams_->color_by.empty()) {
    try {
      AddBlendedColours(vtkImageData::GetData(inputVector[0]),
                        vtkImageData::GetData(outputVector));
    } catch (const std::exception& e) {
      vtkErrorMacro(<< "Color By " << proxyParams_->color_by << ": " << e.what());
      return 0;
    }
  }
  vtkInformation* out = outputVector->GetInformationObject(0);
  if (out->Has(SDDP::UPDATE_EXTENT()))
    vtkImageData::GetData(outputVector)->Crop(out->Get(SDDP::UPDATE_EXTENT()));
  return 1;
}

namespace {

// The colour scalar as `fluidviz lic --color-by NAME` takes it (apps/fluidviz, colourScalar):
// speed is |v| of the convolved vectors, any other name a point array of the input; masked
// nodes are NaN, drawn in the NaN grey.
fluidviz::ScalarField colourScalar(vtkImageData* input, const fluidviz::VectorField& velocity,
                                   const fluidviz::PointMask& mask, const std::string& name) {
  fluidviz::ScalarField s = name == "speed"
                                ? fluidviz::magnitude(velocity, "speed")
                                : fluidviz::scalarFieldFrom(input, name, "fvPvLic input");
  return fluidviz::withMaskedNaN(s, mask);
}

std::array<double, 2> finiteRange(const fluidviz::ScalarField& s) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : s.values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  return {lo, hi};
}

}  // namespace

// The point array lic_color (RGB, 0-255): the texture blended with the colour-mapped scalar by
// blendLicTexture, the rule of `fluidviz lic` pictures (fieldviz/render/LicBlend.h), one pixel per
// texture node, rows from the lowest y as the texture's.
void fvPvLic::AddBlendedColours(vtkImageData* input, vtkImageData* texture) {
  const fluidviz::VectorField velocity = fluidviz::vectorFieldFrom(
      input, GetInputArrayToProcess(0, input)->GetName(), "fvPvLic input");
  const fluidviz::PointMask mask = fluidviz::defaultFlowMask(input, velocity, "fvPvLic input");
  const fluidviz::ScalarField colour = colourScalar(input, velocity, mask, proxyParams_->color_by);
  const fluidviz::ScalarField lic = fluidviz::scalarFieldFrom(texture, "lic", "fvPvLic texture");
  const fluidviz::ScalarField licMask =
      fluidviz::scalarFieldFrom(texture, "lic_mask", "fvPvLic texture");
  std::vector<std::uint8_t> masked(licMask.values.size());
  std::transform(licMask.values.begin(), licMask.values.end(), masked.begin(),
                 [](double m) { return static_cast<std::uint8_t>(m != 0); });
  std::array<double, 2> range = finiteRange(colour);
  if (proxyParams_->range_min) range[0] = *proxyParams_->range_min;
  if (proxyParams_->range_max) range[1] = *proxyParams_->range_max;
  if (!(range[0] < range[1]))
    throw std::invalid_argument("colour range [" + std::to_string(range[0]) + ", " +
                                std::to_string(range[1]) +
                                "] is empty: give Range Min < Range Max");
  const fluidviz::ColorMap& map = fluidviz::ColorMap::byName(proxyParams_->colormap);
  const fluidviz::RgbaImage image =
      fluidviz::blendLicTexture(lic, masked, colour, map, range, *proxyParams_);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("lic_color");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(vtkIdType(image.width) * image.height);
  for (int j = 0; j < image.height; ++j)  // image rows top first, texture rows bottom first
    for (int i = 0; i < image.width; ++i) {
      const std::size_t top = std::size_t(image.height - 1 - j);
      const std::uint8_t* px = &image.pixels[4 * (top * image.width + i)];
      for (int c = 0; c < 3; ++c) rgb->SetTypedComponent(vtkIdType(j) * image.width + i, c, px[c]);
    }
  texture->GetPointData()->AddArray(rgb);
}
