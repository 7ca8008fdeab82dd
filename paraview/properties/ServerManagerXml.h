#pragma once
// ParaView server-manager XML for fluidviz's filters, written from the parameter declarations
// (fieldviz/scene/ParamTable.h): each scene key becomes one property with the key's default,
// range (as a domain), unit (in the label) and description (as its documentation). The
// property calls the VTK class's Set<Kind>Parameter(key, value) (initial_string = the key), which
// hands the value to PropertyValues; an array of 2 or 3 numbers is one property of as many
// elements calling SetNumbers<N>Parameter(key, x, y[, z]). VTK-free: the plugin build runs it as a generator.
#include <string>
#include <vector>

#include "fieldviz/scene/ParamTable.h"

namespace fluidviz::paraview {

/// What a proxy reads: one input of `dataType` whose point arrays of `arrayAttribute` ("Vectors",
/// "Scalars") the user picks, or none (a source).
struct ProxyInput {
  std::string dataType;        ///< "vtkImageData"; empty: a source without input
  std::string arrayAttribute;  ///< "Vectors"; empty: no array selection
};

struct ProxyDescription {
  std::string name;      ///< proxy name, also the paraview.simple function (label w/o spaces)
  std::string label;     ///< menu text
  std::string vtkClass;  ///< the plugin's VTK algorithm
  std::string help;      ///< one paragraph for the proxy's documentation
  std::string sceneSection;  ///< where the same keys live in a scene ("topology"); empty: none
  ProxyInput input;
  std::vector<std::string> outputPorts;  ///< names of the output ports; empty: one, unnamed
  std::vector<scene::ParamRow> params;
};

/// The method a proxy's array property of `elements` numbers calls: "SetNumbers3Parameter"
/// (key, x, y, z). The plugin's classes have those of 2 and 3 elements (offeredArraySize).
std::string numbersCommand(int elements);
inline bool offeredArraySize(int elements) { return elements == 2 || elements == 3; }

/// "separatrix_integration.step" -> "SeparatrixIntegrationStep".
std::string propertyName(const std::string& key);

/// The <ServerManagerConfiguration> of all proxies, in group "filters" (or "sources").
std::string serverManagerXml(const std::vector<ProxyDescription>& proxies);

}  // namespace fluidviz::paraview
