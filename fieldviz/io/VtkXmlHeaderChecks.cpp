#include "fieldviz/io/VtkXmlHeaderChecks.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <vtkDataArray.h>
#include <vtkType.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include "fieldviz/core/ByteSize.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlSizeCheck.h"

namespace fluidviz {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& problem,
                       const std::string& array = {}) {
  throw FileError(path, "file " + path.string() + ": " + problem, array);
}

std::string quoted(const char* text) { return std::string("\"") + (text ? text : "") + "\""; }

std::vector<vtkXMLDataElement*> children(vtkXMLDataElement* e, const char* name) {
  std::vector<vtkXMLDataElement*> out;
  for (int i = 0; e && i < e->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* c = e->GetNestedElement(i);
    if (c && c->GetName() && std::strcmp(c->GetName(), name) == 0) out.push_back(c);
  }
  return out;
}

vtkXMLDataElement* child(vtkXMLDataElement* e, const char* name) {
  const auto found = children(e, name);
  return found.empty() ? nullptr : found.front();
}

vtkXMLDataElement* primaryElement(vtkXMLDataParser* parser, const char* dataType) {
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  return root ? child(root, dataType) : nullptr;
}

// The attribute's words as numbers; nullopt unless there are exactly `count` of them, each a
// number in full (strtod: "nan" and "inf" are numbers, checked by the callers).
std::optional<std::vector<double>> numbersOf(const char* text, std::size_t count) {
  std::istringstream words(text ? text : "");
  std::vector<double> values;
  for (std::string word; words >> word;) {
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0') return std::nullopt;
    values.push_back(x);
  }
  if (values.size() != count) return std::nullopt;
  return values;
}

bool isInt(double x) { return std::floor(x) == x && x >= INT_MIN && x <= INT_MAX; }

// VTK keeps its default (origin 0, spacing 1) for an attribute it cannot parse: "nan 0.1 1" or
// "abc" would silently put the data on another grid.
void requireFiniteNumbers(vtkXMLDataElement* e, const char* attribute, std::size_t count,
                          const fs::path& path) {
  const char* text = e->GetAttribute(attribute);
  if (!text) return;  // absent: VTK's default, which is a valid grid
  const auto values = numbersOf(text, count);
  bool ok = values.has_value();
  for (std::size_t i = 0; ok && i < count; ++i) ok = std::isfinite((*values)[i]);
  if (!ok)
    fail(path, std::string(e->GetName()) + " " + attribute + " is " + quoted(text) +
                   "; allowed: " + std::to_string(count) + " finite numbers");
}

using Extent = std::array<long long, 6>;

// An Extent attribute: 6 whole numbers that VTK's int can hold, with a node count per axis that
// a grid's int can hold too.
Extent extentOf(vtkXMLDataElement* e, const char* attribute, const std::string& owner,
                const fs::path& path) {
  const char* text = e->GetAttribute(attribute);
  const auto values = numbersOf(text, 6);
  bool ok = values.has_value();
  for (std::size_t i = 0; ok && i < 6; ++i) ok = isInt((*values)[i]);
  if (!ok)
    fail(path, owner + " " + attribute + " is " + quoted(text) +
                   "; allowed: 6 whole numbers x0 x1 y0 y1 z0 z1 (first and last node index)");
  Extent extent{};
  for (int i = 0; i < 6; ++i) extent[i] = static_cast<long long>((*values)[i]);
  static const char* axis = "xyz";
  for (int a = 0; a < 3; ++a)
    if (extent[2 * a + 1] - extent[2 * a] + 1 > INT_MAX)
      fail(path, owner + " " + attribute + " " + quoted(text) + " gives " +
                     std::to_string(extent[2 * a + 1] - extent[2 * a] + 1) + " nodes along " +
                     axis[a] + "; at most " + std::to_string(INT_MAX) + " fit a grid");
  return extent;
}

