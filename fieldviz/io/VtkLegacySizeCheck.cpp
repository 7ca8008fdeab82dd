#include "fieldviz/io/VtkLegacySizeCheck.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fieldviz/io/FileError.h"

namespace fluidviz {

namespace {

// Bytes of one value of each legacy type name in a BINARY file (VTK file formats, "Simple Legacy
// Formats"; VTK compares them in lower case); 0 for a name VTK does not read. VTK 9.1's reader
// dereferences the null array it makes of an unknown type in some places (a FIELD array of type
// "i" crashed vtkStructuredGridReader::ReadMetaDataSimple), so unknown types are refused first.
std::string lowerCase(std::string word) {
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return word;
}

double binaryBytesOf(const std::string& name) {
  const std::string type = lowerCase(name);
  static const std::map<std::string, double> bytes = {
      {"bit", 0.125},        {"unsigned_char", 1}, {"char", 1},          {"signed_char", 1},
      {"unsigned_short", 2}, {"short", 2},         {"unsigned_int", 4},  {"int", 4},
      {"unsigned_long", 8},  {"long", 8},          {"float", 4},         {"double", 8},
      {"vtkidtype", 4},      {"vtktypeint64", 8},  {"vtktypeuint64", 8}, {"string", 1},
      {"utf8_string", 1}};
  auto it = bytes.find(type);
  return it == bytes.end() ? 0.0 : it->second;
}

// A token as it may be shown in a message: control bytes as '?', at most 40 characters.
std::string printable(const std::string& token) {
  std::string out = token.substr(0, 40);
  for (char& c : out)
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  return out;
}

std::string exactCount(double n) {
  std::ostringstream out;
  out << std::setprecision(15) << n;
  return out.str();
}

struct Declaration {
  std::string keyword;
  int line;
};

class LegacySizes {
 public:
  LegacySizes(std::filesystem::path path, double fileBytes, bool binary)
      : path_(std::move(path)), fileBytes_(fileBytes), binary_(binary) {}

  /// A count read from the line; refuses what is not a whole number >= 0.
  double count(std::istringstream& in, const Declaration& d, const char* what) const {
    std::string token;
    if (!(in >> token) || token.find_first_not_of("0123456789") != std::string::npos ||
        token.size() > 18)
      fail(d, std::string(what) + " is " + (token.empty() ? "missing" : "'" + token + "'") +
                  ", expected a whole number >= 0");
    return std::stod(token);
  }

  /// `type` must be one VTK reads.
  void requireKnownType(const Declaration& d, const std::string& type) const {
    if (binaryBytesOf(type) == 0.0)
      fail(d, "has type '" + printable(type) + "'; allowed: bit, char, signed_char, " +
                  "unsigned_char, short, unsigned_short, int, unsigned_int, long, " +
                  "unsigned_long, vtkIdType, vtktypeint64, vtktypeuint64, float, double, " +
                  "string, utf8_string");
  }

  /// `values` values of `type` must fit in the file.
  void requireFits(const Declaration& d, double values, const std::string& type) const {
    requireKnownType(d, type);
    requireBytes(d, values, values * (binary_ ? binaryBytesOf(type) : 2.0),
                 std::string("values (") + (binary_ ? "binary " : "ASCII ") + type + ")");
  }

  /// A count of `noun` (nodes, cells, arrays) that needs at least one value each, of at least a
  /// bit in binary files and two characters in ASCII ones.
  void requireCountFits(const Declaration& d, double count, const std::string& noun) const {
    requireBytes(d, count, count * (binary_ ? 0.125 : 2.0), noun);
  }

  [[noreturn]] void fail(const Declaration& d, const std::string& why) const {
    throw FileError(path_, "file " + path_.string() + " is corrupt or truncated: line " +
                               std::to_string(d.line) + " (" + d.keyword + ") " + why);
  }

