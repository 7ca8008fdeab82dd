#include "filters/sketch/vtk/StrokeFiles.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "fieldviz/core/Params.h"
#include "fieldviz/io/CsvTable.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlReaders.h"

namespace fluidviz::sketch {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const fs::path& file, const std::string& what,
                         const std::string& array = {}) {
  throw FileError(file, file.string() + ": " + what, array);
}

/// The value in row `row` of `column`, refused unless finite (CsvTable reads "nan").
double finiteCsvValue(const CsvTable& t, const fs::path& file, const std::string& column,
                      std::size_t row) {
  const double v = t.column(column, file)[row];
  if (!std::isfinite(v))
    refuse(file, "data row " + std::to_string(row + 1) + ": " + column + " is " +
                     formatNumber(v) + "; expected a finite number");
  return v;
}

/// The 1-component array "speed" of cell or point data; nullptr if there is none.
vtkDataArray* speedArray(vtkFieldData* data, const fs::path& file, const char* where,
                         vtkIdType tuples) {
  vtkAbstractArray* any = data->GetAbstractArray("speed");
  if (any == nullptr) return nullptr;
  vtkDataArray* a = vtkDataArray::SafeDownCast(any);
  if (a == nullptr || a->GetNumberOfComponents() != 1)
    refuse(file, std::string(where) + " array 'speed' must be numeric with 1 component (m/s)",
           "speed");
  if (a->GetNumberOfTuples() != tuples)
    refuse(file, std::string(where) + " array 'speed' has " +
                     std::to_string(a->GetNumberOfTuples()) + " values for " +
                     std::to_string(tuples) + (std::string(where) == "cell-data" ? " cells" : " points"),
           "speed");
  return a;
}

double finiteSpeed(vtkDataArray* a, vtkIdType i, const fs::path& file, const std::string& where) {
  const double v = a->GetComponent(i, 0);
  if (!std::isfinite(v))
    refuse(file, where + ": speed is " + formatNumber(v) + "; expected a finite number (m/s)",
           "speed");
  return v;
}

/// The text of an .svg file (at most 4 MB: a drawing, not a data set; every 12 bytes of it may
/// become a cubic of kSvgCurveSegments points).
std::string svgText(const fs::path& file) {
  constexpr std::uintmax_t kMaxBytes = 4u << 20;
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) refuse(file, "cannot be read (" + ec.message() + ")");
  if (size > kMaxBytes)
    refuse(file, "is " + std::to_string(size) + " bytes; an .svg stroke file may have at most " +
                     std::to_string(kMaxBytes));
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) refuse(file, "cannot be read");
  return text;
}

/// The value of attribute `name` inside the tag text `tag` ("<path ... >"); nullopt if absent.
std::optional<std::string> svgAttribute(const std::string& tag, const std::string& name) {
  for (std::size_t at = tag.find(name); at != std::string::npos; at = tag.find(name, at + 1)) {
    const bool starts = at > 0 && std::isspace(static_cast<unsigned char>(tag[at - 1]));
    std::size_t k = at + name.size();
    while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
    if (!starts || k >= tag.size() || tag[k] != '=') continue;
    ++k;
    while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
    if (k >= tag.size() || (tag[k] != '"' && tag[k] != '\'')) continue;
    const std::size_t end = tag.find(tag[k], k + 1);
    if (end == std::string::npos) return std::nullopt;
    return tag.substr(k + 1, end - k - 1);
  }
  return std::nullopt;
}

/// Reads the numbers and command letters of an SVG path's d attribute.
class SvgPathReader {
 public:
  SvgPathReader(const std::string& d, const fs::path& file, std::string where)
      : d_(d), file_(file), where_(std::move(where)) {}

  /// The next command letter, or 0 at the end; a number where a command is due repeats `last`.
  char command(char last) {
    skipSeparators();
    if (k_ >= d_.size()) return 0;
    const char c = d_[k_];
    if (std::isalpha(static_cast<unsigned char>(c))) {
      ++k_;
      return c;
    }
    if (last == 0 || last == 'Z' || last == 'z')
      refuse(file_, where_ + ": a number where a path command is due (at character " +
                        std::to_string(k_ + 1) + ")");
    return last == 'M' ? 'L' : last == 'm' ? 'l' : last;  // implicit lineto after moveto
  }
  double number() {
    skipSeparators();
    const char* begin = d_.c_str() + k_;
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    if (end == begin)
      refuse(file_, where_ + ": expected a number at character " + std::to_string(k_ + 1));
    if (!std::isfinite(v))
      refuse(file_, where_ + ": the number at character " + std::to_string(k_ + 1) +
                        " is not finite");
    k_ += static_cast<std::size_t>(end - begin);
    return v;
  }

