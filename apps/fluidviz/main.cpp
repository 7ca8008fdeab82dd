// fluidviz: the command-line program. Exit codes: 0 success, 2 bad input, 3 numerical
// instability, 1 anything else; `run` stopped by SIGINT/SIGTERM: 130/143 (after a checkpoint).
#include <unistd.h>

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "apps/fluidviz/Commands.h"
#include "pipeline/StopSignals.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  // A run stops cleanly on SIGINT/SIGTERM: it writes a checkpoint first (RunScene.h).
  if (!args.empty() && args[0] == "run") fluidviz::installStopSignalHandlers();
  return fluidviz::app::dispatch(args, std::cout, std::cerr, isatty(STDERR_FILENO) != 0);
}
