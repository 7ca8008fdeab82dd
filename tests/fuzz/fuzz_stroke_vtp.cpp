// libFuzzer target: .vtp bytes -> readStrokeFile, the strokes of `fluidviz sketch STROKES.vtp`
// and of lbm.sketch.file (readVtp + the line cells, their point indices and coordinates, and the
// cell- or point-data array "speed"), then each stroke's arc length and resampling as the sketch
// filter does first (its refusal of a degenerate stroke, std::invalid_argument, is a bad-input
// error of the callers, which name the file).
#include <cmath>
#include <stdexcept>

#include "filters/sketch/vtk/StrokeFiles.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  const std::filesystem::path file = fuzz::writeInputFile(data, size, ".vtp");
  fuzz::expectOnlyBadInputErrors([&] {
    for (const sketch::Stroke& s : sketch::readStrokeFile(file)) {
      const double length = sketch::strokeLength(s);
      // Resampled at 1/1000 of its length at most (the callers bound the point count).
      if (!(length > 0.0) || !std::isfinite(length)) continue;
      try {
        sketch::resampleStroke(s, length / 1000.0);
      } catch (const std::invalid_argument&) {
      }
    }
  });
  return 0;
}
