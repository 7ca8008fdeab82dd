#include "fieldviz/io/DataSetChecks.h"

#include <functional>
#include <string>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>

#include "fieldviz/io/FileError.h"

namespace fluidviz {

namespace {

// VTK's reader takes the arrays' lengths from POINT_DATA / CELL_DATA, not from the geometry:
// an array that does not match would be read past its end by every filter after it.
void requireArraysMatch(vtkFieldData* arrays, vtkIdType expected, const char* what,
                        const std::filesystem::path& path) {
  for (int i = 0; i < arrays->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* a = arrays->GetAbstractArray(i);
    if (a->GetNumberOfTuples() == expected) continue;
    const std::string name = a->GetName() ? a->GetName() : "(unnamed)";
    throw FileError(path,
                    "file " + path.string() + ": array '" + name + "' has " +
                        std::to_string(a->GetNumberOfTuples()) + " values, but the dataset has " +
                        std::to_string(expected) + " " + what,
                    name);
  }
}

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& why) {
  throw FileError(path, "file " + path.string() + ": " + why);
}

// Points per cell of the linear cell types fluidviz accepts (VTK's vtkCellType.h); -k: at least
// k points (poly vertex, poly line, polygon, triangle strip). Others (quadratic, polyhedra) are
// refused: VTK's filters trust the connectivity of a cell's type blindly.
int pointsOfCellType(int type) {
  switch (type) {
    case VTK_VERTEX:
      return 1;
    case VTK_POLY_VERTEX:
      return -1;
    case VTK_LINE:
      return 2;
    case VTK_POLY_LINE:
      return -2;
    case VTK_TRIANGLE:
      return 3;
    case VTK_TRIANGLE_STRIP:
      return -3;
    case VTK_POLYGON:
      return -3;
    case VTK_PIXEL:
    case VTK_QUAD:
    case VTK_TETRA:
      return 4;
    case VTK_VOXEL:
    case VTK_HEXAHEDRON:
      return 8;
    case VTK_WEDGE:
      return 6;
    case VTK_PYRAMID:
      return 5;
    default:
      return 0;
  }
}

// The offsets of a cell array (read from a version-5 file's OFFSETS) start at 0, never
// decrease and end at the connectivity's length; else traversing the cells reads outside it.
void requireConsistentOffsets(vtkCellArray* cells, const char* what,
                              const std::filesystem::path& path) {
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  if (!offsets || !connectivity || offsets->GetNumberOfTuples() == 0) return;
  const vtkIdType n = offsets->GetNumberOfTuples();
  double previous = 0;
  for (vtkIdType i = 0; i < n; ++i) {
    const double o = offsets->GetComponent(i, 0);
    if ((i == 0 && o != 0) || o < previous)
      refuse(path, std::string("the OFFSETS of the ") + what +
                       "s are not 0, then non-decreasing (" + "offset " + std::to_string(i) +
                       " is " + std::to_string(o) + ")");
    previous = o;
  }
  if (previous != double(connectivity->GetNumberOfTuples()))
    refuse(path, std::string("the OFFSETS of the ") + what + "s end at " +
                     std::to_string(previous) + ", the CONNECTIVITY has " +
                     std::to_string(connectivity->GetNumberOfTuples()) + " ids");
}

// Every point id of `cells` names a point, and (when the type is known) each cell has the
// points its type needs. The legacy reader checks neither.
void requireValidCells(vtkCellArray* cells, vtkIdType points,
                       const std::function<int(vtkIdType)>& typeOf, const char* what,
                       const std::filesystem::path& path) {
  if (!cells) return;
  requireConsistentOffsets(cells, what, path);
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  vtkIdType cell = 0;
  for (cells->InitTraversal(); cells->GetNextCell(npts, ids); ++cell) {
    const int type = typeOf(cell);
    const int need = pointsOfCellType(type);
    if (need == 0)
      refuse(path, std::string(what) + " " + std::to_string(cell) + " has cell type " +
                       std::to_string(type) + "; readable: the linear VTK cell types (1-12, 14)");
    if ((need > 0 && npts != need) || (need < 0 && npts < -need))
      refuse(path, std::string(what) + " " + std::to_string(cell) + " (type " +
                       std::to_string(type) + ") has " + std::to_string(npts) + " points, needs " +
                       (need > 0 ? "" : "at least ") + std::to_string(need > 0 ? need : -need));
    for (vtkIdType k = 0; k < npts; ++k)
      if (ids[k] < 0 || ids[k] >= points)
        refuse(path, std::string(what) + " " + std::to_string(cell) + " names point " +
                         std::to_string(ids[k]) + ", outside [0, " + std::to_string(points - 1) +
                         "]");
  }
}

// What the geometry declares must be what was read: the legacy reader keeps a short POINTS or
// X_COORDINATES list without complaint, and cells naming points that do not exist.
void requireConsistentGeometry(vtkDataSet* data, const std::filesystem::path& path) {
  const vtkIdType points = data->GetNumberOfPoints();
  if (auto* grid = vtkStructuredGrid::SafeDownCast(data)) {
    int dims[3];
    grid->GetDimensions(dims);
    const long long declared = (long long)dims[0] * dims[1] * dims[2];
    const long long read = grid->GetPoints() ? grid->GetPoints()->GetNumberOfPoints() : 0;
    if (declared != read)
      refuse(path, "DIMENSIONS " + std::to_string(dims[0]) + " " + std::to_string(dims[1]) + " " +
                       std::to_string(dims[2]) + " need " + std::to_string(declared) +
                       " points, POINTS has " + std::to_string(read));
  } else if (auto* rect = vtkRectilinearGrid::SafeDownCast(data)) {
    int dims[3];
    rect->GetDimensions(dims);
    vtkDataArray* coords[3] = {rect->GetXCoordinates(), rect->GetYCoordinates(),
                               rect->GetZCoordinates()};
    const char* names[3] = {"X_COORDINATES", "Y_COORDINATES", "Z_COORDINATES"};
    for (int a = 0; a < 3; ++a)
      if (!coords[a] || coords[a]->GetNumberOfTuples() != dims[a])
        refuse(path, std::string(names[a]) + " has " +
                         std::to_string(coords[a] ? coords[a]->GetNumberOfTuples() : 0) +
                         " values, DIMENSIONS says " + std::to_string(dims[a]));
  } else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data)) {
    vtkDataArray* types = grid->GetCellTypesArray();
    const vtkIdType cells = grid->GetCells() ? grid->GetCells()->GetNumberOfCells() : 0;
    if (cells > 0 && (!types || types->GetNumberOfTuples() != cells))
      refuse(path, "CELL_TYPES has " + std::to_string(types ? types->GetNumberOfTuples() : 0) +
                       " types for " + std::to_string(cells) + " cells");
    requireValidCells(
        grid->GetCells(), points, [grid](vtkIdType c) { return grid->GetCellType(c); }, "cell",
        path);
  } else if (auto* poly = vtkPolyData::SafeDownCast(data)) {
    requireValidCells(
        poly->GetVerts(), points, [](vtkIdType) { return VTK_POLY_VERTEX; }, "vertex cell", path);
    requireValidCells(
        poly->GetLines(), points, [](vtkIdType) { return VTK_POLY_LINE; }, "line", path);
    requireValidCells(
        poly->GetPolys(), points, [](vtkIdType) { return VTK_POLYGON; }, "polygon", path);
    requireValidCells(
        poly->GetStrips(), points, [](vtkIdType) { return VTK_TRIANGLE_STRIP; }, "triangle strip",
        path);
  }
}

}  // namespace

void requireConsistentDataSet(vtkDataSet* data, const std::filesystem::path& path) {
  requireConsistentGeometry(data, path);
  requireArraysMatch(data->GetPointData(), data->GetNumberOfPoints(), "points", path);
  requireArraysMatch(data->GetCellData(), data->GetNumberOfCells(), "cells", path);
}

}  // namespace fluidviz
