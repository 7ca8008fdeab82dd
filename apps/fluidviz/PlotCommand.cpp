// fluidviz plot: a line plot (fieldviz/render/LinePlot.h) of columns of a user's CSV file, with
// an optional reference CSV drawn as markers.
#include "apps/fluidviz/PlotCommand.h"

#include <ostream>

#include "apps/fluidviz/Commands.h"
#include "apps/fluidviz/FlowCommandSupport.h"
#include "fieldviz/io/CsvTable.h"
#include "fieldviz/render/LinePlot.h"

namespace fluidviz::app {

namespace {

namespace fs = std::filesystem;

const char* kPlotHelp = R"HELP(fluidviz plot FILE.csv -o PLOT.png [options]

Draws columns of a CSV file against one of them: '#' comment lines, a header line naming the
columns ("t (s),kinetic_energy (J/m)"), then one number per column on every line ("nan": no
value, left out). Columns are named in full or without their unit in parentheses ("t").
Probes and time series of `fluidviz run` write such files.

Options:
  -o, --output PLOT.png   the picture (required)
  --x COL                 column of the horizontal axis (default: the first)
  --y COL[,COL...]        columns drawn as lines (default: all others)
  --reference REF.csv     drawn as markers: its column named as --x (else its first) against
                          those named as --y (else all its other columns)
  --title TEXT            plot title (default: the file name)
  --width PX, --height PX picture size (default 900 x 600)
  -h, --help              this text

Exit codes: 0 success, 2 bad input (missing file, unknown column - the columns there are are
named -, a value that is not a number - with its line); nothing is written then.
)HELP";

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    items.push_back(text.substr(begin, comma - begin));
    begin = comma + 1;
  }
  return items;
}

int parseSize(const ParsedArgs& a, const std::string& flag, int fallback) {
  if (!a.has(flag)) return fallback;
  const double v = parseNumbers(flag, a.value(flag), 1)[0];
  if (v != static_cast<int>(v) || v < 150 || v > 8192)
    throw UsageError(flag + " is " + a.value(flag) + "; allowed: a whole number of px from 150 "
                     "to 8192");
  return static_cast<int>(v);
}

// The columns drawn: --y, else every column but the x column.
std::vector<std::string> yColumns(const CsvTable& t, const std::string& x, const ParsedArgs& a) {
  if (a.has("--y")) return splitList(a.value("--y"));
  std::vector<std::string> ys;
  for (const std::string& n : t.names)
    if (t.find(x) != t.find(n)) ys.push_back(n);
  return ys;
}

PlotSeries seriesOf(const CsvTable& t, const fs::path& file, const std::string& x,
                    const std::string& y, PlotMarks marks, const std::string& label) {
  return {label, t.column(x, file), t.column(y, file), marks};
}

// The full header name ("E (J)") of a column named with or without its unit; FileError naming
// the columns there are if there is none.
std::string fullName(const CsvTable& t, const fs::path& file, const std::string& name) {
  t.column(name, file);
  return t.names[static_cast<std::size_t>(t.find(name))];
}

// Marker series of the reference: its --x (else first) column against its --y columns (else
// all others).
std::vector<PlotSeries> referenceSeries(const fs::path& file, const std::string& x,
                                        const std::vector<std::string>& ys) {
  const CsvTable ref = readCsv(file);
  const std::string refX = ref.find(x) >= 0 ? x : ref.names.front();
  std::vector<std::string> refYs;
  for (const std::string& y : ys)
    if (ref.find(y) >= 0) refYs.push_back(y);
  if (refYs.empty())
    for (const std::string& n : ref.names)
      if (ref.find(n) != ref.find(refX)) refYs.push_back(n);
  std::vector<PlotSeries> series;
  for (const std::string& y : refYs)
    series.push_back(seriesOf(ref, file, refX, y, PlotMarks::markers,
                              file.stem().string() + ": " + y));
  return series;
}

}  // namespace

int plotCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&, bool) {
  for (const std::string& a : args)
    if (a == "-h" || a == "--help") {
      out << kPlotHelp;
      return kSuccess;
    }
  const ParsedArgs a = parseArgs(args, {"--output", "--x", "--y", "--reference", "--title",
                                        "--width", "--height"},
                                 {}, {{"-o", "--output"}});
  if (a.positional.size() != 1)
    throw UsageError("needs exactly one CSV file, got " + std::to_string(a.positional.size()));
  if (!a.has("--output")) throw UsageError("needs -o PLOT.png (see --help)");
  const fs::path file = a.positional[0];
  const CsvTable table = readCsv(file);
  const std::string x = a.value("--x", table.names.front());
  const std::string xLabel = fullName(table, file, x);
  std::vector<PlotSeries> series;
  for (const std::string& y : yColumns(table, x, a))
    series.push_back(seriesOf(table, file, x, y, PlotMarks::line, fullName(table, file, y)));
  if (series.empty()) throw UsageError(file.string() + " has only the column " + x + " to plot");
  const std::size_t lines = series.size();
  if (a.has("--reference"))
    for (PlotSeries& s : referenceSeries(a.value("--reference"), x, yColumns(table, x, a)))
      series.push_back(std::move(s));
  LinePlotParams params;
  params.width = parseSize(a, "--width", params.width);
  params.height = parseSize(a, "--height", params.height);
  params.title = a.value("--title", file.filename().string());
  params.x_label = xLabel;
  params.y_label = lines == 1 ? series[0].label : "value (see the legend)";
  const fs::path png = a.value("--output");
  writePicture(renderLinePlot(series, params), png);
  out << "wrote " << png.string() << "\n";
  return kSuccess;
}

}  // namespace fluidviz::app
