#include "filters/streamlines/vtk/fvStreamlineFilter.h"

#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"

namespace sl = fluidviz::streamlines;

vtkStandardNewMacro(fvStreamlineFilter);

fvStreamlineFilter::fvStreamlineFilter() { SetNumberOfInputPorts(2); }

void fvStreamlineFilter::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  os << indent << "Integrator: " << fluidviz::choiceName(integration_.integrator) << ", step "
     << integration_.step << " cells, direction " << fluidviz::choiceName(integration_.direction) << "\n";
  os << indent << "Seeding strategy: " << fluidviz::choiceName(seeding_.strategy) << "\n";
}

void fvStreamlineFilter::SetIntegration(const sl::StreamlineParams& params) {
  integration_ = params;
  Modified();
}

void fvStreamlineFilter::SetSeeding(const sl::SeedingParams& params) {
  seeding_ = params;
  Modified();
}

void fvStreamlineFilter::SetSourceConnection(vtkAlgorithmOutput* seeds) {
  SetInputConnection(1, seeds);
}

void fvStreamlineFilter::SetSourceData(vtkDataSet* seeds) { SetInputData(1, seeds); }

int fvStreamlineFilter::FillInputPortInformation(int port, vtkInformation* info) {
  if (port == 0) {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  } else {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int fvStreamlineFilter::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector,
                                            vtkInformationVector*) {
  fluidviz::requestWholeInput(inputVector[0]->GetInformationObject(0));
  return 1;
}

// The array chosen with SetInputArrayToProcess, else the active vectors.
std::string fvStreamlineFilter::vectorArrayName(vtkInformationVector** inputVector) {
  return fluidviz::chosenVectorArrayName(GetInputArrayInformation(0), vtkImageData::GetData(inputVector[0]), "fvStreamlineFilter");
}

namespace {

// What `fluidviz streamlines` masks (FlowCommandSupport's readFlowInput): in 2D the flow mask of
// every fluidviz front end, in 3D the vtkValidPointMask and NaN nodes (solids are found layer
// by layer, so not in a volume).
fluidviz::PointMask cliMask(vtkImageData* image, const fluidviz::VectorField& field) {
  if (field.grid.is2D()) return fluidviz::defaultFlowMask(image, field, "fvStreamlineFilter input");
  fluidviz::PointMask mask;
  if (image->GetPointData()->GetArray(fluidviz::kValidPointMaskArray))
    fluidviz::addMask(mask, fluidviz::zeroNodes(fluidviz::scalarFieldFrom(
                                image, fluidviz::kValidPointMaskArray, "fvStreamlineFilter input")));
  fluidviz::addMask(mask, fluidviz::nonFiniteNodes(field));
  return mask;
}

}  // namespace

std::vector<sl::Streamline> fvStreamlineFilter::TraceLines(vtkInformationVector** inputVector) {
  vtkImageData* image = vtkImageData::GetData(inputVector[0]);
  const fluidviz::VectorField field =
      fluidviz::vectorFieldFrom(image, vectorArrayName(inputVector), "fvStreamlineFilter input");
  const fluidviz::VectorField masked = fluidviz::withMaskedNaN(field, cliMask(image, field));
  if (vtkDataSet* seeds = vtkDataSet::GetData(inputVector[1]))
    return sl::traceStreamlines(masked, sl::seedsFromDataSet(seeds), integration_);
  return sl::traceSeeded(masked, seeding_, integration_);
}

int fvStreamlineFilter::Fail(const std::string& message) {
  lastError_ = message;
  vtkErrorMacro(<< lastError_);
  return 0;
}

int fvStreamlineFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector) {
  lastError_.clear();
  try {
    vtkPolyData::GetData(outputVector)
        ->ShallowCopy(sl::streamlinesToPolyData(TraceLines(inputVector)));
    return 1;
  } catch (const fluidviz::ParamError& e) {
    return Fail("parameter " + e.key() + " " + e.what());
  } catch (const std::exception& e) {
    return Fail(e.what());
  }
}
