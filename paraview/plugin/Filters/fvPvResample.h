#pragma once
// SPH resampling of particles (filters/resample, as `fluidviz resample`) as a ParaView proxy:
// poly data points with point arrays in, image data out (each resampled array, color, mask,
// summation_density with masses, vtkValidPointMask). Properties are generated from
// ParticleResampleParams' declarations and call the Set*Parameter methods. Without
// SmoothingLength the particles' array smoothing_length gives h (its median), as in the CLI.
//
// The grid follows from the particles (their bounding box, spacing and kernel support), so
// RequestInformation reads the whole particle set to announce the grid's extent, origin and
// spacing. Particles that need another grid later without a new RequestInformation (the next
// step of a time series) fail the update with both grids named: a grid fixed over a run, as
// `fluidviz run` resamples SPH snapshots, is not offered here yet. In parallel every rank reads every particle (a node's sum reaches particles of any
// piece), resamples the whole grid and keeps the extent ParaView asks it for: the ranks' pieces
// together are the serial grid, node for node.
#include <memory>
#include <string>

#include <vtkImageAlgorithm.h>

#include "FluidvizFiltersModule.h"

// Nested, not `fluidviz::paraview`: VTK's wrapper parser reads C++11 only.
namespace fluidviz {
namespace paraview {
class PropertyValues;
}
}

class vtkPolyData;

class FLUIDVIZFILTERS_EXPORT fvPvResample : public vtkImageAlgorithm {
 public:
  static fvPvResample* New();
  vtkTypeMacro(fvPvResample, vtkImageAlgorithm);

  void SetNumberParameter(const char* key, double value);
  void SetIntegerParameter(const char* key, int value);
  void SetChoiceParameter(const char* key, int index);
  void SetFlagParameter(const char* key, int on);
  void SetParameterGiven(const char* key, int given);
  void SetTextParameter(const char* key, const char* value);

 protected:
  fvPvResample();
  ~fvPvResample() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
                         vtkInformationVector* outputVector) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
                          vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

 private:
  fvPvResample(const fvPvResample&) = delete;
  void operator=(const fvPvResample&) = delete;

  void ApplyProperties();
  int Fail(const std::string& message);
  vtkPolyData* WholeInput();

  std::unique_ptr<fluidviz::paraview::PropertyValues> values_;
  std::string propertyError_;
  int announcedDims_[3] = {0, 0, 0};  ///< the grid RequestInformation announced
  double announcedOrigin_[3] = {0, 0, 0};
  double announcedSpacing_[3] = {0, 0, 0};
};
