#pragma once
// Progress of long runs: a bar with ETA on a terminal, plain lines (every 10% or 30 s) otherwise.
#include <chrono>
#include <ostream>
#include <string>

namespace fluidviz {

class ProgressReporter {
 public:
  /// interactive: redraw one line with '\r' (a terminal); otherwise print whole lines.
  ProgressReporter(std::ostream& out, bool interactive, std::string label);
  /// fraction in [0, 1]; detail is shown after the bar (e.g. "t = 1.2 s, step 4000").
  void update(double fraction, const std::string& detail);
  /// Ends the bar (newline on a terminal) and prints the summary line.
  void finish(const std::string& summary);

  static std::string formatDuration(double seconds);

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream& out_;
  bool interactive_;
  std::string label_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastPrint_ = Clock::now();
  int lastDecile_ = -1;
  bool barShown_ = false;
};

}  // namespace fluidviz
