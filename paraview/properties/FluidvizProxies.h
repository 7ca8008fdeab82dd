#pragma once
// The proxies of fluidviz's ParaView plugin: which VTK class, which input, which parameter
// struct. The plugin's XML is generated from this list (GenerateServerManagerXml.cpp).
#include <vector>

#include "paraview/properties/ServerManagerXml.h"

namespace fluidviz::paraview {

std::vector<ProxyDescription> fluidvizProxies();

}  // namespace fluidviz::paraview
