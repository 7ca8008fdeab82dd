#pragma once
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluidviz::app {

/// kSignalBase + signal: `fluidviz run` stopped by SIGINT (130) or SIGTERM (143) after writing
/// its checkpoint (the shell convention for a process ended by a signal).
enum ExitCode { kSuccess = 0, kFailure = 1, kBadInput = 2, kUnstable = 3, kSignalBase = 128 };

/// A malformed command line; dispatch() reports it with exit code 2.
class UsageError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Each command is a function of its arguments (args[0] is the command's name) that returns the
/// exit code and throws for errors; dispatch() maps exceptions to exit codes: UsageError,
/// scene::SceneError, FileError and DataArrayError -> 2, solver instability -> 3, others -> 1.
/// New commands live in their own file (e.g. LicCommand.cpp) and get one line in dispatch().
using CommandFunction = int (*)(const std::vector<std::string>& args, std::ostream& out,
                                std::ostream& err, bool interactive);

/// "fluidviz <command>: ", the start of every message of the command args[0] names.
std::string messagePrefix(const std::vector<std::string>& args);

/// Runs one fluidviz command line (without the program name) and returns its exit code.
int dispatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             bool interactive);

}  // namespace fluidviz::app
