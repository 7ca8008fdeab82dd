// libFuzzer target: .vtp bytes -> readParticleVtp, the particle set `fluidviz resample` reads
// (readVtp + positions and every 1-3 component point array).
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  const std::filesystem::path file = fuzz::writeInputFile(data, size, ".vtp");
  fuzz::expectOnlyBadInputErrors([&] {
    std::vector<SkippedArray> skipped;
    resample::readParticleVtp(file, &skipped);
  });
  return 0;
}
