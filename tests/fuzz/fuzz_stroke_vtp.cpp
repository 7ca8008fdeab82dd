// libFuzzer target: .vtp bytes -> readStrokeFile, the strokes of `fluidviz sketch STROKES.vtp`
// and of lbm.sketch.file (readVtp + the line cells, their point indices and coordinates, and the
// cell- or point-data array "speed"), then each stroke's arc length and resampling
// (tests/fuzz/FuzzStrokeFile.h).
#include "tests/fuzz/FuzzStrokeFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fluidviz::fuzz::fuzzStrokeFile(data, size, ".vtp");
}
