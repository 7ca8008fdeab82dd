#pragma once
// fvLicFilter (filters/lic/vtk) as a ParaView proxy. The proxy's properties are generated from
// LicParams' declarations (paraview/properties/ServerManagerXml.h); each calls one of the
// Set*Parameter methods with the scene key as its first argument.
//
// In parallel every rank reads the whole input (a streamline may leave any piece) and computes
// the whole texture, then keeps the pixels of the piece ParaView asks it for: the pieces together
// are the serial texture, pixel for pixel.
#include <memory>
#include <string>

#include "FluidvizFiltersModule.h"
#include "filters/lic/vtk/fvLicFilter.h"

// Nested, not `fluidviz::paraview`: VTK's wrapper parser reads C++11 only.
namespace fluidviz {
namespace paraview {
class PropertyValues;
struct LicProxyParams;
}
}

class FLUIDVIZFILTERS_EXPORT fvPvLic : public fvLicFilter {
 public:
  static fvPvLic* New();
  vtkTypeMacro(fvPvLic, fvLicFilter);

  void SetNumberParameter(const char* key, double value);
  void SetIntegerParameter(const char* key, int value);
  void SetChoiceParameter(const char* key, int index);
  void SetFlagParameter(const char* key, int on);
  void SetParameterGiven(const char* key, int given);
  void SetTextParameter(const char* key, const char* value);
  void SetNumbers3Parameter(const char* key, double x, double y, double z);

 protected:
  fvPvLic();
  ~fvPvLic() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
                         vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

 private:
  fvPvLic(const fvPvLic&) = delete;
  void operator=(const fvPvLic&) = delete;

  void ApplyProperties();
  bool PropertiesAreValid();
  void AddBlendedColours(vtkImageData* input, vtkImageData* texture);

  std::unique_ptr<fluidviz::paraview::PropertyValues> values_;
  std::string propertyError_;
  std::unique_ptr<fluidviz::paraview::LicProxyParams> proxyParams_;
};