long long nodesAlong(const Extent& e, int axis) {
  return std::max(0LL, e[2 * axis + 1] - e[2 * axis] + 1);
}
double pointsOf(const Extent& e) {
  return double(nodesAlong(e, 0)) * double(nodesAlong(e, 1)) * double(nodesAlong(e, 2));
}
double cellsOf(const Extent& e) {
  double cells = 1;
  for (int a = 0; a < 3; ++a) cells *= double(std::max(1LL, nodesAlong(e, a) - 1));
  return pointsOf(e) > 0 ? cells : 0;
}
bool inside(const Extent& piece, const Extent& whole) {
  for (int a = 0; a < 3; ++a)
    if (piece[2 * a] < whole[2 * a] || piece[2 * a + 1] > whole[2 * a + 1]) return false;
  return true;
}

struct DeclaredArray {
  vtkXMLDataElement* element;
  std::string name;
  std::string typeName;
  int wordType;
  int components;
  std::size_t wordSize;
};

// The DataArrays of a PointData, CellData or Points element. Arrays whose type VTK could not
// parse are left out: VTK has already reported them.
std::vector<DeclaredArray> declaredArrays(vtkXMLDataParser* parser, vtkXMLDataElement* section) {
  std::vector<DeclaredArray> out;
  for (vtkXMLDataElement* e : children(section, "DataArray")) {
    int type = 0;
    if (!e->GetWordTypeAttribute("type", type)) continue;
    int components = 1;
    e->GetScalarAttribute("NumberOfComponents", components);
    const char* name = e->GetAttribute("Name");
    out.push_back({e, name ? name : "(unnamed)", e->GetAttribute("type"), type,
                   std::max(components, 1), parser->GetWordTypeSize(type)});
  }
  return out;
}

double bytesPerTuple(const std::vector<DeclaredArray>& arrays) {
  double bytes = 0;
  for (const DeclaredArray& a : arrays) bytes += double(a.components) * double(a.wordSize);
  return bytes;
}

std::string describe(const std::vector<DeclaredArray>& arrays) {
  std::string list;
  for (const DeclaredArray& a : arrays)
    list += (list.empty() ? "" : ", ") + a.name + " (" + std::to_string(a.components) + " x " +
            a.typeName + ")";
  return list;
}

// Reading allocates every declared array for all declared points at once; a header that asks for
// more than the machine has is refused here, before VTK tries.
void requireAffordable(double bytes, const std::string& what, const fs::path& path) {
  const double memory = physicalMemoryBytes();
  if (memory <= 0 || bytes <= memory) return;
  fail(path, what + " would need " + formatBytes(bytes) + " of memory to read, more than the " +
                 formatBytes(memory) + " of this machine; refused before allocating (the header "
                 "is damaged, or the file is too large for this machine)");
}

std::string roundedCount(double n) {
  std::ostringstream s;
  s.precision(4);
  s << n;
  return s.str();
}

// ---- ImageData, RectilinearGrid, StructuredGrid (extents) ------------------------------------

bool isStructured(const char* dataType) {
  for (const char* t : {"ImageData", "RectilinearGrid", "StructuredGrid"})
    if (std::strcmp(dataType, t) == 0) return true;
  return false;
}

