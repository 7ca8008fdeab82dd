#pragma once
// A PNG file read back into the renderer's image type, for tests that check written pictures.
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <cstdint>
#include <filesystem>

#include "fieldviz/render/RgbaImage.h"

namespace fluidviz::testing {

/// The picture in `file`, rows top first (VTK delivers the bottom row first); alpha 255 where
/// the file has no alpha channel. An unreadable file gives a 0 x 0 image.
inline RgbaImage readPngImage(const std::filesystem::path& file) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  RgbaImage image{data->GetDimensions()[0], data->GetDimensions()[1], {}};
  const int channels = data->GetNumberOfScalarComponents();
  image.pixels.reserve(std::size_t(4) * image.width * image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto* p = static_cast<const std::uint8_t*>(data->GetScalarPointer(x, image.height - 1 - y, 0));
      for (int k = 0; k < 3; ++k) image.pixels.push_back(p[channels >= 3 ? k : 0]);
      image.pixels.push_back(channels == 4 ? p[3] : 255);
    }
  return image;
}

}  // namespace fluidviz::testing
