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

// The array chosen with SetInputArrayToProcess, else the active vectors.
std::string fvStreamlineFilter::vectorArrayName(vtkInformationVector** inputVector) {
  return fluidviz::chosenVectorArrayName(GetInputArrayInformation(0), vtkImageData::GetData(inputVector[0]), "fvStreamlineFilter");
}

int fvStreamlineFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector) {
  lastError_.clear();
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  try {
    vtkImageData* image = vtkImageData::GetData(inputVector[0]);
    const fluidviz::VectorField field =
        fluidviz::vectorFieldFrom(image, vectorArrayName(inputVector), "fvStreamlineFilter input");
    std::vector<sl::Streamline> lines;
    if (vtkDataSet* seeds = vtkDataSet::GetData(inputVector[1]))
      lines = sl::traceStreamlines(field, sl::seedsFromDataSet(seeds), integration_);
    else
      lines = sl::traceSeeded(field, seeding_, integration_);
    output->ShallowCopy(sl::streamlinesToPolyData(lines));
    return 1;
  } catch (const fluidviz::ParamError& e) {
    lastError_ = "parameter " + e.key() + " " + e.what();
  } catch (const std::exception& e) {
    lastError_ = e.what();
  }
  vtkErrorMacro(<< lastError_);
  return 0;
}
