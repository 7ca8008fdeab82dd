#include "filters/sketch/vtk/StrokeFiles.h"

#include <cmath>
#include <map>
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

}  // namespace

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
  refuse(file, "is not a stroke file: expected .csv (stroke, x, y, speed) or .vtp (polylines)");
}

}  // namespace fluidviz::sketch
