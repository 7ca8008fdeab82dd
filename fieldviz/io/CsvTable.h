#pragma once
// Numeric CSV tables: the reference profiles and series that probes and plots compare with
// (e.g. examples/data/ghia1982_*.csv), the CSV files fluidviz writes (probes, time series), and
// `fluidviz plot`'s input.
//
// Format read: lines starting with '#' are comments (also before the header); the first other
// line names the columns, separated by commas; every later non-empty line holds one number per
// column, or "nan" for no value (what fluidviz writes for a probe point outside the grid). A column is found by its full name ("y (m)") or by the name before its unit in
// parentheses ("y"). Written: '#' comment lines, the header, then the rows with numbers in
// their shortest round-trip form (formatShortest).
#include <filesystem>
#include <string>
#include <vector>

namespace fluidviz {

struct CsvTable {
  std::vector<std::string> comments;  ///< '#' lines without the '#' and one space after it
  std::vector<std::string> names;     ///< column names as in the header, trimmed
  std::vector<std::vector<double>> columns;  ///< columns[c][row]

  std::size_t rowCount() const { return columns.empty() ? 0 : columns.front().size(); }
  /// Index of the column called `name` (see above), or -1.
  int find(const std::string& name) const;
  /// The column called `name`; FileError naming `file` and the columns there are if none is.
  const std::vector<double>& column(const std::string& name,
                                    const std::filesystem::path& file) const;
  /// "y, Re100, Re400".
  std::string nameList() const;
};

/// Parses CSV text (see above). Throws FileError naming `file` for no header, an empty column
/// name, a row with the wrong number of fields, or a field that is neither a finite number nor
/// "nan" (with its line number).
CsvTable parseCsv(const std::string& text, const std::filesystem::path& file);
/// Reads and parses `file`; FileError if it cannot be read.
CsvTable readCsv(const std::filesystem::path& file);

/// The shortest text that reads back as `value` (std::to_chars): 0.1, 5, 1e-07, not
/// 5.000000000000001; "nan" for NaN.
std::string formatShortest(double value);

/// The table as CSV text (see above). Throws std::invalid_argument if columns differ in length
/// or from names in count.
std::string formatCsv(const CsvTable& table);

}  // namespace fluidviz
