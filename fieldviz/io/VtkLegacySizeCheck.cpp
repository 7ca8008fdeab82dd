#include "fieldviz/io/VtkLegacySizeCheck.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fieldviz/io/FileError.h"

namespace fluidviz {

namespace {

// Bytes of one value of each legacy type name in a BINARY file (VTK file formats, "Simple Legacy
// Formats": bit, unsigned_char, char, ..., double, vtkIdType, vtktypeint64 ...).
double binaryBytesOf(const std::string& type) {
  static const std::map<std::string, double> bytes = {
      {"bit", 0.125},          {"unsigned_char", 1},  {"char", 1},         {"signed_char", 1},
      {"unsigned_short", 2},   {"short", 2},          {"unsigned_int", 4}, {"int", 4},
      {"unsigned_long", 8},    {"long", 8},           {"float", 4},        {"double", 8},
      {"vtkIdType", 4},        {"vtktypeint64", 8},   {"vtktypeuint64", 8}, {"vtktypeint32", 4},
      {"vtktypeuint32", 4},    {"vtktypeint8", 1},    {"vtktypeuint8", 1}, {"vtktypeint16", 2},
      {"vtktypeuint16", 2},    {"string", 1},         {"utf8_string", 1}};
  auto it = bytes.find(type);
  return it == bytes.end() ? 1.0 : it->second;
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

  /// `values` values of `type` must fit in the file.
  void requireFits(const Declaration& d, double values, const std::string& type) const {
    const double bytes = values * (binary_ ? binaryBytesOf(type) : 2.0);
    if (bytes > fileBytes_ + 16) {
      std::ostringstream msg;
      msg << "declares " << values << " values (" << (binary_ ? "binary " : "ASCII ") << type
          << "), at least " << bytes << " bytes, but the file has " << fileBytes_ << " bytes";
      fail(d, msg.str());
    }
  }

  [[noreturn]] void fail(const Declaration& d, const std::string& why) const {
    throw FileError(path_, "file " + path_.string() + " is corrupt or truncated: line " +
                               std::to_string(d.line) + " (" + d.keyword + ") " + why);
  }

 private:
  std::filesystem::path path_;
  double fileBytes_;
  bool binary_;
};

bool isKeyword(const std::string& word) {
  static const char* const keywords[] = {
      "DATASET", "DIMENSIONS", "ORIGIN", "SPACING", "ASPECT_RATIO", "POINTS", "X_COORDINATES",
      "Y_COORDINATES", "Z_COORDINATES", "CELLS", "CELL_TYPES", "VERTICES", "LINES", "POLYGONS",
      "TRIANGLE_STRIPS", "OFFSETS", "CONNECTIVITY", "POINT_DATA", "CELL_DATA", "FIELD", "SCALARS",
      "COLOR_SCALARS", "LOOKUP_TABLE", "VECTORS", "NORMALS", "TEXTURE_COORDINATES", "TENSORS",
      "METADATA", "INFORMATION", "NAME", "DATA", "COMPONENT_NAMES", "GLOBAL_IDS", "PEDIGREE_IDS",
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
  if (k == "DIMENSIONS") {
    double product = 1;
    for (const char* axis : {"nx", "ny", "nz"}) product *= sizes.count(in, d, axis);
    sizes.requireFits(d, product, "bit");
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
  } else if (k == "CELL_TYPES" || k == "POINT_DATA" || k == "CELL_DATA") {
    sizes.requireFits(d, sizes.count(in, d, "the count"), "bit");
  } else if (k == "LOOKUP_TABLE") {
    in >> name;
    if (in >> std::ws && !in.eof()) sizes.requireFits(d, 4 * sizes.count(in, d, "the size"), "unsigned_char");
  } else if (k == "SCALARS") {
    in >> name >> type;
    std::string components;
    if (in >> components && (components.size() != 1 || components[0] < '1' || components[0] > '4'))
      sizes.fail(d, "has " + components + " components; VTK allows 1 to 4");
  } else if (k == "FIELD") {
    in >> name;
    sizes.requireFits(d, sizes.count(in, d, "the number of arrays"), "bit");
  }
}

// A field array line: "name components tuples type" (inside a FIELD block); other lines that do
// not start with a keyword (data, a title) are left alone.
void checkFieldArrayLine(const LegacySizes& sizes, const std::string& line, int number) {
  std::istringstream in(line);
  std::string name, components, tuples, type, extra;
  if (!(in >> name >> components >> tuples >> type) || (in >> extra)) return;
  auto whole = [](const std::string& s) {
    return !s.empty() && s.size() <= 18 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (!whole(components) || !whole(tuples)) return;
  sizes.requireFits({"field array " + name, number}, std::stod(components) * std::stod(tuples),
                    type);
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
    if (isKeyword(first)) checkLine(sizes, line, number);
    else checkFieldArrayLine(sizes, line, number);
  }
}

}  // namespace fluidviz
