#pragma once
// The body of the stroke-file fuzz targets (fuzz_stroke_vtp, fuzz_stroke_svg): the input bytes
// as a file of the given extension -> readStrokeFile, then each stroke's arc length and its
// resampling as the sketch filter does first. The filter's refusal of a degenerate stroke
// (std::invalid_argument) is a bad-input error of its callers, which name the file.
#include <cmath>
#include <stdexcept>

#include "filters/sketch/vtk/StrokeFiles.h"
#include "tests/fuzz/FuzzSupport.h"

namespace fluidviz::fuzz {

inline int fuzzStrokeFile(const std::uint8_t* data, std::size_t size, const char* extension) {
  const std::filesystem::path file = writeInputFile(data, size, extension);
  expectOnlyBadInputErrors([&] {
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

}  // namespace fluidviz::fuzz