 private:
  void skipSeparators() {
    while (k_ < d_.size() && (std::isspace(static_cast<unsigned char>(d_[k_])) || d_[k_] == ','))
      ++k_;
  }
  const std::string& d_;
  const fs::path& file_;
  std::string where_;
  std::size_t k_ = 0;
};

/// Point of the cubic Bezier p0 p1 p2 p3 at parameter t.
Vec3 cubicBezier(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double t) {
  const double s = 1.0 - t;
  return s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3;
}

/// The strokes of one path's d attribute, in SVG user units (y down).
std::vector<Stroke> svgPathStrokes(const std::string& d, double speed, const fs::path& file,
                                   const std::string& where) {
  SvgPathReader in(d, file, where);
  std::vector<Stroke> strokes;
  Vec3 at(0, 0, 0), start(0, 0, 0);
  char last = 0;
  for (char c = in.command(0); c != 0; c = in.command(last)) {
    const bool relative = std::islower(static_cast<unsigned char>(c));
    const Vec3 origin = relative ? at : Vec3(0, 0, 0);
    auto point = [&] {
      const double x = in.number();
      const double y = in.number();
      return Vec3(origin[0] + x, origin[1] + y, 0.0);
    };
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper != 'M' && strokes.empty())
      refuse(file, where + ": the path data does not start with a moveto (M or m)");
    switch (upper) {
      case 'M':
        at = start = point();
        strokes.push_back({{at}, speed});
        break;
      case 'L':
        at = point();
        break;
      case 'H':
        at = Vec3(origin[0] + in.number(), at[1], 0.0);
        break;
      case 'V':
        at = Vec3(at[0], origin[1] + in.number(), 0.0);
        break;
      case 'C': {
        const Vec3 p0 = at, p1 = point(), p2 = point(), p3 = point();
        for (int k = 1; k < kSvgCurveSegments; ++k)
          strokes.back().points.push_back(
              cubicBezier(p0, p1, p2, p3, static_cast<double>(k) / kSvgCurveSegments));
        at = p3;
        break;
      }
      case 'Z':
        at = start;
        break;
      default:
        refuse(file, where + ": path command '" + std::string(1, c) +
                         "' is not supported (M, L, H, V, C and Z are; convert other curves to "
                         "cubic Beziers, e.g. Inkscape: Path > Object to Path)");
    }
    if (upper != 'M') strokes.back().points.push_back(at);
    last = c;
  }
  return strokes;
}

}  // namespace

std::vector<Stroke> readStrokesSvg(const fs::path& file) {
  const std::string text = svgText(file);
  if (text.find("<svg") == std::string::npos) refuse(file, "is not an SVG file (no <svg> element)");
  if (svgAttribute(text, "transform"))
    refuse(file, "has a transform attribute, which is not supported: apply the transforms to the "
                 "paths first (e.g. Inkscape: Path > Object to Path, then ungroup)");
  const std::size_t svgAt = text.find("<svg");
  const std::string svgTag = text.substr(svgAt, text.find('>', svgAt) - svgAt);
  const std::optional<std::string> viewBox = svgAttribute(svgTag, "viewBox");
  if (!viewBox)
    refuse(file, "has no viewBox on its <svg> element: it gives the drawing's extent (1 user "
                 "unit = 1 m), within which y is flipped");
  std::istringstream box(*viewBox);
  double minX = 0, minY = 0, width = 0, height = 0;
  char comma = 0;
  for (double* v : {&minX, &minY, &width, &height}) {
    if (box.peek() == ',') box >> comma;
    box >> *v;
  }
  if (!box || !std::isfinite(minY) || !std::isfinite(height) || !(height > 0) || !(width > 0))
    refuse(file, "viewBox \"" + *viewBox + "\" is not four numbers min-x min-y width height with "
                 "width and height > 0");
  std::vector<Stroke> strokes;
  std::size_t paths = 0;
  for (std::size_t at = text.find("<path"); at != std::string::npos;
       at = text.find("<path", at + 1)) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) refuse(file, "a <path> element is not closed");
    const std::string tag = text.substr(at, end - at);
    const std::string where = "path " + std::to_string(++paths);
    const std::optional<std::string> d = svgAttribute(tag, "d");
    if (!d) continue;
    double speed = kDefaultStrokeSpeed;
    if (const std::optional<std::string> s = svgAttribute(tag, "data-speed")) {
      char* stop = nullptr;
      speed = std::strtod(s->c_str(), &stop);
      if (stop == s->c_str() || *stop != '\0' || !std::isfinite(speed))
        refuse(file, where + ": data-speed \"" + *s + "\" is not a finite number (m/s)");
    }
    for (Stroke& stroke : svgPathStrokes(*d, speed, file, where)) {
      for (Vec3& p : stroke.points) {
        p[1] = 2.0 * minY + height - p[1];  // y up, within the viewBox
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
          refuse(file, where + ": a point is not finite");
      }
      strokes.push_back(std::move(stroke));
    }
  }
  if (strokes.empty()) refuse(file, "has no <path> with path data (d attribute)");
  return strokes;
}

