#include "fieldviz/io/VtkXmlKinds.h"

#include <array>

#include <vtkType.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPImageDataReader.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLRectilinearGridReader.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace fluidviz {

namespace {

template <class R>
vtkSmartPointer<vtkXMLReader> make() {
  return vtkSmartPointer<R>::New();
}
template <class W>
vtkSmartPointer<vtkXMLWriter> makeWriter() {
  return vtkSmartPointer<W>::New();
}

const std::array<VtkXmlKind, 8> kKinds = {{
    {".vti", "ImageData", VTK_IMAGE_DATA, nullptr, make<vtkXMLImageDataReader>,
     makeWriter<vtkXMLImageDataWriter>},
    {".vtr", "RectilinearGrid", VTK_RECTILINEAR_GRID, nullptr, make<vtkXMLRectilinearGridReader>,
     makeWriter<vtkXMLRectilinearGridWriter>},
    {".vts", "StructuredGrid", VTK_STRUCTURED_GRID, nullptr, make<vtkXMLStructuredGridReader>,
     makeWriter<vtkXMLStructuredGridWriter>},
    {".vtu", "UnstructuredGrid", VTK_UNSTRUCTURED_GRID, nullptr,
     make<vtkXMLUnstructuredGridReader>, makeWriter<vtkXMLUnstructuredGridWriter>},
    {".vtp", "PolyData", VTK_POLY_DATA, nullptr, make<vtkXMLPolyDataReader>,
     makeWriter<vtkXMLPolyDataWriter>},
    {".pvti", "PImageData", -1, "ImageData", make<vtkXMLPImageDataReader>, nullptr},
    {".pvtu", "PUnstructuredGrid", -1, "UnstructuredGrid", make<vtkXMLPUnstructuredGridReader>,
     nullptr},
    {".vtm", "vtkMultiBlockDataSet", -1, "", make<vtkXMLMultiBlockDataReader>, nullptr},
}};

}  // namespace

const VtkXmlKind* kindForExtension(const std::string& extension) {
  for (const VtkXmlKind& k : kKinds)
    if (extension == k.extension) return &k;
  return nullptr;
}

const VtkXmlKind* kindForFileType(const std::string& fileType) {
  for (const VtkXmlKind& k : kKinds)
    if (fileType == k.fileType) return &k;
  return nullptr;
}

const VtkXmlKind* kindForVtkType(int vtkType) {
  if (vtkType == VTK_STRUCTURED_POINTS) vtkType = VTK_IMAGE_DATA;
  for (const VtkXmlKind& k : kKinds)
    if (k.vtkType == vtkType) return &k;
  return nullptr;
}

}  // namespace fluidviz
