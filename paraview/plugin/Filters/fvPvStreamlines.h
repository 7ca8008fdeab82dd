#pragma once
// fvStreamlineFilter (filters/streamlines/vtk) as a ParaView proxy. Its properties are generated
// from StreamlineProxyParams' declarations (paraview/properties/StreamlineProxyParams.h: the
// keys seeding.* and integration.* of a scene's output.streamlines[]); each calls one of the
// Set*Parameter methods with the scene key as its first argument.
//
// In parallel every rank reads the whole input (a line crosses any partition) and traces every
// seed (evenly spaced seeds depend on the lines before them), then keeps the lines whose seed
// lies in a cell of its own piece (PieceOwnership.h): each line is produced once, whole, and
// seed_id keeps the serial numbering.
#include <memory>
#include <string>

#include "FluidvizFiltersModule.h"
#include "filters/streamlines/vtk/fvStreamlineFilter.h"

// Nested, not `fluidviz::paraview`: VTK's wrapper parser reads C++11 only.
namespace fluidviz {
namespace paraview {
class PropertyValues;
}
}

class FLUIDVIZFILTERS_EXPORT fvPvStreamlines : public fvStreamlineFilter {
 public:
  static fvPvStreamlines* New();
  vtkTypeMacro(fvPvStreamlines, fvStreamlineFilter);

  void SetNumberParameter(const char* key, double value);
  void SetIntegerParameter(const char* key, int value);
  void SetChoiceParameter(const char* key, int index);
  void SetFlagParameter(const char* key, int on);
  void SetParameterGiven(const char* key, int given);
  void SetTextParameter(const char* key, const char* value);
  void SetNumbers2Parameter(const char* key, double x, double y);
  void SetNumbers3Parameter(const char* key, double x, double y, double z);

 protected:
  fvPvStreamlines();
  ~fvPvStreamlines() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

 private:
  fvPvStreamlines(const fvPvStreamlines&) = delete;
  void operator=(const fvPvStreamlines&) = delete;

  void ApplyProperties();

  std::unique_ptr<fluidviz::paraview::PropertyValues> values_;
  std::string propertyError_;
};
