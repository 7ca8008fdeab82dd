#include "fvPvTopology.h"

#include "PieceOwnership.h"

#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/TopologyParams.h"
#include "filters/topology/vtk/TopologyPolyData.h"
#include "paraview/properties/PropertyValues.h"

using SDDP = vtkStreamingDemandDrivenPipeline;
namespace pv = fluidviz::paraview;
namespace topo = fluidviz::topology;

vtkStandardNewMacro(fvPvTopology);

fvPvTopology::fvPvTopology()
    : values_(std::make_unique<pv::PropertyValues>(
          fluidviz::scene::paramTable<topo::TopologyParams>())) {}

fvPvTopology::~fvPvTopology() = default;

void fvPvTopology::ApplyProperties() {
  topo::TopologyParams params;
  if (values_->tryRead(params, propertyError_)) {
    propertyError_.clear();
    SetParams(params);
  } else {
    Modified();
  }
}

void fvPvTopology::SetNumberParameter(const char* key, double value) {
  values_->setNumber(key, value);
  ApplyProperties();
}
void fvPvTopology::SetIntegerParameter(const char* key, int value) {
  values_->setInteger(key, value);
  ApplyProperties();
}
void fvPvTopology::SetChoiceParameter(const char* key, int index) {
  values_->setChoice(key, index);
  ApplyProperties();
}
void fvPvTopology::SetFlagParameter(const char* key, int on) {
  values_->setFlag(key, on);
  ApplyProperties();
}
void fvPvTopology::SetParameterGiven(const char* key, int given) {
  values_->setGiven(key, given != 0);
  ApplyProperties();
}
void fvPvTopology::SetTextParameter(const char* key, const char* value) {
  values_->setText(key, value ? value : "");
  ApplyProperties();
}

int fvPvTopology::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                              vtkInformationVector* outputVector) {
  if (!propertyError_.empty()) {
    vtkErrorMacro(<< propertyError_);
    return 0;
  }
  try {
    vtkImageData* image = vtkImageData::GetData(inputVector[0]);
    const topo::TopologyResult r = topo::computeTopology(
        image,
        fluidviz::chosenVectorArrayName(GetInputArrayInformation(0), image,
                                        "FluidvizCriticalPoints"),
        GetParams(), ComputeSeparatrices, "FluidvizCriticalPoints input");
    vtkInformation* out = outputVector->GetInformationObject(0);
    const int pieces = out->Get(SDDP::UPDATE_NUMBER_OF_PIECES());
    std::vector<topo::CriticalPoint> points = r.points;
    std::vector<topo::Separatrix> separatrices = r.separatrices;
    if (pieces > 1) {
      const pv::OwnedPart owned = pv::ownedPart(
          inputVector[0]->GetInformationObject(0)->Get(SDDP::WHOLE_EXTENT()),
          out->Get(SDDP::UPDATE_PIECE_NUMBER()), pieces);
      const int layer = GetParams().slice_index;
      std::vector<bool> mine(r.points.size());
      points.clear();
      for (std::size_t i = 0; i < r.points.size(); ++i)
        if ((mine[i] = owned.owns(r.points[i].cell, layer))) points.push_back(r.points[i]);
      separatrices.clear();
      for (const topo::Separatrix& s : r.separatrices)
        if (s.origin >= 0 && mine[s.origin]) separatrices.push_back(s);
    }
    vtkPolyData::GetData(outputVector, 0)->ShallowCopy(topo::criticalPointsToPolyData(points));
    vtkPolyData::GetData(outputVector, 1)->ShallowCopy(topo::separatricesToPolyData(separatrices));
    return 1;
  } catch (const fluidviz::ParamError& e) {
    vtkErrorMacro(<< "parameter " << e.key() << " " << e.what());
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());
  }
  return 0;
}