void checkStructuredHeader(vtkXMLDataParser* parser, vtkXMLDataElement* image,
                           const char* dataType, const fs::path& path) {
  if (std::strcmp(dataType, "ImageData") == 0) {
    requireFiniteNumbers(image, "Origin", 3, path);
    requireFiniteNumbers(image, "Spacing", 3, path);
  }
  const Extent whole = extentOf(image, "WholeExtent", dataType, path);
  const std::vector<vtkXMLDataElement*> pieces = children(image, "Piece");
  double covered = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const std::string owner = "Piece " + std::to_string(k);
    const Extent piece = extentOf(pieces[k], "Extent", owner, path);
    if (pointsOf(piece) > 0 && !inside(piece, whole))
      fail(path, owner + " Extent " + quoted(pieces[k]->GetAttribute("Extent")) +
                     " reaches outside WholeExtent " + quoted(image->GetAttribute("WholeExtent")));
    covered += pointsOf(piece);
  }
  if (pieces.empty()) return;
  auto pointArrays = declaredArrays(parser, child(pieces[0], "PointData"));
  for (const DeclaredArray& a : declaredArrays(parser, child(pieces[0], "Points")))
    pointArrays.push_back(a);  // a StructuredGrid's coordinates, one per point
  const auto cellArrays = declaredArrays(parser, child(pieces[0], "CellData"));
  const double bytes =
      pointsOf(whole) * bytesPerTuple(pointArrays) + cellsOf(whole) * bytesPerTuple(cellArrays);
  std::string arrays = describe(pointArrays);
  if (!cellArrays.empty()) arrays += (arrays.empty() ? "" : ", ") + describe(cellArrays);
  requireAffordable(bytes,
                    "WholeExtent " + quoted(image->GetAttribute("WholeExtent")) + " gives " +
                        std::to_string(nodesAlong(whole, 0)) + " x " +
                        std::to_string(nodesAlong(whole, 1)) + " x " +
                        std::to_string(nodesAlong(whole, 2)) + " = " +
                        roundedCount(pointsOf(whole)) + " points; its arrays " + arrays,
                    path);
  if (covered < pointsOf(whole))
    fail(path, "its pieces hold " + roundedCount(covered) + " of the " +
                   roundedCount(pointsOf(whole)) + " points of WholeExtent " +
                   quoted(image->GetAttribute("WholeExtent")) + "; the file is incomplete");
}

// ---- PolyData, UnstructuredGrid (point and cell counts) ---------------------------------------

const std::vector<const char*>& cellCountAttributes(vtkXMLDataElement* piece) {
  static const std::vector<const char*> poly = {"NumberOfVerts", "NumberOfLines",
                                                "NumberOfStrips", "NumberOfPolys"};
  static const std::vector<const char*> unstructured = {"NumberOfCells"};
  const char* owner = piece->GetParent() ? piece->GetParent()->GetName() : nullptr;
  return owner && std::strcmp(owner, "UnstructuredGrid") == 0 ? unstructured : poly;
}

double countOf(vtkXMLDataElement* piece, const char* attribute, const std::string& owner,
               const fs::path& path) {
  const char* text = piece->GetAttribute(attribute);
  if (!text) return 0;
  const auto value = numbersOf(text, 1);
  if (!value || !((*value)[0] >= 0) || std::floor((*value)[0]) != (*value)[0] ||
      (*value)[0] > 9.2e18)
    fail(path, owner + " " + attribute + " is " + quoted(text) + "; allowed: a whole number >= 0");
  return (*value)[0];
}

double cellCountOf(vtkXMLDataElement* piece, const std::string& owner, const fs::path& path) {
  double cells = 0;
  for (const char* kind : cellCountAttributes(piece)) cells += countOf(piece, kind, owner, path);
  return cells;
}

void checkPointSetHeader(vtkXMLDataParser* parser, vtkXMLDataElement* poly, const fs::path& path) {
  double points = 0, cells = 0, bytes = 0;
  std::string arrays;
  const std::vector<vtkXMLDataElement*> pieces = children(poly, "Piece");
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const std::string owner = "Piece " + std::to_string(k);
    const double n = countOf(pieces[k], "NumberOfPoints", owner, path);
    const double c = cellCountOf(pieces[k], owner, path);
    const auto pointArrays = declaredArrays(parser, child(pieces[k], "Points"));
    const auto dataArrays = declaredArrays(parser, child(pieces[k], "PointData"));
    const auto cellArrays = declaredArrays(parser, child(pieces[k], "CellData"));
    // A cell costs at least an offset and one connectivity entry (8 bytes each).
    bytes += n * (bytesPerTuple(pointArrays) + bytesPerTuple(dataArrays)) +
             c * (bytesPerTuple(cellArrays) + 16.0);
    points += n;
    cells += c;
    if (k == 0)
      for (const auto* list : {&pointArrays, &dataArrays, &cellArrays})
        if (!list->empty()) arrays += (arrays.empty() ? "" : ", ") + describe(*list);
  }
  requireAffordable(bytes,
                    "its pieces declare " + roundedCount(points) + " points and " +
                        roundedCount(cells) + " cells; with their arrays " +
                        (arrays.empty() ? std::string("(none)") : arrays) + " they",
                    path);
}

