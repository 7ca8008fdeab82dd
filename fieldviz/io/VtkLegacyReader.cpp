#include "fieldviz/io/VtkLegacyReader.h"

#include <sys/wait.h>
#include <unistd.h>
#include <vtkDataSet.h>
#include <vtkXMLReader.h>

#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "fieldviz/core/ChildProcess.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/InputFile.h"
#include "fieldviz/io/VtkLegacySizeCheck.h"
#include "fieldviz/io/VtkXmlKinds.h"
#include "fieldviz/vtk/VtkMessageCollector.h"

namespace fluidviz {

namespace {

namespace fs = std::filesystem;

constexpr const char* kHelperName = "fluidviz-legacy-vtk-reader";

// Where the helper is: in <libexec>/fluidviz/ (FLUIDVIZ_HELPER_DIR) of one of the three folders
// above the running program (<prefix>/bin/fluidviz -> <prefix>; build/apps/fluidviz/fluidviz
// and build/tests/test_x -> build), else in the install prefix's.
std::vector<fs::path> helperCandidates() {
  std::vector<fs::path> candidates;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path above = self.parent_path();
    for (int level = 0; level < 3 && above.has_relative_path(); ++level) {
      above = above.parent_path();
      candidates.push_back(above / FLUIDVIZ_HELPER_DIR / kHelperName);
    }
  }
  candidates.push_back(fs::path(FLUIDVIZ_HELPER_INSTALL_DIR) / kHelperName);
  return candidates;
}

fs::path legacyReaderHelper(const fs::path& file) {
  std::string looked;
  for (const fs::path& candidate : helperCandidates()) {
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    looked += (looked.empty() ? "" : ", ") + candidate.lexically_normal().string();
  }
  throw FileError(file, "file " + file.string() + ": cannot start its reader: " + kHelperName +
                            " is missing (looked for " + looked +
                            "); build or install fluidviz again");
}

// The helper's XML read by VTK's XML reader, its complaints collected.
vtkSmartPointer<vtkDataSet> datasetFromReport(const std::string& report,
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
// seconds, issue 15). So it reads in another process, fluidviz-legacy-vtk-reader
// (VtkLegacyReport.h): a crash there is an error naming the file, its leaks end with it, and this
// process gets the dataset as VTK XML bytes (read by VTK's XML reader, its messages collected)
// or the helper's FileError. A program started by posix_spawn, not a fork of this one: a fork of
// a process with threads (OpenMP's, Mesa's) can inherit a lock held by another thread and wait
// for it forever (core/ChildProcess.h); one did, in a sanitizer build's test.
vtkSmartPointer<vtkDataSet> readLegacyVtk(const std::filesystem::path& path) {
  requireReadableFile(path);
  checkLegacyVtkSizes(path);
  const fs::path helper = legacyReaderHelper(path);
  std::string report;
  ChildProcessResult child;
  try {
    child = runChildProcess({helper.string(), path.string()},
                            [&](std::string_view piece) { report.append(piece); });
  } catch (const std::exception& e) {
    throw FileError(path, "file " + path.string() + ": cannot start its reader: " + e.what());
  }
  if (!exitedWithZero(child.status) || report.size() < 3)
    throw FileError(path, "file " + path.string() + " is malformed: VTK's legacy reader " +
                              (WIFSIGNALED(child.status) ? "crashed on it (" : "failed on it (") +
                              exitDescription(child.status) + ")");
  if (report.compare(0, 3, "ER\n") == 0) {
    const std::size_t eol = report.find('\n', 3);
    throw FileError(path, report.substr(eol + 1), report.substr(3, eol - 3));
  }
  return datasetFromReport(report, path);
}

}  // namespace fluidviz
