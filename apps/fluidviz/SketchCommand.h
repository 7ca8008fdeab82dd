#pragma once
// `fluidviz sketch` (SketchCommand.cpp). Signature: Commands.h CommandFunction.
#include <iosfwd>
#include <string>
#include <vector>

namespace fluidviz::app {

int sketchCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                  bool interactive);

}  // namespace fluidviz::app
