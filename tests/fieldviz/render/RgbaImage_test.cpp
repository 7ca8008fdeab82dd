// Picture files: the extension chooses the format (issue 16, defect 10: `-o x.jpg` wrote PNG
// bytes under a .jpg name).
#include "fieldviz/render/RgbaImage.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkImageData.h>
#include <vtkJPEGReader.h>
#include <vtkNew.h>

#include <cstdlib>
#include <fstream>

#include "tests/support/PngFiles.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

// Left half red, right half blue, 64 x 32.
RgbaImage twoColourImage() {
  RgbaImage image{64, 32, {}};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x)
      for (std::uint8_t c : {std::uint8_t(x < 32 ? 220 : 20), std::uint8_t(40),
                             std::uint8_t(x < 32 ? 30 : 200), std::uint8_t(255)})
        image.pixels.push_back(c);
  return image;
}

std::string firstBytes(const fs::path& file, int n) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), n);
  return bytes;
}

class PictureFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fluidviz_PictureFiles_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(PictureFiles, JpgAndJpegNamesGetJpegBytesThatReadBack) {
  for (const char* name : {"a.jpg", "b.JPEG"}) {
    writePicture(twoColourImage(), dir_ / name);
    EXPECT_EQ(firstBytes(dir_ / name, 3), "\xFF\xD8\xFF") << name;  // JPEG SOI marker
    vtkNew<vtkJPEGReader> reader;
    reader->SetFileName((dir_ / name).c_str());
    reader->Update();
    vtkImageData* d = reader->GetOutput();
    ASSERT_EQ(d->GetDimensions()[0], 64);
    ASSERT_EQ(d->GetDimensions()[1], 32);
    // Quality 95: each half's centre within 12 of its colour (JPEG is lossy).
    const auto* left = static_cast<const std::uint8_t*>(d->GetScalarPointer(16, 16, 0));
    const auto* right = static_cast<const std::uint8_t*>(d->GetScalarPointer(48, 16, 0));
    EXPECT_NEAR(left[0], 220, 12);
    EXPECT_NEAR(left[2], 30, 12);
    EXPECT_NEAR(right[0], 20, 12);
    EXPECT_NEAR(right[2], 200, 12);
  }
}

TEST_F(PictureFiles, PngNamesGetExactPngBytes) {
  writePicture(twoColourImage(), dir_ / "c.png");
  EXPECT_EQ(firstBytes(dir_ / "c.png", 4), "\x89PNG");
  EXPECT_EQ(testing::readPngImage(dir_ / "c.png").pixels, twoColourImage().pixels);
}

TEST_F(PictureFiles, OtherExtensionsAreRefusedAndWriteNothing) {
  for (const char* name : {"d.bmp", "e", "f.tiff"}) {
    try {
      writePicture(twoColourImage(), dir_ / name);
      ADD_FAILURE() << name << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(".png, .jpg or .jpeg"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir_ / name));
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace fluidviz
