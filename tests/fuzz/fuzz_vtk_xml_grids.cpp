// libFuzzer target: bytes -> readImageData as the grid kinds besides .vti: .vtr, .vts and .vtu
// (the input is the file), and .pvti, .pvtu and .vtm (the input is the summary file; the pieces
// it may name, piece.vti and piece.vtu, are fixed valid files beside it). Each read goes through
// VTK's own reader, fluidviz's header and size checks and the resampling onto an image
// (fieldviz/io/VtkXmlReaders.h); a summary naming any other file is refused by the piece checks.
// The input is named with the extension of the <VTKFile type> it holds (.vtu when none is
// found), so a mutated type reaches another kind's reader: one read per input instead of six
// keeps the executions per CI second six times higher.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <fstream>

#include <vtkAppendFilter.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "fieldviz/io/VtkXmlKinds.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "tests/fuzz/FuzzSupport.h"

namespace {

namespace fs = std::filesystem;

// The image the seeds' summaries describe (tools/make_vtk_seeds.py, grid_pieces()): 3 x 2 x 1
// nodes 0.5 apart with a "velocity" vector and a "density" scalar.
vtkSmartPointer<vtkImageData> pieceImage() {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(3, 2, 1);
  image->SetSpacing(0.5, 0.5, 1.0);
  vtkNew<vtkDoubleArray> velocity, density;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  density->SetName("density");
  for (vtkIdType n = 0; n < image->GetNumberOfPoints(); ++n) {
    velocity->InsertNextTuple3(0.1 * n, -0.2 * n, 0.0);
    density->InsertNextValue(1.0 + 0.01 * n);
  }
  image->GetPointData()->AddArray(velocity);
  image->GetPointData()->AddArray(density);
  return image;
}

// One folder per process, holding the fixed pieces and the input under each extension.
fs::path folder() {
  static const fs::path dir = [] {
    static const fluidviz::fuzz::ProcessScratch scratch("fluidviz_fuzz_grids");
    const fs::path d = scratch.path();
    fs::create_directories(d);
    vtkSmartPointer<vtkImageData> image = pieceImage();
    vtkNew<vtkXMLImageDataWriter> vti;
    vti->SetInputData(image);
    vti->SetFileName((d / "piece.vti").c_str());
    vti->Write();
    vtkNew<vtkAppendFilter> toUnstructured;
    toUnstructured->AddInputData(image);
    toUnstructured->Update();
    vtkNew<vtkXMLUnstructuredGridWriter> vtu;
    vtu->SetInputData(toUnstructured->GetOutput());
    vtu->SetFileName((d / "piece.vtu").c_str());
    vtu->Write();
    return d;
  }();
  return dir;
}

// The kind of the first type="..." attribute in the input's first 1 kB.
const char* extensionFor(const std::uint8_t* data, std::size_t size) {
  const std::string head(reinterpret_cast<const char*>(data), std::min<std::size_t>(size, 1024));
  const std::size_t at = head.find("type=\"");
  const std::size_t end = at == std::string::npos ? at : head.find('"', at + 6);
  if (end == std::string::npos) return ".vtu";
  const fluidviz::VtkXmlKind* kind = fluidviz::kindForFileType(head.substr(at + 6, end - at - 6));
  return kind ? kind->extension : ".vtu";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  const fs::path file = folder() / (std::string("input") + extensionFor(data, size));
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  fuzz::expectOnlyBadInputErrors([&] {
    readImageData(file);
    readVectorField(file, "velocity");
  });
  return 0;
}
