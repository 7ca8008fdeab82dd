#include "pipeline/Progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fluidviz {

ProgressReporter::ProgressReporter(std::ostream& out, bool interactive, std::string label)
    : out_(out), interactive_(interactive), label_(std::move(label)) {}

std::string ProgressReporter::formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

void ProgressReporter::update(double fraction, const std::string& detail) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = fraction > 1e-6 ? elapsed * (1.0 - fraction) / fraction : NAN;
  const int percent = static_cast<int>(fraction * 100.0);
  if (interactive_) {
    // Redraw at most 10 times a second.
    if (barShown_ && now - lastPrint_ < std::chrono::milliseconds(100)) return;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    out_ << "\r" << label_ << " [" << std::string(filled, '#') << std::string(kWidth - filled, '.')
         << "] " << percent << "%  " << detail << "  ETA " << formatDuration(eta) << "\x1b[K"
         << std::flush;
    barShown_ = true;
  } else {
    const int decile = percent / 10;
    if (decile == lastDecile_ && now - lastPrint_ < std::chrono::seconds(30)) return;
    lastDecile_ = decile;
    out_ << label_ << ": " << percent << "%  " << detail << "  elapsed "
         << formatDuration(elapsed) << "  ETA " << formatDuration(eta) << "\n"
         << std::flush;
  }
  lastPrint_ = now;
}

void ProgressReporter::finish(const std::string& summary) {
  if (interactive_ && barShown_) out_ << "\n";
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  out_ << label_ << ": " << summary << " in " << formatDuration(elapsed) << "\n" << std::flush;
}

}  // namespace fluidviz
