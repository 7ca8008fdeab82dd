#pragma once
// The work of fluidviz-legacy-vtk-reader (fieldviz/io/helper), the process in which VTK's legacy
// reader runs (VtkLegacyReader.h says why): the file read by vtkDataSetReader with every array,
// checked as every fluidviz reader checks its datasets, and handed back as text.
#include <filesystem>
#include <string>

namespace fluidviz {

// "OK <vtk data type>\n" and the dataset as VTK XML bytes (binary, uncompressed), or the refusal
// as "ER\n<array>\n<message>" (a FileError's array name and message). XML, not legacy: VTK's
// legacy writer puts array names out as they are, and its reader crashed on a name it had written
// itself (fuzzing, issue 25); XML escapes them, and its reader is hardened (VtkXmlReaders.h).
std::string legacyVtkReport(const std::filesystem::path& path);

}  // namespace fluidviz
