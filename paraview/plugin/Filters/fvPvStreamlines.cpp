#include "fvPvStreamlines.h"

#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include "PieceOwnership.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"
#include "paraview/properties/PropertyValues.h"
#include "paraview/properties/StreamlineProxyParams.h"

using SDDP = vtkStreamingDemandDrivenPipeline;
namespace pv = fluidviz::paraview;
namespace sl = fluidviz::streamlines;

vtkStandardNewMacro(fvPvStreamlines);

fvPvStreamlines::fvPvStreamlines()
    : values_(std::make_unique<pv::PropertyValues>(
          fluidviz::scene::paramTable<pv::StreamlineProxyParams>())) {}

fvPvStreamlines::~fvPvStreamlines() = default;

// validateStreamlineParams adds the checks between keys (min_step <= max_step) that the CLI's
// flags get too; its keys are those of StreamlineParams, here under integration.
void fvPvStreamlines::ApplyProperties() {
  pv::StreamlineProxyParams params;
  if (values_->tryRead(params, propertyError_)) {
    try {
      sl::validateStreamlineParams(params.integration);
      propertyError_.clear();
      SetSeeding(params.seeding);
      SetIntegration(params.integration);
      return;
    } catch (const fluidviz::ParamError& e) {
      propertyError_ = pv::PropertyValues::propertyMessage(
          fluidviz::ParamError("integration." + e.key(), e.what()));
    }
  }
  Modified();
}

void fvPvStreamlines::SetNumberParameter(const char* key, double value) {
  values_->setNumber(key, value);
  ApplyProperties();
}
void fvPvStreamlines::SetIntegerParameter(const char* key, int value) {
  values_->setInteger(key, value);
  ApplyProperties();
}
void fvPvStreamlines::SetChoiceParameter(const char* key, int index) {
  values_->setChoice(key, index);
  ApplyProperties();
}
void fvPvStreamlines::SetFlagParameter(const char* key, int on) {
  values_->setFlag(key, on);
  ApplyProperties();
}
void fvPvStreamlines::SetParameterGiven(const char* key, int given) {
  values_->setGiven(key, given != 0);
  ApplyProperties();
}
void fvPvStreamlines::SetTextParameter(const char* key, const char* value) {
  values_->setText(key, value ? value : "");
  ApplyProperties();
}
void fvPvStreamlines::SetNumbers2Parameter(const char* key, double x, double y) {
  values_->setNumbers(key, {x, y});
  ApplyProperties();
}
void fvPvStreamlines::SetNumbers3Parameter(const char* key, double x, double y, double z) {
  values_->setNumbers(key, {x, y, z});
  ApplyProperties();
}

int fvPvStreamlines::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                 vtkInformationVector* outputVector) {
  if (!propertyError_.empty()) return Fail(propertyError_);
  try {
    std::vector<sl::Streamline> lines = TraceLines(inputVector);
    vtkInformation* out = outputVector->GetInformationObject(0);
    const int pieces = out->Get(SDDP::UPDATE_NUMBER_OF_PIECES());
    if (pieces > 1) {
      vtkImageData* image = vtkImageData::GetData(inputVector[0]);
      const pv::OwnedPart owned = pv::ownedPart(
          inputVector[0]->GetInformationObject(0)->Get(SDDP::WHOLE_EXTENT()),
          out->Get(SDDP::UPDATE_PIECE_NUMBER()), pieces);
      // A line of another rank's seed keeps its place without points: no cell, and seed_id
      // numbers the remaining lines as in the serial output.
      for (sl::Streamline& line : lines) {
        if (line.points.empty()) continue;
        const fluidviz::Vec3& seed = line.points[line.seed_index];
        const double p[3] = {seed.x(), seed.y(), seed.z()};
        if (!owned.ownsPoint(p, image->GetOrigin(), image->GetSpacing())) line.points.clear();
      }
    }
    vtkPolyData::GetData(outputVector)->ShallowCopy(sl::streamlinesToPolyData(lines));
    return 1;
  } catch (const fluidviz::ParamError& e) {
    return Fail("parameter " + e.key() + " " + e.what());
  } catch (const std::exception& e) {
    return Fail(e.what());
  }
}