 private:
  void requireBytes(const Declaration& d, double count, double bytes,
                    const std::string& what) const {
    if (bytes <= fileBytes_ + 16) return;
    std::ostringstream msg;
    msg << "declares " << count << " " << what << ", at least " << bytes
        << " bytes, but the file has " << fileBytes_ << " bytes";
    fail(d, msg.str());
  }

 public:

 private:
  std::filesystem::path path_;
  double fileBytes_;
  bool binary_;
};

// The dataset types vtkDataSetReader reads (VTK file formats, "Dataset Format").
constexpr const char* kDatasetTypes =
    "STRUCTURED_POINTS, STRUCTURED_GRID, RECTILINEAR_GRID, UNSTRUCTURED_GRID, POLYDATA";

// VTK compares them in lower case.
bool isDatasetType(const std::string& word) {
  const std::string lower = lowerCase(word);
  for (const char* t : {"structured_points", "structured_grid", "rectilinear_grid",
                        "unstructured_grid", "polydata"})
    if (lower == t) return true;
  return false;
}

bool isKeyword(const std::string& word) {
  static const char* const keywords[] = {"DATASET",
                                         "DIMENSIONS",
                                         "ORIGIN",
                                         "SPACING",
                                         "ASPECT_RATIO",
                                         "POINTS",
                                         "X_COORDINATES",
                                         "Y_COORDINATES",
                                         "Z_COORDINATES",
                                         "CELLS",
                                         "CELL_TYPES",
                                         "VERTICES",
                                         "LINES",
                                         "POLYGONS",
                                         "TRIANGLE_STRIPS",
                                         "OFFSETS",
                                         "CONNECTIVITY",
                                         "POINT_DATA",
                                         "CELL_DATA",
                                         "FIELD",
                                         "SCALARS",
                                         "COLOR_SCALARS",
                                         "LOOKUP_TABLE",
                                         "VECTORS",
                                         "NORMALS",
                                         "TEXTURE_COORDINATES",
                                         "TENSORS",
                                         "METADATA",
                                         "INFORMATION",
                                         "NAME",
                                         "DATA",
                                         "COMPONENT_NAMES",
                                         "GLOBAL_IDS",
                                         "PEDIGREE_IDS",
                                         "EDGE_FLAGS"};
  for (const char* k : keywords)
    if (word == k) return true;
  return false;
}

void checkLine(const LegacySizes& sizes, const std::string& line, int number) {
  std::istringstream in(line);
  Declaration d;
  in >> d.keyword;
  d.line = number;
  std::string type, name;
  const std::string& k = d.keyword;
  if (k == "DATASET") {
    in >> type;
    if (!isDatasetType(type))
      sizes.fail(d, "has dataset type '" + printable(type) + "'; allowed: " + kDatasetTypes);
  } else if (k == "DIMENSIONS") {
    double product = 1;
    for (const char* axis : {"nx", "ny", "nz"}) product *= sizes.count(in, d, axis);
    sizes.requireCountFits(d, product, "nodes");
  } else if (k == "POINTS") {
    const double n = sizes.count(in, d, "the number of points");
    in >> type;
    sizes.requireFits(d, 3 * n, type);
  } else if (k == "X_COORDINATES" || k == "Y_COORDINATES" || k == "Z_COORDINATES") {
    const double n = sizes.count(in, d, "the number of coordinates");
    in >> type;
    sizes.requireFits(d, n, type);
  } else if (k == "CELLS" || k == "VERTICES" || k == "LINES" || k == "POLYGONS" ||
             k == "TRIANGLE_STRIPS") {
    sizes.count(in, d, "the number of cells");
    sizes.requireFits(d, sizes.count(in, d, "the list size"), "unsigned_char");
  } else if (k == "CELL_TYPES") {
    sizes.requireCountFits(d, sizes.count(in, d, "the count"), "cell types");
  } else if (k == "POINT_DATA" || k == "CELL_DATA") {
    sizes.requireCountFits(d, sizes.count(in, d, "the count"),
                           k == "POINT_DATA" ? "point values" : "cell values");
  } else if (k == "LOOKUP_TABLE") {
    in >> name;
    if (in >> std::ws && !in.eof())
      sizes.requireFits(d, 4 * sizes.count(in, d, "the size"), "unsigned_char");
  } else if (k == "VECTORS" || k == "NORMALS" || k == "TENSORS") {
    in >> name >> type;
    sizes.requireKnownType(d, type);
  } else if (k == "TEXTURE_COORDINATES") {
    std::string dim;
    in >> name >> dim >> type;
    sizes.requireKnownType(d, type);
  } else if (k == "OFFSETS" || k == "CONNECTIVITY") {
    in >> type;
    sizes.requireKnownType(d, type);
  } else if (k == "SCALARS") {
    in >> name >> type;
    sizes.requireKnownType(d, type);
    std::string components;
    if (in >> components && (components.size() != 1 || components[0] < '1' || components[0] > '4'))
      sizes.fail(d, "has " + components + " components; VTK allows 1 to 4");
  } else if (k == "FIELD") {
    in >> name;
    sizes.requireCountFits(d, sizes.count(in, d, "the number of arrays"), "arrays");
  }
}

bool isWholeNumber(const std::string& s) {
  return !s.empty() && s.size() <= 18 && s.find_first_not_of("0123456789") == std::string::npos;
}

// The arrays of a FIELD block, followed through the file: each header "name components tuples
// type" (or NULL_ARRAY) is checked like a keyword line, then its data skipped (BINARY: exactly
// components x tuples values of the type, then the rest of the line; ASCII: that many tokens),
// and a METADATA block after it, up to its empty line. A header that is not of that form is
// refused: VTK 9.1 reads one as an array of an unknown type and may dereference it (issue 15).
// String arrays end the walk (their binary layout has no fixed size); scanning goes on by lines.
void walkFieldArrays(std::istream& in, const LegacySizes& sizes, double arrays, int& number,
                     bool binary) {
  std::string line;
  for (double a = 0; a < arrays; ++a) {
    do {
      if (!std::getline(in, line)) return;
      ++number;
    } while (line.find_first_not_of(" \t\r") == std::string::npos);
    std::istringstream header(line);
    std::string name, components, tuples, type, extra;
    header >> name;
    if (name == "NULL_ARRAY") continue;
    const Declaration d{"field array " + printable(name), number};
    if (!(header >> components >> tuples >> type) || (header >> extra) ||
        !isWholeNumber(components) || !isWholeNumber(tuples))
      sizes.fail(d, "is '" + printable(line) +
                        "'; a FIELD array starts with 'name components "
                        "tuples type'");
    const double values = std::stod(components) * std::stod(tuples);
    sizes.requireFits(d, values, type);
    const double bytesPerValue = binaryBytesOf(type);
    const std::string lower = lowerCase(type);
    if (lower == "string" || lower == "utf8_string") return;
    if (binary) {
      in.seekg(static_cast<std::streamoff>(std::ceil(values * bytesPerValue)), std::ios::cur);
      std::getline(in, line);
    } else {
      std::string token;
      for (double v = 0; v < values && in >> token; ++v) {
      }
      std::getline(in, line);
    }
    ++number;  // data lines are not counted exactly in ASCII; the numbers stay close
    const std::streampos afterData = in.tellg();
    if (std::getline(in, line) && line.rfind("METADATA", 0) == 0) {
      while (std::getline(in, line) && line.find_first_not_of(" \t\r") != std::string::npos) {
      }
    } else {
      in.clear();
      in.seekg(afterData);
    }
  }
}

bool isLegacyCellList(const std::string& keyword) {
  return keyword == "CELLS" || keyword == "VERTICES" || keyword == "LINES" ||
         keyword == "POLYGONS" || keyword == "TRIANGLE_STRIPS";
}

// Before version 5 a cell list "KEYWORD n size" is `size` integers, each cell its point count
// and then its point ids. VTK 9.1 copies it cell by cell without checking the counts against
// the list (a count past the end read beyond it: vtkCellArray::AppendLegacyFormat, found by
// fuzzing), so the list is walked here: n cells exactly filling `size` integers. BINARY lists are
// big-endian int32.
void walkLegacyCellList(std::istream& in, const LegacySizes& sizes, const std::string& line,
                        int number, bool binary) {
  std::istringstream header(line);
  std::string keyword;
  double cells = 0, size = 0;
  header >> keyword >> cells >> size;
  const Declaration d{keyword, number};
  const std::streampos start = in.tellg();
  auto next = [&](long long& value) {
    if (binary) {
      unsigned char b[4];
      if (!in.read(reinterpret_cast<char*>(b), 4)) return false;
      value = static_cast<std::int32_t>((std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                                        (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]));
      return true;
    }
    std::string token;
    if (!(in >> token)) return false;
    char* end = nullptr;
    value = std::strtoll(token.c_str(), &end, 10);
    return end && *end == '\0';
  };
  double used = 0;
  for (double c = 0; c < cells; ++c) {
    long long points = 0;
    if (!next(points)) sizes.fail(d, "ends before its " + exactCount(cells) + " cells");
    if (points < 0 || used + 1 + points > size)
      sizes.fail(d, "cell " + exactCount(c) + " has " + std::to_string(points) +
                        " points, past the list of " + exactCount(size) + " integers");
    used += 1 + points;
    for (long long k = 0; k < points; ++k) {
      long long id = 0;
      if (!next(id)) sizes.fail(d, "ends inside cell " + exactCount(c));
    }
  }
  if (used != size)
    sizes.fail(d, "lists " + exactCount(cells) + " cells in " + exactCount(used) +
                      " integers, not the " + exactCount(size) + " it declares");
  in.clear();
  in.seekg(start);  // the line scan goes on from the list's first line
}

}  // namespace

void checkLegacyVtkSizes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "file " + path.string() + " cannot be opened");
  std::string line;
  std::vector<std::string> head;
  for (int i = 0; i < 3 && std::getline(in, line); ++i) head.push_back(line);
  if (head.empty() || head[0].rfind("# vtk DataFile", 0) != 0)
    throw FileError(path, "file " + path.string() +
                              " is not a legacy VTK file (its first line must start with "
                              "'# vtk DataFile Version')");
  int major = 0, minor = 0;
  if (std::sscanf(head[0].c_str(), "# vtk DataFile Version %d.%d", &major, &minor) != 2)
    throw FileError(path, "file " + path.string() + ": the first line is '" + printable(head[0]) +
                              "'; expected '# vtk DataFile Version M.m' (VTK would guess the "
                              "layout of the cells)");
  const bool binary = head.size() == 3 && head[2].rfind("BINARY", 0) == 0;
  in.seekg(0, std::ios::end);
  const double fileBytes = static_cast<double>(in.tellg());
  in.seekg(0);
  const LegacySizes sizes(path, fileBytes, binary);
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number <= 3 || line.empty() || !std::isalpha(static_cast<unsigned char>(line[0]))) continue;
    const std::string first = line.substr(0, line.find_first_of(" \t\r"));
    if (!isKeyword(first)) continue;
    checkLine(sizes, line, number);
    if (major < 5 && isLegacyCellList(first)) walkLegacyCellList(in, sizes, line, number, binary);
    if (first == "FIELD") {
      std::istringstream field(line);
      std::string keyword, name, arrays;
      field >> keyword >> name >> arrays;
      walkFieldArrays(in, sizes, std::stod(arrays), number, binary);  // checkLine read a count
    }
  }
}

}  // namespace fluidviz
