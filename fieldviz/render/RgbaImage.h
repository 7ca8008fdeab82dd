#pragma once
// An 8-bit RGBA picture in main memory, top row first, and writing it as PNG. No VTK here, so
// code that makes pictures without the renderer (e.g. LIC textures) can use it too.
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace fluidviz {

struct RgbaImage {
  int width = 0;   ///< pixels per row, >= 0
  int height = 0;  ///< rows, >= 0
  /// width * height * 4 bytes, R G B A per pixel, rows top first: pixel (x, y) with y counted
  /// down from the top row starts at byte 4 * (y * width + x).
  std::vector<std::uint8_t> pixels;

  std::array<std::uint8_t, 4> pixel(int x, int y) const;
};

/// Writes `image` as an 8-bit RGBA PNG through a temporary file (writeAtomically). Throws
/// std::runtime_error naming the file if the image is empty, inconsistent, or cannot be written.
void writePng(const RgbaImage& image, const std::filesystem::path& file);

}  // namespace fluidviz
