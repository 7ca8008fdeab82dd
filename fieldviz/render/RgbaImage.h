#pragma once
// An 8-bit RGBA picture in main memory, top row first, and writing it as PNG or JPEG. No VTK here, so
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

enum class PictureFormat { png, jpeg };

/// The format a picture file's extension asks for: .png, or .jpg/.jpeg (any case). Throws
/// std::invalid_argument naming the file for any other extension.
PictureFormat pictureFormatOf(const std::filesystem::path& file);

/// Writes `image` through a temporary file (writeAtomically) in the format of its extension
/// (pictureFormatOf): 8-bit RGBA PNG, or RGB JPEG of quality 95. Throws std::invalid_argument
/// for another extension, std::runtime_error naming the file if the image is empty,
/// inconsistent, or cannot be written.
void writePicture(const RgbaImage& image, const std::filesystem::path& file);

}  // namespace fluidviz
