#pragma once
// Other programs run from fluidviz (ffmpeg for movies, the legacy VTK reader's helper): started
// by posix_spawn, which execs at once, never by a fork that goes on running fluidviz's code. A
// child forked from a process with threads (OpenMP's, Mesa's) may inherit a lock another thread
// held and wait for it forever; POSIX allows such a child only async-signal-safe calls.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fluidviz {

struct ChildProcessResult {
  int status = 0;      // as waitpid reports it
  std::string errors;  // everything the child wrote to stderr
};

// Runs argv (argv[0] the program's path, no shell, the caller's environment) with stdin from
// /dev/null; its stdout is handed to onOutput in pieces as it arrives, its stderr collected.
// Throws std::runtime_error naming the program when it cannot be started.
ChildProcessResult runChildProcess(const std::vector<std::string>& argv,
                                   const std::function<void(std::string_view)>& onOutput);

bool exitedWithZero(int status);
// "exit code 3", "signal 11".
std::string exitDescription(int status);

}  // namespace fluidviz
