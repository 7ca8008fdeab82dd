// libFuzzer target: .svg bytes -> readStrokeFile, the strokes of `fluidviz sketch STROKES.svg` and
// of lbm.sketch.file (the <svg> viewBox, every <path>'s d attribute: the commands M L H V C Z,
// absolute and relative, and data-speed), then each stroke's length and resampling as in
// fuzz_stroke_vtp.
#include <cmath>
#include <stdexcept>

#include "filters/sketch/vtk/StrokeFiles.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  const std::filesystem::path file = fuzz::writeInputFile(data, size, ".svg");
  fuzz::expectOnlyBadInputErrors([&] {
    for (const sketch::Stroke& s : sketch::readStrokeFile(file)) {
      const double length = sketch::strokeLength(s);
      if (!(length > 0.0) || !std::isfinite(length)) continue;
      try {
        sketch::resampleStroke(s, length / 1000.0);
      } catch (const std::invalid_argument&) {
      }
    }
  });
  return 0;
}