// ---- Values beyond the declared size -----------------------------------------------------------

// 1 if the array's data goes on past `words` values, 0 if it ends there (or earlier: VTK has
// reported that already).
std::size_t wordsPast(vtkXMLDataParser* parser, const DeclaredArray& a, double words,
                      const fs::path& path) {
  if (a.wordType == VTK_STRING || a.wordType == VTK_BIT || words < 0 || words > 9.2e18) return 0;
  // Compressed: the header says how many bytes there are; asking VTK for the word just past the
  // end reads a block size past its list when the data ends on a block boundary.
  if (const std::optional<double> bytes = compressedArrayBytes(parser, path, a.element))
    return *bytes > words * vtkDataArray::GetDataTypeSize(a.wordType) ? 1 : 0;
  unsigned char probe[16];
  const auto start = static_cast<vtkTypeUInt64>(words);
  const ArrayEncoding encoding = arrayEncodingOf(a.element);
  if (encoding == ArrayEncoding::Appended) {
    vtkTypeInt64 offset = 0;
    if (!a.element->GetScalarAttribute("offset", offset)) return 0;
    return parser->ReadAppendedData(offset, probe, start, 1, a.wordType);
  }
  const bool ascii = encoding == ArrayEncoding::Ascii;
  return parser->ReadInlineData(a.element, ascii ? 1 : 0, probe, start, 1, a.wordType);
}

void requireNoExtraValues(vtkXMLDataParser* parser, vtkXMLDataElement* section, double tuples,
                          const std::string& declaredBy, const fs::path& path) {
  if (!(tuples > 0)) return;  // an empty or inverted extent: Grid::validate says so
  for (const DeclaredArray& a : declaredArrays(parser, section)) {
    if (wordsPast(parser, a, tuples * a.components, path) == 0) continue;
    fail(path,
         "array '" + a.name + "' holds more values than the " + roundedCount(tuples) +
             " tuples x " + std::to_string(a.components) +
             (a.components == 1 ? " component of " : " components of ") + a.typeName +
             " that " + declaredBy + " and its NumberOfComponents and type give; the header "
             "does not match the data (edited extent, component count or type?)",
         a.name);
  }
}

// A RectilinearGrid's <Coordinates> hold one array per axis, as long as the Extent along it.
void requireNoExtraCoordinates(vtkXMLDataParser* parser, vtkXMLDataElement* piece,
                               const std::string& owner, const fs::path& path) {
  vtkXMLDataElement* coordinates = child(piece, "Coordinates");
  if (!coordinates) return;
  const Extent e = extentOf(piece, "Extent", owner, path);
  const std::vector<DeclaredArray> axes = declaredArrays(parser, coordinates);
  for (std::size_t a = 0; a < axes.size() && a < 3; ++a) {
    const double nodes = double(nodesAlong(e, int(a)));
    if (wordsPast(parser, axes[a], nodes * axes[a].components, path) == 0) continue;
    fail(path,
         "coordinate array '" + axes[a].name + "' holds more than the " + roundedCount(nodes) +
             " values that " + owner + " Extent " + quoted(piece->GetAttribute("Extent")) +
             " gives along " + "xyz"[a],
         axes[a].name);
  }
}

// Every element nested in a `sections` element is one of the two array elements: VTK's readers
// take any element there as an array, sized by whatever its attributes say.
template <std::size_t N>
void requireOnlyArrayElements(vtkXMLDataElement* root, const char* const (&sections)[N],
                              const char* arrayElement, const char* stringArrayElement,
                              const fs::path& path) {
  for (const char* section : sections)
    forEachElement(root, section, [&](vtkXMLDataElement* s) {
      for (int i = 0; i < s->GetNumberOfNestedElements(); ++i) {
        vtkXMLDataElement* e = s->GetNestedElement(i);
        const char* name = e->GetName();
        if (name && (std::strcmp(name, arrayElement) == 0 ||
                     std::strcmp(name, stringArrayElement) == 0))
          continue;
        const char* array = e->GetAttribute("Name");
        fail(path,
             "element <" + std::string(name ? name : "") + ">" +
                 (array ? " '" + std::string(array) + "'" : std::string()) + " inside <" +
                 section + "> is not an array (allowed: " + arrayElement + ", " +
                 stringArrayElement + "); VTK would read it as one with whatever size its "
                 "attributes give",
             array ? array : "");
      }
    });
}

}  // namespace

