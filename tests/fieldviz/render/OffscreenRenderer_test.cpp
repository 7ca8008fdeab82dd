// Off-screen rendering without X (DISPLAY is unset for every test): a shaded sphere against the
// camera's geometry and Lambert's law, several renderers in one process, PNG output.
#include "fieldviz/render/OffscreenRenderer.h"
#include "tests/fieldviz/render/PixelChecks.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPNGReader.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkStringOutputWindow.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>

namespace fluidviz {
namespace {

namespace fs = std::filesystem;

// Every message VTK logs during a test (errors, warnings, "GLEW could not be initialized") is
// captured and must be empty: a render that "works" while VTK complains is a failure.
class OffscreenRendererTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(std::getenv("DISPLAY"), nullptr) << "tests must run without an X display";
    previous_ = vtkOutputWindow::GetInstance();
    vtkOutputWindow::SetInstance(log_);
  }
  void TearDown() override {
    vtkOutputWindow::SetInstance(previous_);
    const std::string logged = log_->GetOutput();
    EXPECT_EQ(logged.find("GLEW could not be initialized"), std::string::npos) << logged;
    EXPECT_TRUE(logged.empty()) << "VTK logged: " << logged;
  }

 private:
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkNew<vtkStringOutputWindow> log_;
};

vtkSmartPointer<vtkActor> unitSphere(const Rgb& color) {
  vtkNew<vtkSphereSource> source;
  source->SetRadius(1.0);
  source->SetThetaResolution(180);
  source->SetPhiResolution(180);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetAmbient(0.0);
  actor->GetProperty()->SetDiffuse(1.0);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}

using fluidviz::testing::isBackground;

// Radius of the drawn disc from its area: pixels that are not background = pi r^2.
double silhouetteRadiusPx(const RgbaImage& image, const Rgb& background) {
  long covered = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) covered += !isBackground(image, x, y, background);
  return std::sqrt(covered / std::numbers::pi);
}

// Sphere of radius R at distance d seen with vertical view angle a in an H px tall window:
// silhouette half-angle asin(R/d), so radius = (H/2) tan(asin(R/d)) / tan(a/2) px.
constexpr int kSize = 400;
constexpr double kDistance = 5.0, kViewAngleDeg = 30.0;
double expectedPerspectiveRadiusPx() {
  const double halfAngle = 0.5 * kViewAngleDeg * std::numbers::pi / 180.0;
  return 0.5 * kSize * std::tan(std::asin(1.0 / kDistance)) / std::tan(halfAngle);  // 152.36
}

RgbaImage renderPerspectiveSphere(const Rgb& background) {
  OffscreenRenderer r(kSize, kSize, background);
  r.addProp(unitSphere({1.0, 1.0, 1.0}));
  vtkCamera* camera = r.camera();
  camera->SetPosition(0.0, 0.0, kDistance);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(kViewAngleDeg);
  camera->SetClippingRange(1.0, 10.0);
  return r.render();
}

TEST_F(OffscreenRendererTest, SphereSilhouetteRadiusMatchesThePerspectiveCameraWithinTwoPixels) {
  const Rgb blue{0.0, 0.0, 1.0};
  const RgbaImage image = renderPerspectiveSphere(blue);
  ASSERT_EQ(image.width, kSize);
  ASSERT_EQ(image.height, kSize);
  ASSERT_EQ(image.pixels.size(), static_cast<std::size_t>(kSize * kSize * 4));
  EXPECT_NEAR(silhouetteRadiusPx(image, blue), expectedPerspectiveRadiusPx(), 2.0);
  // The disc is centred: the centre row leaves the background at 200 -+ r.
  const int r = static_cast<int>(std::lround(expectedPerspectiveRadiusPx()));
  EXPECT_TRUE(isBackground(image, kSize / 2 - r - 3, kSize / 2, blue));
  EXPECT_FALSE(isBackground(image, kSize / 2 - r + 3, kSize / 2, blue));
  EXPECT_FALSE(isBackground(image, kSize / 2 + r - 3, kSize / 2, blue));
  EXPECT_TRUE(isBackground(image, kSize / 2 + r + 3, kSize / 2, blue));
  EXPECT_EQ(image.pixel(0, 0)[3], 255);
}

