// libFuzzer target: .vti bytes -> readVti, the field model of every usable point array (what
// `fluidviz lic/streamlines/topology/isosurface` read), and readVectorField of "velocity".
#include "fieldviz/io/VtkXmlReaders.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  const std::filesystem::path file = fuzz::writeInputFile(data, size, ".vti");
  fuzz::expectOnlyBadInputErrors([&] {
    std::vector<SkippedArray> skipped;
    const FieldSet fields = readVti(file, &skipped);
    // Arrays named "velocity" with 2 or 3 components become a vector field; others are refused.
    readVectorField(file, "velocity");
  });
  return 0;
}
