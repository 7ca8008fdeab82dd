#pragma once
// Streamlines as a VTK algorithm, so the shared integrator plugs into VTK pipelines:
//
//   vtkNew<fvStreamlineFilter> f;
//   f->SetInputConnection(reader->GetOutputPort());          // vtkImageData, 2D or 3D
//   f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
//   f->SetSourceConnection(seeds->GetOutputPort());          // optional: any points as seeds
//   f->SetIntegration(params);                               // StreamlineParams (rk4, step, ...)
//   f->Update();                                             // polylines, StreamlinePolyData.h
//
// Without a seed source the SeedingParams strategy (grid, line, points, evenly_spaced) places the
// seeds. Without SetInputArrayToProcess the image's active vectors are traced. It masks what
// `fluidviz streamlines` masks (lines end there, reason nan_in_field): in a 2D field the image's
// vtkValidPointMask, NaN nodes and no-slip solids (defaultFlowMask), in a 3D field the
// vtkValidPointMask and NaN nodes. It asks for the whole input (requestWholeInput): a line may
// cross any piece of a partitioned image. The filter only
// converts: vtkImageData -> VectorField (fieldviz/vtk/ImageDataAdapter.h), the core
// (filters/streamlines/Seeding.h) traces, StreamlinePolyData.h converts back. Errors (missing or
// scalar array, bad parameters) are reported through vtkErrorMacro and GetLastError(), and the
// output is left empty.
#include <string>
#include <vector>

#include <vtkPolyDataAlgorithm.h>

#include "filters/streamlines/Seeding.h"
#include "filters/streamlines/StreamlineParams.h"

class vtkDataSet;

class fvStreamlineFilter : public vtkPolyDataAlgorithm {
 public:
  static fvStreamlineFilter* New();
  vtkTypeMacro(fvStreamlineFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Integrator parameters (step and lengths in cells; filters/streamlines/StreamlineParams.h).
  void SetIntegration(const fluidviz::streamlines::StreamlineParams& params);
  const fluidviz::streamlines::StreamlineParams& GetIntegration() const { return integration_; }

  /// Seed placement used when no seed source is connected.
  void SetSeeding(const fluidviz::streamlines::SeedingParams& params);
  const fluidviz::streamlines::SeedingParams& GetSeeding() const { return seeding_; }

  /// Seeds: the points of any data set on input port 1 (like vtkStreamTracer::SetSourceConnection).
  void SetSourceConnection(vtkAlgorithmOutput* seeds);
  void SetSourceData(vtkDataSet* seeds);

  /// Why the last update produced no lines; empty after a successful update.
  const std::string& GetLastError() const { return lastError_; }

 protected:
  fvStreamlineFilter();
  ~fvStreamlineFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
                          vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  /// The lines of the input (masked as above), one per seed, in seed order; throws on errors.
  std::vector<fluidviz::streamlines::Streamline> TraceLines(vtkInformationVector** inputVector);
  /// Records `message` (GetLastError) and reports it with vtkErrorMacro; returns 0.
  int Fail(const std::string& message);

 private:
  fvStreamlineFilter(const fvStreamlineFilter&) = delete;
  void operator=(const fvStreamlineFilter&) = delete;

  std::string vectorArrayName(vtkInformationVector** inputVector);

  fluidviz::streamlines::StreamlineParams integration_;
  fluidviz::streamlines::SeedingParams seeding_;
  std::string lastError_;
};