void checkSectionElements(vtkXMLDataParser* parser, const fs::path& path) {
  static const char* const sections[] = {"PointData", "CellData", "FieldData", "Points",
                                         "Coordinates", "Cells", "Verts", "Lines", "Strips",
                                         "Polys"};
  requireOnlyArrayElements(parser ? parser->GetRootElement() : nullptr, sections, "DataArray",
                           "Array", path);
}

void checkPointCoordinates(vtkXMLDataParser* parser, const fs::path& path) {
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  forEachElement(root, "Points", [&](vtkXMLDataElement* points) {
    for (const DeclaredArray& a : declaredArrays(parser, points))
      if (a.components != 3)
        fail(path,
             "the point coordinates, array '" + a.name + "' inside <Points>, have " +
                 std::to_string(a.components) + " component(s)" +
                 (a.element->GetAttribute("NumberOfComponents")
                      ? std::string()
                      : " (no NumberOfComponents attribute)") +
                 "; allowed: NumberOfComponents=\"3\" (x, y, z)",
             a.name);
  });
}

void checkArrayTypes(vtkXMLDataParser* parser, const fs::path& path) {
  static const char* const known[] = {"Int8",   "Int16",  "Int32",   "Int64",   "UInt8",
                                      "UInt16", "UInt32", "UInt64",  "Float32", "Float64",
                                      "String", "Bit",    "Char"};
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  forEachArrayElement(root, [&](vtkXMLDataElement* e) {
    // VTK sizes its arrays with a negative count as given (std::length_error, an abort).
    if (const char* components = e->GetAttribute("NumberOfComponents")) {
      const auto n = numbersOf(components, 1);
      if (!n || !((*n)[0] >= 1 && isInt((*n)[0]))) {
        const char* name = e->GetAttribute("Name");
        const std::string array = name ? name : "(unnamed)";
        fail(path, "array '" + array + "' has NumberOfComponents=" + quoted(components) +
                       "; allowed: a whole number >= 1", array);
      }
    }
    const char* type = e->GetAttribute("type");
    for (const char* k : known)
      if (type && std::strcmp(type, k) == 0) return;
    const char* name = e->GetAttribute("Name");
    const std::string array = name ? name : "(unnamed)";
    fail(path,
         "array '" + array + "' has type " + (type ? quoted(type) : std::string("(none)")) +
             "; allowed: Int8, Int16, Int32, Int64, UInt8, UInt16, UInt32, UInt64, Float32, "
             "Float64, String, Bit",
         array);
  });
}

void checkVtkXmlHeader(vtkXMLDataParser* parser, const char* dataType, const fs::path& path) {
  vtkXMLDataElement* primary = primaryElement(parser, dataType);
  if (!primary) return;  // VTK has reported the missing element
  if (isStructured(dataType))
    checkStructuredHeader(parser, primary, dataType, path);
  else if (std::strcmp(dataType, "PolyData") == 0 || std::strcmp(dataType, "UnstructuredGrid") == 0)
    checkPointSetHeader(parser, primary, path);
}

namespace {

struct ArrayDeclaration {
  std::string type;
  std::string components;
};

// The arrays of a section element by name ("" for the one of <Points>), as the file spells them
// (NumberOfComponents absent: "1").
std::vector<std::pair<std::string, ArrayDeclaration>> declarationsIn(vtkXMLDataElement* root,
                                                                     const char* section,
                                                                     const char* arrayElement) {
  std::vector<std::pair<std::string, ArrayDeclaration>> out;
  forEachElement(root, section, [&](vtkXMLDataElement* s) {
    for (vtkXMLDataElement* a : children(s, arrayElement)) {
      const char* name = a->GetAttribute("Name");
      const char* components = a->GetAttribute("NumberOfComponents");
      const char* type = a->GetAttribute("type");
      const bool points = std::strstr(section, "Points") != nullptr;
      out.push_back({points ? "" : (name ? name : ""),
                     {type ? type : "", components ? components : "1"}});
    }
  });
  return out;
}

}  // namespace

