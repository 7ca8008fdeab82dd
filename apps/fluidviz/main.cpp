// fluidviz: the command-line program. Exit codes: 0 success, 2 bad input, 3 numerical
// instability, 1 anything else.
#include <unistd.h>

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "apps/fluidviz/Commands.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  return fluidviz::app::dispatch(args, std::cout, std::cerr, isatty(STDERR_FILENO) != 0);
}
