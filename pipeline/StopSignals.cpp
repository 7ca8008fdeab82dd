#include "pipeline/StopSignals.h"

#include <csignal>
#include <sstream>

namespace fluidviz {

namespace {

volatile std::sig_atomic_t stopSignal = 0;

extern "C" void onStopSignal(int signal) {
  if (stopSignal != 0) {  // asked twice: stop now (the last checkpoint on disk stays valid)
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  stopSignal = signal;
}

std::string runInterruptedMessage(int signal, const std::filesystem::path& checkpoint, double time,
                                  long long step) {
  std::ostringstream s;
  s.precision(6);
  s << "interrupted by " << signalName(signal) << " at t = " << time << " s (step " << step
    << "); checkpoint written to " << checkpoint.string();
  return s.str();
}

}  // namespace

void installStopSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a signal during a write must not make the write fail
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int pendingStopSignal() { return stopSignal; }

void clearStopSignal() { stopSignal = 0; }

std::string signalName(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

RunInterrupted::RunInterrupted(int signal, std::filesystem::path checkpoint, double time,
                               long long step)
    : std::runtime_error(runInterruptedMessage(signal, checkpoint, time, step)),
      signal_(signal),
      checkpoint_(std::move(checkpoint)),
      time_(time),
      step_(step) {}

}  // namespace fluidviz
