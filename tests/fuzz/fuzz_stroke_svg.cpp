// libFuzzer target: .svg bytes -> readStrokeFile, the strokes of `fluidviz sketch STROKES.svg` and
// of lbm.sketch.file (the <svg> viewBox, every <path>'s d attribute: the commands M L H V C Z,
// absolute and relative, and data-speed), then each stroke's length and resampling
// (tests/fuzz/FuzzStrokeFile.h).
#include "tests/fuzz/FuzzStrokeFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fluidviz::fuzz::fuzzStrokeFile(data, size, ".svg");
}
