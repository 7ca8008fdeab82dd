#pragma once
// Line Integral Convolution as a VTK image algorithm: vtkImageData with a vector point array
// (2D, or an xy slice of 3D at LicParams::slice_height) -> vtkImageData texture (LicImageData.h
// layout: `lic` in [0, 1] and `lic_mask` at pixel centres).
//
//   vtkNew<fvLicFilter> lic;
//   lic->SetInputConnection(reader->GetOutputPort());
//   lic->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
//   lic->SetParams(params);   // filters/lic/LicParams.h: length, kernel, method, width, ...
//   lic->Update();
//
// Without SetInputArrayToProcess the active vectors are used. Only converts and calls
// computeLic; errors (missing/scalar array, NaN, bad parameters) go to vtkErrorMacro and
// GetLastError(), and the output is left empty.
#include <string>

#include <vtkImageAlgorithm.h>

#include "filters/lic/LicParams.h"

class fvLicFilter : public vtkImageAlgorithm {
 public:
  static fvLicFilter* New();
  vtkTypeMacro(fvLicFilter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void SetParams(const fluidviz::lic::LicParams& params);
  const fluidviz::lic::LicParams& GetParams() const { return params_; }

  /// Why the last update failed; empty after a successful update.
  const std::string& GetLastError() const { return lastError_; }

 protected:
  fvLicFilter();
  ~fvLicFilter() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
                         vtkInformationVector* outputVector) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
                          vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

 private:
  fvLicFilter(const fvLicFilter&) = delete;
  void operator=(const fvLicFilter&) = delete;

  std::string vectorArrayName(vtkImageData* image);
  int fail(const std::string& message);

  fluidviz::lic::LicParams params_;
  std::string lastError_;
};
