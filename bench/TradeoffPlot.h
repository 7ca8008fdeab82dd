#pragma once
// Error against wall time, log-log, one panel per reference, drawn off-screen with plain VTK 2D
// actors into a PNG (shared by the trade-off benches: lbm_tradeoff, sph_tradeoff).
#include <filesystem>
#include <string>
#include <vector>

namespace fluidviz::bench {

/// One run: its panel (reference), its series (variant), a label printed next to the marker
/// (the resolution n), its error and wall time.
struct TradeoffPoint {
  std::string reference, variant;
  int n = 0;
  double error = 0.0, seconds = 0.0;
  long long steps = 0;
};

struct TradeoffPanel {
  std::string title;                  ///< matches TradeoffPoint::reference
  std::vector<std::string> variants;  ///< series in legend order
};

/// Command line of a trade-off bench: `[--quick] [OUTPUT_DIR]` (default "."). Creates the folder
/// and pins the benches to one thread (their wall times are compared with each other).
struct TradeoffArgs {
  std::filesystem::path outDir = ".";
  bool quick = false;  ///< fewer, smaller runs
};
TradeoffArgs parseTradeoffArgs(int argc, char** argv);

/// Writes the plot to png (through the renderer's atomic PNG writer). `title` goes on top,
/// `footnote` at the bottom.
void writeTradeoffPlot(const std::vector<TradeoffPoint>& points,
                       const std::vector<TradeoffPanel>& panels, const std::string& title,
                       const std::string& footnote, const std::filesystem::path& png);

}  // namespace fluidviz::bench
