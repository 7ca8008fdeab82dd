#include "fieldviz/io/CsvTable.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "fieldviz/io/FileError.h"

namespace fluidviz {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = line.find(',', begin);
    fields.push_back(trimmed(line.substr(begin, comma - begin)));
    if (comma == std::string::npos) return fields;
    begin = comma + 1;
  }
}

// The name before a unit in parentheses: "y (m)" -> "y".
std::string withoutUnit(const std::string& name) {
  const auto paren = name.find(" (");
  return paren == std::string::npos ? name : trimmed(name.substr(0, paren));
}

double parseNumber(const std::string& field, const std::filesystem::path& file, int line,
                   const std::string& column) {
  if (field == "nan") return std::numeric_limits<double>::quiet_NaN();  // "no value" (written)
  double v = 0.0;
  const char* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, v);
  if (field.empty() || ec != std::errc() || ptr != end || !std::isfinite(v))
    throw FileError(file, file.string() + " line " + std::to_string(line) + ": '" + field +
                              "' in column '" + column + "' is not a finite number (or nan)");
  return v;
}

void appendRow(std::string& out, const std::vector<std::string>& fields) {
  for (std::size_t c = 0; c < fields.size(); ++c) {
    if (c > 0) out += ',';
    out += fields[c];
  }
  out += '\n';
}

}  // namespace

int CsvTable::find(const std::string& name) const {
  for (std::size_t c = 0; c < names.size(); ++c)
    if (names[c] == name) return static_cast<int>(c);
  for (std::size_t c = 0; c < names.size(); ++c)
    if (withoutUnit(names[c]) == name) return static_cast<int>(c);
  return -1;
}

const std::vector<double>& CsvTable::column(const std::string& name,
                                            const std::filesystem::path& file) const {
  const int c = find(name);
  if (c < 0)
    throw FileError(file, file.string() + " has no column '" + name + "'; its columns: " +
                              nameList(), name);
  return columns[static_cast<std::size_t>(c)];
}

std::string CsvTable::nameList() const {
  std::string list;
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (c > 0) list += ", ";
    list += names[c];
  }
  return list;
}

CsvTable parseCsv(const std::string& text, const std::filesystem::path& file) {
  CsvTable table;
  std::istringstream in(text);
  std::string raw;
  int lineNumber = 0;
  while (std::getline(in, raw)) {
    ++lineNumber;
    const std::string line = trimmed(raw);
    if (line.empty()) continue;
    if (line[0] == '#') {
      table.comments.push_back(trimmed(line.substr(1)));
      continue;
    }
    std::vector<std::string> fields = splitFields(line);
    if (table.names.empty()) {
      for (const std::string& name : fields)
        if (name.empty())
          throw FileError(file, file.string() + " line " + std::to_string(lineNumber) +
                                    ": the header has an empty column name");
      table.names = std::move(fields);
      table.columns.resize(table.names.size());
      continue;
    }
    if (fields.size() != table.names.size())
      throw FileError(file, file.string() + " line " + std::to_string(lineNumber) + ": " +
                                std::to_string(fields.size()) + " fields, the header names " +
                                std::to_string(table.names.size()) + " columns");
    for (std::size_t c = 0; c < fields.size(); ++c)
      table.columns[c].push_back(parseNumber(fields[c], file, lineNumber, table.names[c]));
  }
  if (table.names.empty())
    throw FileError(file, file.string() + " has no header line naming its columns");
  return table;
}

CsvTable readCsv(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError(file, "cannot read " + file.string() + ": no such file or no access");
  std::ostringstream text;
  text << in.rdbuf();
  return parseCsv(text.str(), file);
}

std::string formatShortest(double value) {
  if (std::isnan(value)) return "nan";
  char buffer[32];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, ptr) : std::string("nan");
}

std::string formatCsv(const CsvTable& table) {
  if (table.columns.size() != table.names.size())
    throw std::invalid_argument("CSV table: " + std::to_string(table.names.size()) + " names, " +
                                std::to_string(table.columns.size()) + " columns");
  for (const auto& c : table.columns)
    if (c.size() != table.rowCount())
      throw std::invalid_argument("CSV table: columns of different lengths");
  std::string out;
  for (const std::string& c : table.comments) out += "# " + c + "\n";
  appendRow(out, table.names);
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    std::vector<std::string> row;
    for (const auto& column : table.columns) row.push_back(formatShortest(column[r]));
    appendRow(out, row);
  }
  return out;
}

}  // namespace fluidviz
