#include "filters/lic/vtk/fvLicFilter.h"

#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "filters/lic/vtk/LicImageData.h"

namespace lic = fluidviz::lic;
using SDDP = vtkStreamingDemandDrivenPipeline;

vtkStandardNewMacro(fvLicFilter);

fvLicFilter::fvLicFilter() {
  SetNumberOfInputPorts(1);
  SetNumberOfOutputPorts(1);
}

void fvLicFilter::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  os << indent << "Length: " << params_.length << " px, kernel " << fluidviz::choiceName(params_.kernel)
     << ", method " << fluidviz::choiceName(params_.method) << "\n";
}

void fvLicFilter::SetParams(const lic::LicParams& params) {
  params_ = params;
  Modified();
}

int fvLicFilter::fail(const std::string& message) {
  lastError_ = message;
  vtkErrorMacro(<< lastError_);
  return 0;
}

// The output's geometry follows from the input's and the parameters alone, so downstream
// filters can plan before the (expensive) convolution runs.
int fvLicFilter::RequestInformation(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector) {
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  vtkInformation* out = outputVector->GetInformationObject(0);
  int extent[6];
  double origin[3], spacing[3];
  in->Get(SDDP::WHOLE_EXTENT(), extent);
  in->Get(vtkDataObject::ORIGIN(), origin);
  in->Get(vtkDataObject::SPACING(), spacing);
  fluidviz::Grid g;
  for (int a = 0; a < 3; ++a) {
    g.dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
    g.origin[a] = origin[a] + extent[2 * a] * spacing[a];
    g.spacing[a] = spacing[a];
  }
  try {
    g.validate();
    lic::validateLicParams(params_);
    const fluidviz::Grid px = lic::licPixelGrid(g, params_);
    const int outExtent[6] = {0, px.dims[0] - 1, 0, px.dims[1] - 1, 0, 0};
    out->Set(SDDP::WHOLE_EXTENT(), outExtent, 6);
    out->Set(vtkDataObject::ORIGIN(), px.origin.data(), 3);
    out->Set(vtkDataObject::SPACING(), px.spacing.data(), 3);
    vtkDataObject::SetPointDataActiveScalarInfo(out, VTK_DOUBLE, 1);
  } catch (const fluidviz::ParamError& e) {
    return fail("parameter " + e.key() + " " + e.what());
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  return 1;
}

// Every output pixel can depend on any input node (streamlines wander): ask for all of it.
int fvLicFilter::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector,
                                     vtkInformationVector*) {
  fluidviz::requestWholeInput(inputVector[0]->GetInformationObject(0));
  return 1;
}

std::string fvLicFilter::vectorArrayName(vtkImageData* image) {
  return fluidviz::chosenVectorArrayName(GetInputArrayInformation(0), image, "fvLicFilter");
}

int fvLicFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                             vtkInformationVector* outputVector) {
  lastError_.clear();
  try {
    vtkImageData* image = vtkImageData::GetData(inputVector[0]);
    const fluidviz::VectorField field =
        fluidviz::vectorFieldFrom(image, vectorArrayName(image), "fvLicFilter input");
    const fluidviz::PointMask mask = fluidviz::defaultFlowMask(image, field, "fvLicFilter input");
    vtkImageData::GetData(outputVector)
        ->ShallowCopy(lic::licToImageData(lic::computeLic(field, params_, mask)));
    return 1;
  } catch (const fluidviz::ParamError& e) {
    return fail("parameter " + e.key() + " " + e.what());
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}
