// Writes the plugin's server-manager XML (paraview/plugin) from the parameter declarations.
//   fluidviz-paraview-xml OUT.xml
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <string>

#include "fieldviz/core/AtomicFile.h"
#include "paraview/properties/FluidvizProxies.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT.xml\n", argv[0]);
    return 2;
  }
  try {
    const std::string xml =
        fluidviz::paraview::serverManagerXml(fluidviz::paraview::fluidvizProxies());
    fluidviz::writeAtomically(argv[1], [&](const std::filesystem::path& tmp) {
      std::ofstream out(tmp);
      out << xml;
      if (!out.flush()) throw std::runtime_error("cannot write " + tmp.string());
    });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[1], e.what());
    return 1;
  }
  return 0;
}
