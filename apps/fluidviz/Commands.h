#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace fluidviz::app {

enum ExitCode { kSuccess = 0, kFailure = 1, kBadInput = 2, kUnstable = 3 };

/// Runs one fluidviz command line (without the program name) and returns its exit code.
int dispatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             bool interactive);

}  // namespace fluidviz::app
