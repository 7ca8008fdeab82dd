// libFuzzer target: legacy .vtk bytes -> readImageData (the size checks, VTK's vtkDataSetReader,
// the geometry checks and, for non-image datasets, vtkResampleToImage: what every fluidviz
// command does with a .vtk file) and readVectorField of "velocity".
#include "fieldviz/io/VtkXmlReaders.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  const std::filesystem::path file = fuzz::writeInputFile(data, size, ".vtk");
  fuzz::expectOnlyBadInputErrors([&] {
    readImageData(file);
    readVectorField(file, "velocity");
  });
  return 0;
}