// Orthographic view, headlight along the view axis, diffuse only: a pixel at distance rho from
// the disc centre sees the normal with n_z = sqrt(1 - (rho/R)^2), so its level is 255 n_z.
TEST_F(OffscreenRendererTest, ParallelSphereFollowsLambertsLawWithinThreeLevels) {
  const Rgb black{0.0, 0.0, 0.0};
  OffscreenRenderer r(kSize, kSize, black);
  r.addProp(unitSphere({1.0, 1.0, 1.0}));
  vtkCamera* camera = r.camera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0.0, 0.0, 5.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(1.25);  // 400 px show 2.5 units: 160 px per unit
  camera->SetClippingRange(1.0, 10.0);
  const RgbaImage image = r.render();
  const double pxPerUnit = kSize / 2.5;
  for (int column : {200, 240, 280, 300, 330}) {
    const double rho = (column + 0.5 - kSize / 2.0) / pxPerUnit;
    const double expected = 255.0 * std::sqrt(1.0 - rho * rho);
    const auto p = image.pixel(column, kSize / 2);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], expected, 3.0) << "column " << column;
  }
  EXPECT_NEAR(silhouetteRadiusPx(image, black), pxPerUnit, 2.0);
}

TEST_F(OffscreenRendererTest, RenderersCreatedOneAfterAnotherEachRenderCorrectly) {
  for (int round = 0; round < 3; ++round) {
    const Rgb background{0.1 * round, 0.5, 0.0};
    const RgbaImage image = renderPerspectiveSphere(background);
    EXPECT_NEAR(silhouetteRadiusPx(image, background), expectedPerspectiveRadiusPx(), 2.0)
        << "round " << round;
    EXPECT_TRUE(isBackground(image, 1, 1, background)) << "round " << round;
  }
}

TEST_F(OffscreenRendererTest, TwoLiveRenderersKeepTheirOwnScenes) {
  const Rgb red{1.0, 0.0, 0.0}, green{0.0, 1.0, 0.0};
  OffscreenRenderer withSphere(200, 100, red);
  OffscreenRenderer empty(120, 80, green);
  withSphere.addProp(unitSphere({1.0, 1.0, 1.0}));
  withSphere.resetCamera();
  const RgbaImage a1 = withSphere.render();
  const RgbaImage b = empty.render();
  const RgbaImage a2 = withSphere.render();
  EXPECT_EQ(b.width, 120);
  EXPECT_EQ(b.height, 80);
  EXPECT_TRUE(isBackground(b, 60, 40, green));
  EXPECT_FALSE(isBackground(a1, 100, 50, red));  // sphere in the middle
  EXPECT_TRUE(isBackground(a1, 2, 2, red));
  EXPECT_EQ(a1.pixels, a2.pixels);  // rendering another context in between changes nothing
}

TEST_F(OffscreenRendererTest, SizeOutsideTheAllowedRangeThrowsNamingIt) {
  try {
    OffscreenRenderer r(0, 100);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("[1, 16384]"), std::string::npos) << e.what();
  }
}

class PngTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_png_test_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(PngTest, WritesTopRowFirstPixelsThatReadBackExactly) {
  RgbaImage image{3, 2, {}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      image.pixels.insert(image.pixels.end(), {static_cast<std::uint8_t>(40 * x),
                                               static_cast<std::uint8_t>(100 * y), 7, 255});
  const fs::path file = dir_ / "tiny.png";
  writePicture(image, file);
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkImageData* read = reader->GetOutput();
  ASSERT_EQ(read->GetDimensions()[0], 3);
  ASSERT_EQ(read->GetDimensions()[1], 2);
  ASSERT_EQ(read->GetNumberOfScalarComponents(), 4);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int k = 0; k < 4; ++k)  // VTK counts rows from the bottom
        EXPECT_EQ(read->GetScalarComponentAsDouble(x, 1 - y, 0, k), image.pixel(x, y)[k]);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1)
      << "no temporary file may remain";
}

TEST_F(PngTest, InconsistentImageThrowsNamingTheFileAndWritesNothing) {
  const fs::path file = dir_ / "bad.png";
  RgbaImage image{4, 4, std::vector<std::uint8_t>(10)};
  try {
    writePicture(image, file);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.png"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir_));
  EXPECT_THROW(writePicture(RgbaImage{1, 1, {1, 2, 3, 4}}, dir_ / "missing" / "x.png"),
               std::runtime_error);
}

}  // namespace
}  // namespace fluidviz
