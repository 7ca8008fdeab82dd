#pragma once
// The commands that work on a field file: `fluidviz lic` (LicCommand.cpp) and
// `fluidviz streamlines` (StreamlinesCommand.cpp). Signature: Commands.h CommandFunction.
#include <iosfwd>
#include <string>
#include <vector>

namespace fluidviz::app {

int licCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
               bool interactive);
int streamlinesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                       bool interactive);

}  // namespace fluidviz::app
