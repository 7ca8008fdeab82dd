#include "fvPvLic.h"

#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include "filters/lic/LicParams.h"
#include "paraview/properties/PropertyValues.h"

using SDDP = vtkStreamingDemandDrivenPipeline;
namespace pv = fluidviz::paraview;

vtkStandardNewMacro(fvPvLic);

fvPvLic::fvPvLic()
    : values_(std::make_unique<pv::PropertyValues>(
          fluidviz::scene::paramTable<fluidviz::lic::LicParams>())) {}

fvPvLic::~fvPvLic() = default;

void fvPvLic::ApplyProperties() {
  fluidviz::lic::LicParams params;
  if (values_->tryRead(params, propertyError_)) {
    propertyError_.clear();
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
  vtkInformation* out = outputVector->GetInformationObject(0);
  if (out->Has(SDDP::UPDATE_EXTENT()))
    vtkImageData::GetData(outputVector)->Crop(out->Get(SDDP::UPDATE_EXTENT()));
  return 1;
}
