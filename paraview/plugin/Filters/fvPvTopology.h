#pragma once
// fvTopologyFilter (filters/topology/vtk) as a ParaView proxy: critical points (port 0) and
// separatrices (port 1). Properties are generated from TopologyParams' declarations
// (paraview/properties/ServerManagerXml.h) and call the Set*Parameter methods.
//
// In parallel every rank analyses the whole input (an index loop and a separatrix reach beyond
// any piece) and keeps the critical points whose cell lies in its piece of the input's extent,
// with the separatrices that start at them: each point is found once, on one rank, and every
// separatrix is whole. `origin` and `end_point` keep the numbering of the serial result.
#include <memory>
#include <string>

#include "FluidvizFiltersModule.h"
#include "filters/topology/vtk/fvTopologyFilter.h"

// Nested, not `fluidviz::paraview`: VTK's wrapper parser reads C++11 only.
namespace fluidviz {
namespace paraview {
class PropertyValues;
}
}

class FLUIDVIZFILTERS_EXPORT fvPvTopology : public fvTopologyFilter {
 public:
  static fvPvTopology* New();
  vtkTypeMacro(fvPvTopology, fvTopologyFilter);

  void SetNumberParameter(const char* key, double value);
  void SetIntegerParameter(const char* key, int value);
  void SetChoiceParameter(const char* key, int index);
  void SetFlagParameter(const char* key, int on);
  void SetParameterGiven(const char* key, int given);
  void SetTextParameter(const char* key, const char* value);

 protected:
  fvPvTopology();
  ~fvPvTopology() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

 private:
  fvPvTopology(const fvPvTopology&) = delete;
  void operator=(const fvPvTopology&) = delete;

  void ApplyProperties();

  std::unique_ptr<fluidviz::paraview::PropertyValues> values_;
  std::string propertyError_;
};