void checkSummaryMatchesPiece(vtkXMLDataElement* summaryRoot, vtkXMLDataElement* pieceRoot,
                              const fs::path& summary, const std::string& source) {
  // A misspelt <PDataArray> is read by VTK's summary readers as an array too: one declaring 6
  // components where the piece has 3 made vtkXMLPDataReader copy past the piece's values
  // (fuzz_vtk_xml_grids, ASan heap-buffer-overflow).
  static const char* const summarySections[] = {"PPointData", "PCellData", "PPoints",
                                                "PCoordinates"};
  requireOnlyArrayElements(summaryRoot, summarySections, "PDataArray", "PArray", summary);
  static const char* const sections[][2] = {
      {"PPointData", "PointData"}, {"PCellData", "CellData"}, {"PPoints", "Points"}};
  for (const auto& section : sections) {
    const auto inPiece = declarationsIn(pieceRoot, section[1], "DataArray");
    for (const auto& entry : declarationsIn(summaryRoot, section[0], "PDataArray")) {
      const std::string& name = entry.first;  // named, not bound: lambdas capture it
      const ArrayDeclaration& declared = entry.second;
      const std::string array = name.empty() ? "points" : "'" + name + "'";
      auto found = std::find_if(inPiece.begin(), inPiece.end(),
                                [&](const auto& p) { return p.first == name; });
      const std::string where = std::string("<") + section[0] + ">";
      if (found == inPiece.end())
        fail(summary, "array " + array + " of " + where + " is not in piece " + source, name);
      if (found->second.type != declared.type || found->second.components != declared.components)
        fail(summary, "array " + array + " of " + where + " is " + declared.type + " x " +
                          declared.components + ", in piece " + source + " it is " +
                          found->second.type + " x " + found->second.components +
                          "; they must agree (VTK would read the piece's values as the "
                          "summary's type)",
             name);
    }
  }
}

void checkNoValuesBeyondDeclared(vtkXMLDataParser* parser, const char* dataType,
                                 const fs::path& path) {
  vtkXMLDataElement* primary = primaryElement(parser, dataType);
  if (!primary) return;
  const bool structured = isStructured(dataType);
  // The reader has closed its stream after reading; the probes read through one of our own.
  ParserStreamLoan loan(parser, path);
  if (!loan.ok()) return;
  const std::vector<vtkXMLDataElement*> pieces = children(primary, "Piece");
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const std::string owner = "Piece " + std::to_string(k);
    double points = 0, cells = 0;
    std::string pointsFrom, cellsFrom;
    if (structured) {
      const Extent e = extentOf(pieces[k], "Extent", owner, path);
      points = pointsOf(e);
      cells = cellsOf(e);
      pointsFrom = cellsFrom = owner + " Extent " + quoted(pieces[k]->GetAttribute("Extent"));
    } else {
      points = countOf(pieces[k], "NumberOfPoints", owner, path);
      cells = cellCountOf(pieces[k], owner, path);
      pointsFrom = owner + " NumberOfPoints " + quoted(pieces[k]->GetAttribute("NumberOfPoints"));
      cellsFrom = owner + " cell counts (" + roundedCount(cells) + ")";
    }
    requireNoExtraValues(parser, child(pieces[k], "PointData"), points, pointsFrom, path);
    requireNoExtraValues(parser, child(pieces[k], "CellData"), cells, cellsFrom, path);
    requireNoExtraValues(parser, child(pieces[k], "Points"), points, pointsFrom, path);
    if (structured) requireNoExtraCoordinates(parser, pieces[k], owner, path);
  }
}

}  // namespace fluidviz
