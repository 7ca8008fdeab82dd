#include "fvPvResample.h"

#include <cmath>
#include <optional>

#include <vtkAlgorithmOutput.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/resample/ParticleResampler.h"
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "paraview/properties/PropertyValues.h"

using SDDP = vtkStreamingDemandDrivenPipeline;
namespace pv = fluidviz::paraview;
namespace rs = fluidviz::resample;

vtkStandardNewMacro(fvPvResample);

namespace {

const char* kSource = "FluidvizResample input";

// The particles and the parameters `fluidviz resample` would use on them: h from the particles'
// array smoothing_length when no SmoothingLength is set (ResampleCommand.cpp does the same).
struct ResampleInput {
  fluidviz::particles::ParticleSet particles;
  rs::ParticleResampleParams params;
};

ResampleInput resampleInput(vtkPolyData* poly, const rs::ParticleResampleParams& params) {
  if (!poly || poly->GetNumberOfPoints() == 0)
    throw std::invalid_argument(std::string(kSource) + ": has no points (particles) to resample");
  ResampleInput in{rs::particleSetFromPolyData(poly, kSource), params};
  if (!in.params.smoothing_length) {
    const std::optional<double> h = rs::medianSmoothingLength(in.particles);
    if (h && !(*h > 0 && std::isfinite(*h)))
      throw std::invalid_argument(std::string(kSource) + ": particle array '" +
                                  rs::kSmoothingLengthArray + "' has median " +
                                  std::to_string(*h) + "; a smoothing length must be > 0 (set "
                                  "SmoothingLength)");
    in.params.smoothing_length = h;
  }
  return in;
}

}  // namespace

fvPvResample::fvPvResample()
    : values_(std::make_unique<pv::PropertyValues>(
          fluidviz::scene::paramTable<rs::ParticleResampleParams>())) {
  SetNumberOfInputPorts(1);
}

fvPvResample::~fvPvResample() = default;

void fvPvResample::ApplyProperties() {
  rs::ParticleResampleParams params;
  if (values_->tryRead(params, propertyError_)) {
    try {
      rs::validateResampleParams(params);
      propertyError_.clear();
    } catch (const fluidviz::ParamError& e) {
      propertyError_ = pv::PropertyValues::propertyMessage(e);
    } catch (const std::exception& e) {
      propertyError_ = e.what();
    }
  }
  Modified();
}

void fvPvResample::SetNumberParameter(const char* key, double value) {
  values_->setNumber(key, value);
  ApplyProperties();
}
void fvPvResample::SetIntegerParameter(const char* key, int value) {
  values_->setInteger(key, value);
  ApplyProperties();
}
void fvPvResample::SetChoiceParameter(const char* key, int index) {
  values_->setChoice(key, index);
  ApplyProperties();
}
void fvPvResample::SetFlagParameter(const char* key, int on) {
  values_->setFlag(key, on);
  ApplyProperties();
}
void fvPvResample::SetParameterGiven(const char* key, int given) {
  values_->setGiven(key, given != 0);
  ApplyProperties();
}
void fvPvResample::SetTextParameter(const char* key, const char* value) {
  values_->setText(key, value ? value : "");
  ApplyProperties();
}

int fvPvResample::Fail(const std::string& message) {
  vtkErrorMacro(<< message);
  return 0;
}

int fvPvResample::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

// The whole particle set, brought up to date now: the grid's extent depends on it, and
// RequestInformation must announce that extent before any data is requested.
vtkPolyData* fvPvResample::WholeInput() {
  vtkAlgorithmOutput* connection = GetInputConnection(0, 0);
  if (!connection) return nullptr;
  vtkAlgorithm* upstream = connection->GetProducer();
  upstream->UpdatePiece(0, 1, 0);
  return vtkPolyData::SafeDownCast(upstream->GetOutputDataObject(connection->GetIndex()));
}

int fvPvResample::RequestInformation(vtkInformation*, vtkInformationVector**,
                                     vtkInformationVector* outputVector) {
  if (!propertyError_.empty()) return Fail(propertyError_);
  try {
    const ResampleInput in =
        resampleInput(WholeInput(), values_->read<rs::ParticleResampleParams>());
    const fluidviz::Grid grid = rs::planResampling(in.particles, in.params).grid;
    vtkInformation* out = outputVector->GetInformationObject(0);
    const int extent[6] = {0, grid.dims[0] - 1, 0, grid.dims[1] - 1, 0, grid.dims[2] - 1};
    out->Set(SDDP::WHOLE_EXTENT(), extent, 6);
    out->Set(vtkDataObject::ORIGIN(), grid.origin.data(), 3);
    out->Set(vtkDataObject::SPACING(), grid.spacing.data(), 3);
    out->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
    for (int a = 0; a < 3; ++a) {
      announcedDims_[a] = grid.dims[a];
      announcedOrigin_[a] = grid.origin[a];
      announcedSpacing_[a] = grid.spacing[a];
    }
    return 1;
  } catch (const fluidviz::ParamError& e) {
    return Fail(pv::PropertyValues::propertyMessage(e));
  } catch (const std::exception& e) {
    return Fail(e.what());
  }
}

int fvPvResample::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector,
                                      vtkInformationVector*) {
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  in->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
  in->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
  in->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

int fvPvResample::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                              vtkInformationVector* outputVector) {
  if (!propertyError_.empty()) return Fail(propertyError_);
  try {
    const ResampleInput in = resampleInput(vtkPolyData::GetData(inputVector[0]),
                                           values_->read<rs::ParticleResampleParams>());
    const rs::ResampleResult result = rs::resampleParticles(in.particles, in.params);
    const fluidviz::Grid& grid = result.fields.grid;
    for (int a = 0; a < 3; ++a)
      if (grid.dims[a] != announcedDims_[a] || grid.origin[a] != announcedOrigin_[a] ||
          grid.spacing[a] != announcedSpacing_[a])
        return Fail(std::string(kSource) + ": these particles need the grid " + grid.describe() +
                    ", not the one announced for the particles read first (" +
                    std::to_string(announcedDims_[0]) + " x " +
                    std::to_string(announcedDims_[1]) + " x " +
                    std::to_string(announcedDims_[2]) + " nodes); a time series whose "
                    "particles move needs a grid fixed over the run, which FluidvizResample "
                    "does not offer yet (re-apply the filter at each step)");
    vtkSmartPointer<vtkImageData> image = fluidviz::toImageData(result.fields);
    // vtkValidPointMask: 0 at the nodes without particle support, as fluidviz resample writes.
    const fluidviz::ScalarField* support = result.fields.findScalar(rs::kMaskArray);
    fluidviz::addValidPointMask(image,
                                support ? fluidviz::zeroNodes(*support) : fluidviz::PointMask{});
    vtkImageData* output = vtkImageData::GetData(outputVector);
    output->ShallowCopy(image);
    vtkInformation* out = outputVector->GetInformationObject(0);
    if (out->Has(SDDP::UPDATE_EXTENT())) output->Crop(out->Get(SDDP::UPDATE_EXTENT()));
    return 1;
  } catch (const fluidviz::ParamError& e) {
    return Fail(pv::PropertyValues::propertyMessage(e));
  } catch (const std::exception& e) {
    return Fail(e.what());
  }
}
