#include "fieldviz/io/VtkLegacyReader.h"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkType.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLReader.h>
#include <vtkXMLWriter.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/InputFile.h"
#include "fieldviz/io/VtkLegacySizeCheck.h"
#include "fieldviz/io/VtkXmlKinds.h"
#include "fieldviz/vtk/VtkMessageCollector.h"

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

void readEveryArray(vtkDataSetReader* reader) {
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllFieldsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
}

// The sanitizers' death callback belongs to the parent (libFuzzer saves the input there): a
// child that VTK crashes must not report its crash as the parent's.
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));
void detachFromSanitizerDeathCallback() {
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
}

// VTK's reader with every array, and fluidviz's checks of what it made.
vtkSmartPointer<vtkDataSet> readCheckedDataSet(const std::filesystem::path& path) {
  VtkMessageCollector messages;
  VtkUnobservedMessagesCapture capture(messages);
  vtkNew<vtkDataSetReader> reader;
  messages.watchAlgorithm(reader);
  reader->SetFileName(path.c_str());
  readEveryArray(reader);
  reader->Update();
  // Warnings too: VTK's legacy reader only warns ("Error reading ascii data. Possible mismatch
  // of datasize with declaration.") when the data stop short, and leaves the rest unset.
  if (messages.hasErrors() || !messages.warnings().empty() ||
      reader->GetErrorCode() != vtkErrorCode::NoError)
    throw FileError(path, "file " + path.string() + " is corrupt or truncated" +
                              (messages.summary().empty() ? "" : ": " + messages.summary()));
  vtkSmartPointer<vtkDataSet> data = reader->GetOutput();
  if (!data)
    throw FileError(path, "file " + path.string() +
                              " holds no dataset (a legacy VTK file of structured points, a "
                              "structured, rectilinear or unstructured grid, or poly data)");
  requireConsistentGeometry(data, path);
  requireArraysMatch(data->GetPointData(), data->GetNumberOfPoints(), "points", path);
  requireArraysMatch(data->GetCellData(), data->GetNumberOfCells(), "cells", path);
  return data;
}

void writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0 && errno != EINTR) return;
    if (n > 0) done += static_cast<std::size_t>(n);
  }
}

std::string readAll(int fd) {
  std::string bytes;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0)
      bytes.append(buffer, static_cast<std::size_t>(n));
    else if (n == 0 || errno != EINTR)
      return bytes;
  }
}

// In the child: the checked dataset as VTK XML bytes (binary, uncompressed) after
// "OK <vtk data type>\n", or the refusal as "ER\n<array>\n<message>". XML, not legacy: VTK's
// legacy writer puts array names out as they are, and its reader crashed on a name it had
// written itself (fuzzing, issue 25); XML escapes them, and its reader is hardened here.
std::string childReport(const std::filesystem::path& path) {
  try {
    vtkSmartPointer<vtkDataSet> data = readCheckedDataSet(path);
    // vtkXMLDataSetWriter would pick the writer, but does not pass WriteToOutputString on.
    const VtkXmlKind* kind = kindForVtkType(data->GetDataObjectType());
    if (!kind || !kind->makeWriter)
      return "ER\n\nfile " + path.string() + " holds a dataset type fluidviz cannot read";
    vtkSmartPointer<vtkXMLWriter> writer = kind->makeWriter();
    writer->SetInputData(data);
    writer->SetDataModeToBinary();
    writer->SetCompressorTypeToNone();
    writer->WriteToOutputStringOn();
    if (writer->Write() != 1) return "ER\n\nfile " + path.string() + " cannot be converted";
    return "OK " + std::to_string(data->GetDataObjectType()) + "\n" + writer->GetOutputString();
  } catch (const FileError& e) {
    return "ER\n" + e.arrayName() + "\n" + e.what();
  } catch (const std::exception& e) {
    return "ER\n\nfile " + path.string() + " cannot be read: " + e.what();
  }
}

// The parent's read of the child's XML, its complaints collected.
vtkSmartPointer<vtkDataSet> datasetFromChild(const std::string& report,
                                             const std::filesystem::path& path) {
  const std::size_t eol = report.find('\n');
  const int type = std::atoi(report.c_str() + 3);
  const VtkXmlKind* kind = kindForVtkType(type);
  vtkSmartPointer<vtkXMLReader> reader = kind ? kind->makeReader() : nullptr;
  auto failed = [&](const std::string& why) {
    return FileError(path, "file " + path.string() + " cannot be read: " + why);
  };
  if (!reader || eol == std::string::npos) throw failed("its reader sent no dataset");
  VtkMessageCollector messages;
  VtkUnobservedMessagesCapture capture(messages);
  messages.watchAlgorithm(reader);
  reader->ReadFromInputStringOn();
  reader->SetInputString(report.substr(eol + 1));
  reader->Update();
  auto* data = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (messages.hasErrors() || !data) throw failed(messages.summary());
  return data;
}

}  // namespace

// VTK 9.1's legacy reader dereferences null arrays, reads past cell lists and leaks on malformed
// files in more ways than checks before it can foresee (fuzzing found three in its first
// seconds, issue 15). So it reads in a child process: a crash there is an error naming the file,
// its leaks end with it, and the parent gets the dataset as VTK XML bytes (read by VTK's XML
// reader, with its messages collected) or the child's FileError. The child leaves by _exit: no exit
// handlers, no leak report of what VTK left behind.
vtkSmartPointer<vtkDataSet> readLegacyVtk(const std::filesystem::path& path) {
  requireReadableFile(path);
  checkLegacyVtkSizes(path);
  int fds[2];
  if (::pipe(fds) != 0)
    throw FileError(path, "file " + path.string() +
                              ": cannot start its reader (pipe: " + std::strerror(errno) + ")");
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw FileError(path, "file " + path.string() +
                              ": cannot start its reader (fork: " + std::strerror(errno) + ")");
  }
  if (child == 0) {
    ::close(fds[0]);
    detachFromSanitizerDeathCallback();
    writeAll(fds[1], childReport(path));
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  const std::string report = readAll(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || report.size() < 3)
    throw FileError(
        path, "file " + path.string() + " is malformed: VTK's legacy reader " +
                  (WIFSIGNALED(status)
                       ? "crashed on it (signal " + std::to_string(WTERMSIG(status)) + ")"
                       : "failed on it (exit code " + std::to_string(WEXITSTATUS(status)) + ")"));
  if (report.compare(0, 3, "ER\n") == 0) {
    const std::size_t eol = report.find('\n', 3);
    throw FileError(path, report.substr(eol + 1), report.substr(3, eol - 3));
  }
  return datasetFromChild(report, path);
}

}  // namespace fluidviz
