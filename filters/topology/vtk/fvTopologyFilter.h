#pragma once
// Vector field topology as a VTK algorithm, so the core plugs into VTK pipelines:
//
//   vtkNew<fvTopologyFilter> f;
//   f->SetInputConnection(reader->GetOutputPort());          // vtkImageData, 2D or 3D
//   f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
//   f->SetParams(params);                                    // TopologyParams (slice_index, ...)
//   f->Update();
//   f->GetOutput(0);   // critical points (vertices with type, index, morse, det, trace, ...)
//   f->GetOutput(1);   // separatrices (polylines with origin, outgoing, end)
//
// Output layout: TopologyPolyData.h. Without SetInputArrayToProcess the image's active vectors
// are analysed. The filter only converts; the core (filters/topology) computes. Errors (missing
// or scalar array, non-finite values, bad parameters) go through vtkErrorMacro and GetLastError(),
// and both outputs are left empty.
#include <string>

#include <vtkPolyDataAlgorithm.h>

#include "filters/topology/TopologyParams.h"

class fvTopologyFilter : public vtkPolyDataAlgorithm {
 public:
  static fvTopologyFilter* New();
  vtkTypeMacro(fvTopologyFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Detection, classification and separatrix parameters (filters/topology/TopologyParams.h).
  void SetParams(const fluidviz::topology::TopologyParams& params);
  const fluidviz::topology::TopologyParams& GetParams() const { return params_; }

  /// Trace separatrices into output port 1 (default on). Off: port 1 stays empty.
  vtkSetMacro(ComputeSeparatrices, bool);
  vtkGetMacro(ComputeSeparatrices, bool);
  vtkBooleanMacro(ComputeSeparatrices, bool);

  vtkPolyData* GetCriticalPoints() { return GetOutput(0); }
  vtkPolyData* GetSeparatrices() { return GetOutput(1); }

  /// Why the last update failed; empty after a successful update.
  const std::string& GetLastError() const { return lastError_; }

 protected:
  fvTopologyFilter();
  ~fvTopologyFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
                          vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  bool ComputeSeparatrices = true;

 private:
  fvTopologyFilter(const fvTopologyFilter&) = delete;
  void operator=(const fvTopologyFilter&) = delete;

  std::string vectorArrayName(vtkInformationVector** inputVector);

  fluidviz::topology::TopologyParams params_;
  std::string lastError_;
};
