// libFuzzer target: bytes -> readImageData as each grid kind that is not a .vti: .vtr, .vts and
// .vtu (the input is the file), and .pvti, .pvtu and .vtm (the input is the summary file; the
// pieces it may name, piece.vti and piece.vtu, are fixed valid files beside it). Each read goes
// through VTK's own reader, fluidviz's header and size checks and the resampling onto an image
// (fieldviz/io/VtkXmlReaders.h); a summary naming any other file is refused by the piece checks.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <vtkAppendFilter.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

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
    const fs::path d = fs::temp_directory_path() / ("fluidviz_fuzz_grids_" + std::to_string(::getpid()));
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  for (const char* extension : {".vtr", ".vts", ".vtu", ".pvti", ".pvtu", ".vtm"}) {
    const fs::path file = folder() / (std::string("input") + extension);
    {
      std::ofstream out(file, std::ios::binary | std::ios::trunc);
      out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    fuzz::expectOnlyBadInputErrors([&] {
      readImageData(file);
      readVectorField(file, "velocity");
    });
  }
  return 0;
}
