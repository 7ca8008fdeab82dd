#pragma once
// The VTK XML file kinds fluidviz reads, one table: extension, the <VTKFile type> it must hold,
// VTK's dataset type, the type of the pieces a summary file (.pvti, .pvtu, .vtm) names, and VTK's
// reader and writer of the kind. The dispatch by extension (VtkXmlReaders.cpp) and the legacy
// reader's XML hand-over (VtkLegacyReader.cpp) both look kinds up here.
#include <string>

#include <vtkSmartPointer.h>

class vtkXMLReader;
class vtkXMLWriter;

namespace fluidviz {

struct VtkXmlKind {
  const char* extension;  ///< ".vtr"
  const char* fileType;   ///< the <VTKFile type="..."> attribute, "RectilinearGrid"
  int vtkType;            ///< VTK_RECTILINEAR_GRID; -1 for a summary file
  /// Summary files: the fileType every piece must have ("" for .vtm: any serial kind);
  /// nullptr for a file that holds its data itself.
  const char* pieceType;
  vtkSmartPointer<vtkXMLReader> (*makeReader)();
  vtkSmartPointer<vtkXMLWriter> (*makeWriter)();  ///< nullptr for summary files
  bool isSummary() const { return pieceType != nullptr; }
};

/// nullptr when no kind has this extension (".vtu"), file type ("UnstructuredGrid") or VTK
/// dataset type (VTK_STRUCTURED_POINTS is an image).
const VtkXmlKind* kindForExtension(const std::string& extension);
const VtkXmlKind* kindForFileType(const std::string& fileType);
const VtkXmlKind* kindForVtkType(int vtkType);

}  // namespace fluidviz