std::vector<Stroke> readStrokesCsv(const fs::path& file) {
  const CsvTable t = readCsv(file);
  for (const char* c : {"stroke", "x", "y", "speed"}) t.column(c, file);  // names missing ones
  if (t.rowCount() == 0) refuse(file, "has no stroke points (only a header)");
  std::vector<Stroke> strokes;
  std::map<double, std::size_t> seen;  // stroke number -> index in strokes
  for (std::size_t row = 0; row < t.rowCount(); ++row) {
    const std::string where = "data row " + std::to_string(row + 1) + ": ";
    const double id = finiteCsvValue(t, file, "stroke", row);
    if (id != std::floor(id))
      refuse(file, where + "stroke is " + formatNumber(id) + "; expected a whole number");
    const double speed = finiteCsvValue(t, file, "speed", row);
    const Vec3 p(finiteCsvValue(t, file, "x", row), finiteCsvValue(t, file, "y", row), 0.0);
    const bool continues = !strokes.empty() && row > 0 && t.column("stroke", file)[row - 1] == id;
    if (!continues) {
      if (seen.count(id))
        refuse(file, where + "stroke " + formatNumber(id) +
                         " comes back after another stroke; the points of a stroke must be on "
                         "consecutive lines");
      seen[id] = strokes.size();
      strokes.push_back({{}, speed});
    } else if (speed != strokes.back().speed) {
      refuse(file, where + "speed " + formatNumber(speed) + " differs from the stroke's " +
                       formatNumber(strokes.back().speed) +
                       " on its first line; a stroke has one speed");
    }
    strokes.back().points.push_back(p);
  }
  return strokes;
}

std::vector<Stroke> readStrokesVtp(const fs::path& file) {
  vtkSmartPointer<vtkPolyData> poly = readVtp(file);
  const vtkIdType points = poly->GetNumberOfPoints();
  vtkCellArray* lines = poly->GetLines();
  const vtkIdType lineCount = lines ? lines->GetNumberOfCells() : 0;
  if (lineCount == 0)
    refuse(file, "has no polylines (line cells); each line is one stroke, e.g. drawn in "
                 "ParaView with the Polyline source");
  // Cell data is numbered over verts, then lines, then polys and strips: the lines follow the
  // vertices.
  const vtkIdType verts = poly->GetVerts() ? poly->GetVerts()->GetNumberOfCells() : 0;
  vtkDataArray* cellSpeed =
      speedArray(poly->GetCellData(), file, "cell-data", poly->GetNumberOfCells());
  vtkDataArray* pointSpeed =
      cellSpeed ? nullptr : speedArray(poly->GetPointData(), file, "point-data", points);
  std::vector<Stroke> strokes;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < lineCount; ++c) {
    const std::string where = "line " + std::to_string(c + 1);
    lines->GetCellAtId(c, ids);
    Stroke s;
    s.speed = cellSpeed ? finiteSpeed(cellSpeed, verts + c, file, where) : kDefaultStrokeSpeed;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      const vtkIdType id = ids->GetId(k);
      if (id < 0 || id >= points)
        refuse(file, where + ": point index " + std::to_string(id) + " outside the " +
                         std::to_string(points) + " points");
      double x[3];
      poly->GetPoint(id, x);
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]))
        refuse(file, where + ": point " + std::to_string(id) + " is (" + formatNumber(x[0]) +
                         ", " + formatNumber(x[1]) + "); expected finite coordinates (m)");
      s.points.emplace_back(x[0], x[1], 0.0);
      if (pointSpeed) {
        const double v = finiteSpeed(pointSpeed, id, file, where + ", point " + std::to_string(id));
        if (k == 0) s.speed = v;
        else if (v != s.speed)
          refuse(file, where + ": point-data speed " + formatNumber(v) + " at point " +
                           std::to_string(id) + " differs from " + formatNumber(s.speed) +
                           " at the line's first point; a stroke has one speed (or give a "
                           "cell-data array 'speed')",
                 "speed");
      }
    }
    strokes.push_back(std::move(s));
  }
  return strokes;
}

std::vector<Stroke> readStrokeFile(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".csv") return readStrokesCsv(file);
  if (ext == ".vtp") return readStrokesVtp(file);
  if (ext == ".svg") return readStrokesSvg(file);
  refuse(file, "is not a stroke file: expected .csv (stroke, x, y, speed), .vtp (polylines) or "
               ".svg (paths)");
}

}  // namespace fluidviz::sketch
