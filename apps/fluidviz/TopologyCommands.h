#pragma once
// The topology commands: `fluidviz topology` (TopologyCommand.cpp), critical points and
// separatrices of a vector array of a .vti file, and `fluidviz sweep` (SweepCommand.cpp), a scene
// run over a range of one parameter with the bifurcation diagram of its critical points.
// Signature: Commands.h CommandFunction.
#include <iosfwd>
#include <string>
#include <vector>

namespace fluidviz::app {

int topologyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                    bool interactive);
int sweepCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                 bool interactive);

/// Removes every `option VALUE` pair (and `option=VALUE`) from `args` and returns the values in
/// order, for options that may be repeated (--set). Throws UsageError when a value is missing.
std::vector<std::string> takeRepeatedOption(std::vector<std::string>& args,
                                            const std::string& option);

}  // namespace fluidviz::app
