#pragma once
// Stopping a run cleanly: `fluidviz run` turns SIGINT and SIGTERM into a request that the run
// loops poll between chunks of steps (a few hundred ms at most); the loop then writes its
// checkpoint and throws RunInterrupted, which the CLI reports with exit code 128 + signal
// (130 for SIGINT, 143 for SIGTERM). A second signal while the first is being handled takes the
// default action (the process ends at once; the previous checkpoint stays intact, being written
// atomically).
#include <filesystem>
#include <stdexcept>
#include <string>

namespace fluidviz {

/// Installs the SIGINT and SIGTERM handlers (async-signal-safe: they only set a flag).
void installStopSignalHandlers();
/// The signal that asked the run to stop (SIGINT or SIGTERM), or 0.
int pendingStopSignal();
/// Forgets a pending request (tests; a new run in the same process).
void clearStopSignal();
/// "SIGINT", "SIGTERM", else "signal N".
std::string signalName(int signal);

/// A run stopped on request after writing its checkpoint.
class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted(int signal, std::filesystem::path checkpoint, double time, long long step);
  int signal() const { return signal_; }
  const std::filesystem::path& checkpoint() const { return checkpoint_; }
  double time() const { return time_; }  ///< s
  long long step() const { return step_; }

 private:
  int signal_;
  std::filesystem::path checkpoint_;
  double time_;
  long long step_;
};

}  // namespace fluidviz
