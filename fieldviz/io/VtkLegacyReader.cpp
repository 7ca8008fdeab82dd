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

#include "fieldviz/io/DataSetChecks.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/InputFile.h"
#include "fieldviz/io/VtkLegacySizeCheck.h"
#include "fieldviz/io/VtkXmlKinds.h"
#include "fieldviz/vtk/VtkMessageCollector.h"

namespace fluidviz {

namespace {

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
  requireConsistentDataSet(data, path);
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
