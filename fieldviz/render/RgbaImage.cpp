#include "fieldviz/render/RgbaImage.h"

#include <vtkCommand.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkImageExtractComponents.h>
#include <vtkJPEGWriter.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <cctype>
#include <cstring>
#include <stdexcept>
#include <string>

#include "fieldviz/core/AtomicFile.h"

namespace fluidviz {

std::array<std::uint8_t, 4> RgbaImage::pixel(int x, int y) const {
  if (x < 0 || x >= width || y < 0 || y >= height)
    throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                            ") is outside the " + std::to_string(width) + " x " +
                            std::to_string(height) + " image");
  const std::uint8_t* p = pixels.data() + 4 * (static_cast<std::size_t>(y) * width + x);
  return {p[0], p[1], p[2], p[3]};
}

namespace {

// vtkImageData counts rows from the bottom, the picture from the top.
vtkSmartPointer<vtkImageData> toVtkImage(const RgbaImage& image) {
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* out = static_cast<std::uint8_t*>(data->GetScalarPointer());
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y)
    std::memcpy(out + (image.height - 1 - y) * rowBytes, image.pixels.data() + y * rowBytes,
                rowBytes);
  return data;
}

// Keeps VTK's error messages for our exception instead of letting VTK print them.
struct ErrorCollector {
  std::string messages;
  void onError(vtkObject*, unsigned long, void* message) {
    if (!messages.empty()) messages += "; ";
    messages += message ? static_cast<const char*>(message) : "(no message)";
  }
};

}  // namespace

PictureFormat pictureFormatOf(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".png") return PictureFormat::png;
  if (ext == ".jpg" || ext == ".jpeg") return PictureFormat::jpeg;
  throw std::invalid_argument("cannot write " + file.string() + ": a picture file ends in .png, "
                              ".jpg or .jpeg (its extension chooses the format)");
}

void writePicture(const RgbaImage& image, const std::filesystem::path& file) {
  const PictureFormat format = pictureFormatOf(file);
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw std::runtime_error("cannot write " + file.string() + ": the image is " +
                             std::to_string(image.width) + " x " + std::to_string(image.height) +
                             " px with " + std::to_string(image.pixels.size()) +
                             " bytes; need a non-empty image with 4 bytes per pixel");
  vtkSmartPointer<vtkImageData> data = toVtkImage(image);
  writeAtomically(file, [&](const std::filesystem::path& tmp) {
    ErrorCollector errors;
    vtkSmartPointer<vtkImageWriter> writer;
    if (format == PictureFormat::png) {
      writer = vtkSmartPointer<vtkPNGWriter>::New();
      writer->SetInputData(data);
    } else {
      // JPEG has no alpha: the RGB channels (pictures are opaque), quality 95 of 100.
      auto jpeg = vtkSmartPointer<vtkJPEGWriter>::New();
      jpeg->SetQuality(95);
      vtkNew<vtkImageExtractComponents> rgb;
      rgb->SetInputData(data);
      rgb->SetComponents(0, 1, 2);
      rgb->Update();
      jpeg->SetInputData(rgb->GetOutput());
      writer = jpeg;
    }
    writer->AddObserver(vtkCommand::ErrorEvent, &errors, &ErrorCollector::onError);
    writer->SetFileName(tmp.string().c_str());
    writer->Write();
    if (writer->GetErrorCode() != 0 || !errors.messages.empty())
      throw std::runtime_error(
          "cannot write " + file.string() + ": the " +
          (format == PictureFormat::png ? "PNG" : "JPEG") + " writer failed (" +
          std::string(vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode())) +
          "): " + errors.messages);
  });
}

}  // namespace fluidviz
