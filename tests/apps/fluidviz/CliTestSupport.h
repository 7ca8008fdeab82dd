#pragma once
// Runs a fluidviz command line in-process, as the CLI tests of every module do.
#include <sstream>
#include <string>
#include <vector>

#include "apps/fluidviz/Commands.h"

namespace fluidviz::test {

struct Result {
  int code;         ///< exit code dispatch() returned
  std::string out;  ///< what the command printed on stdout
  std::string err;  ///< what it printed on stderr
};

inline Result run(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = app::dispatch(args, out, err, false);
  return {code, out.str(), err.str()};
}

}  // namespace fluidviz::test
