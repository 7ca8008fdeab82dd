#include "filters/topology/vtk/fvTopologyFilter.h"

#include <vtkDataObject.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/vtk/TopologyPolyData.h"

namespace topo = fluidviz::topology;

vtkStandardNewMacro(fvTopologyFilter);

fvTopologyFilter::fvTopologyFilter() {
  SetNumberOfInputPorts(1);
  SetNumberOfOutputPorts(2);
}

void fvTopologyFilter::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  os << indent << "Slice index: " << params_.slice_index << "\n";
  os << indent << "Cluster radius: " << params_.cluster_radius << " cells\n";
  os << indent << "ComputeSeparatrices: " << ComputeSeparatrices << "\n";
}

void fvTopologyFilter::SetParams(const topo::TopologyParams& params) {
  params_ = params;
  Modified();
}

int fvTopologyFilter::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

// An index loop, a cluster and a separatrix reach across any piece: ask for the whole input.
int fvTopologyFilter::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector,
                                          vtkInformationVector*) {
  fluidviz::requestWholeInput(inputVector[0]->GetInformationObject(0));
  return 1;
}

// The array chosen with SetInputArrayToProcess, else the active vectors.
std::string fvTopologyFilter::vectorArrayName(vtkInformationVector** inputVector) {
  return fluidviz::chosenVectorArrayName(GetInputArrayInformation(0), vtkImageData::GetData(inputVector[0]), "fvTopologyFilter");
}

int fvTopologyFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                  vtkInformationVector* outputVector) {
  lastError_.clear();
  vtkPolyData* points = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* separatrices = vtkPolyData::GetData(outputVector, 1);
  try {
    vtkImageData* image = vtkImageData::GetData(inputVector[0]);
    const topo::TopologyResult r =
        topo::computeTopology(image, vectorArrayName(inputVector), params_, ComputeSeparatrices,
                              "fvTopologyFilter input");
    points->ShallowCopy(r.pointsPolyData);
    separatrices->ShallowCopy(r.separatricesPolyData);
    return 1;
  } catch (const fluidviz::ParamError& e) {
    lastError_ = "parameter " + e.key() + " " + e.what();
  } catch (const std::exception& e) {
    lastError_ = e.what();
  }
  vtkErrorMacro(<< lastError_);
  return 0;
}
