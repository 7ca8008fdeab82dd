// 3D pictures without X (DISPLAY unset): camera framing against the projection of a sphere,
// azimuth convention, zoom, background and colour-map colours, particles as spheres and
// sprites, volume rendering (GPU ray casting under OSMesa, and the CPU mapper), turntables.
//
// Framing (View3D.cpp): the bounding sphere of the data, radius rho, fits the narrower field of
// view (half angle a) from distance d = rho / sin(a) / zoom. A sphere of radius R at the centre
// then appears as a disc of radius (H / 2) tan(asin(R / d)) / tan(view_angle / 2) px, H being
// the picture height. For R = 1 (bounds [-1, 1]^3, rho = sqrt 3), 400 x 300 px, view angle 30:
// a = 15 deg (vertical), d = 6.692, disc radius 84.60 px (measured 84.64); at zoom 1.5,
// 128.75 px (measured 128.77). Particle sphere mesh: 84.44 px, sprite: 83.68 px.
#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkSphereSource.h>
#include <vtkStringOutputWindow.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>

#include "fieldviz/core/Grid.h"
#include "fieldviz/render/ColorMap.h"
#include "fieldviz/render/ParticleRendering.h"
#include "fieldviz/render/SurfaceRendering.h"
#include "fieldviz/render/View3D.h"
#include "fieldviz/render/VolumeRendering.h"
#include "tests/fieldviz/render/PixelChecks.h"

using namespace fluidviz;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = std::numbers::pi;

// Every message VTK logs during a test must be empty: a render that "works" while VTK complains
// is a failure.
class View3DTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(std::getenv("DISPLAY"), nullptr) << "tests must run without an X display";
    previous_ = vtkOutputWindow::GetInstance();
    vtkOutputWindow::SetInstance(log_);
  }
  void TearDown() override {
    vtkOutputWindow::SetInstance(previous_);
    EXPECT_EQ(std::string(log_->GetOutput()), "") << "VTK logged messages";
  }

 private:
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkNew<vtkStringOutputWindow> log_;
};

View3DParams plainView(int width = 400, int height = 300) {
  View3DParams v;
  v.width = width;
  v.height = height;
  v.outline = false;
  v.scalar_bar = false;
  v.multisamples = 0;
  v.camera.azimuth = 0.0;
  v.camera.elevation = 0.0;
  return v;
}

vtkSmartPointer<vtkPolyData> sphere(double radius, const Vec3& centre = Vec3::Zero()) {
  vtkNew<vtkSphereSource> s;
  s->SetRadius(radius);
  s->SetCenter(centre.data());
  s->SetThetaResolution(180);
  s->SetPhiResolution(180);
  s->Update();
  return s->GetOutput();
}

using fluidviz::testing::isBackground;

struct Disc {
  double radius = 0.0, cx = 0.0, cy = 0.0;  // px; centre from the left and top edges
};

// Radius from the area of non-background pixels (pi r^2), centre from their centroid.
Disc discOf(const RgbaImage& image, const Rgb& background) {
  double n = 0, sx = 0, sy = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!isBackground(image, x, y, background)) n += 1, sx += x + 0.5, sy += y + 0.5;
  return {std::sqrt(n / kPi), n > 0 ? sx / n : 0.0, n > 0 ? sy / n : 0.0};
}

double predictedRadiusPx(double radius, double rho, const View3DParams& v) {
  const double half = 0.5 * v.camera.view_angle * kPi / 180;
  const double d = rho / std::sin(half) / v.camera.zoom;
  return 0.5 * v.height * std::tan(std::asin(radius / d)) / std::tan(half);
}

vtkSmartPointer<vtkPolyData> points(const std::vector<Vec3>& xs) {
  vtkNew<vtkPoints> p;
  for (const Vec3& x : xs) p->InsertNextPoint(x.data());
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(p);
  return poly;
}

}  // namespace

TEST_F(View3DTest, SphereSilhouetteMatchesTheFramingWithin2Px) {
  for (double zoom : {1.0, 1.5}) {
    View3DParams v = plainView();
    v.camera.zoom = zoom;
    Scene3D scene(v);
    SurfaceStyle style;
    style.specular = 0.0;
    scene.add(makeSurfaceActor(sphere(1.0), style).actor);
    const Disc d = discOf(scene.render(), backgroundColor(Background::white));
    EXPECT_NEAR(d.radius, predictedRadiusPx(1.0, std::sqrt(3.0), v), 2.0) << "zoom " << zoom;
    EXPECT_NEAR(d.cx, 200.0, 1.0);
    EXPECT_NEAR(d.cy, 150.0, 1.0);
  }
}

// Up = y, azimuth 0: the camera looks from +z, x points right. A sphere at +x is right of the
// centre; at azimuth 90 the camera looks from +x and the same sphere sits in the centre; at
// 180 it is on the left. Elevation 89 looks down from +y: +x is still right. The other sphere
// (at -x) keeps the scene's bounds centred on the origin.
TEST_F(View3DTest, AzimuthAndElevationTurnTheCameraAsDocumented) {
  struct Case {
    double azimuth, elevation, expectedSide;  // -1 left, 0 centre, +1 right
  };
  for (const Case c : {Case{0, 0, 1}, Case{90, 0, 0}, Case{180, 0, -1}, Case{0, 89, 1}}) {
    View3DParams v = plainView();
    v.camera.azimuth = c.azimuth;
    v.camera.elevation = c.elevation;
    Scene3D scene(v);
    SurfaceStyle red;
    red.color = {1, 0, 0};
    scene.add(makeSurfaceActor(sphere(0.3, Vec3(1, 0, 0)), red).actor);
    scene.setBounds({-1.3, 1.3, -1.3, 1.3, -1.3, 1.3});
    const Disc d = discOf(scene.render(), backgroundColor(Background::white));
    if (c.expectedSide == 0)
      EXPECT_NEAR(d.cx, 200.0, 2.0) << c.azimuth;
    else
      EXPECT_GT(c.expectedSide * (d.cx - 200.0), 40.0) << c.azimuth << " " << c.elevation;
  }
}

TEST_F(View3DTest, BackgroundsAreExact) {
  for (const std::string bg : {"white", "dark"}) {
    View3DParams v = plainView();
    v.background = fluidviz::choiceNamed<fluidviz::Background>(bg);
    Scene3D scene(v);
    scene.add(makeSurfaceActor(sphere(1.0), SurfaceStyle{}).actor);
    const RgbaImage image = scene.render();
    for (auto [x, y] : {std::pair{0, 0}, std::pair{399, 0}, std::pair{0, 299}, std::pair{399, 299}})
      EXPECT_TRUE(isBackground(image, x, y, backgroundColor(v.background))) << bg << " " << x << "," << y;
  }
}

// Two unlit squares coloured by an array through viridis over [0, 1]: value 0 draws the map's
// first colour, value 1 its last, to within 2/255 (8-bit rounding).
TEST_F(View3DTest, ArrayColouringUsesTheColourMap) {
  vtkNew<vtkAppendPolyData> both;
  for (double value : {0.0, 1.0}) {
    vtkNew<vtkPlaneSource> square;
    square->SetOrigin(value == 0.0 ? -1.0 : 0.0, -0.5, 0.0);
    square->SetPoint1(value == 0.0 ? 0.0 : 1.0, -0.5, 0.0);
    square->SetPoint2(value == 0.0 ? -1.0 : 0.0, 0.5, 0.0);
    square->Update();
    vtkNew<vtkDoubleArray> a;
    a->SetName("value");
    for (int i = 0; i < 4; ++i) a->InsertNextValue(value);
    vtkSmartPointer<vtkPolyData> poly = square->GetOutput();
    poly->GetPointData()->AddArray(a);
    both->AddInputData(poly);
  }
  both->Update();
  SurfaceStyle style;
  style.color_by = "value";
  style.range_min = 0.0;
  style.range_max = 1.0;
  const SurfaceActor actor = makeSurfaceActor(both->GetOutput(), style);
  actor.actor->GetProperty()->LightingOff();  // unlit colour = ambient + diffuse weights x colour
  actor.actor->GetProperty()->SetAmbient(1.0);
  actor.actor->GetProperty()->SetDiffuse(0.0);
  View3DParams v = plainView();
  v.camera.projection = fluidviz::Projection::parallel;
  Scene3D scene(v);
  scene.add(actor.actor);
  const RgbaImage image = scene.render();
  const ColorMap& viridis = ColorMap::byName("viridis");
  for (auto [x, t] : {std::pair{150, 0.0}, std::pair{250, 1.0}}) {
    const auto p = image.pixel(x, 150);
    const ColorMap::Color c = viridis.map(t);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], 255.0 * c[k], 2.0) << "t " << t << " channel " << k;
  }
  ASSERT_TRUE(actor.coloring.has_value());
  EXPECT_EQ(actor.coloring->title, "value");
}

// One particle of radius 1 drawn as a sphere mesh: the same disc as the sphere surface above.
// As a sprite (disc cut by the fragment shader): the same radius within 2 px.
TEST_F(View3DTest, ParticleSpheresAndSpritesHaveTheirWorldRadius) {
  for (const std::string method : {"spheres", "sprites"}) {
    View3DParams v = plainView();
    Scene3D scene(v);
    ParticleStyle style;
    style.radius = 1.0;
    style.method = fluidviz::choiceNamed<fluidviz::ParticleMethod>(method);
    style.sphere_resolution = 64;
    scene.add(makeParticleActor(points({Vec3::Zero()}), style).actor);
    scene.setBounds({-1, 1, -1, 1, -1, 1});
    const Disc d = discOf(scene.render(), backgroundColor(Background::white));
    EXPECT_NEAR(d.radius, predictedRadiusPx(1.0, std::sqrt(3.0), v), 2.0) << method;
  }
}

// Emission-absorption through a slab of constant colour: a 32^3 grid of value 1 over
// [-0.5, 0.5]^3 (31 spacings thick), viridis over [0, 1] (colour C = viridis(1)), opacity 0.02
// per grid spacing, seen straight along z on the dark background B: the centre ray keeps
// T = (1 - 0.02)^31 = 0.534 of the background, pixel = 255 ((1 - T) C + T B) = (129, 118, 31).
// "auto" runs GPU ray casting under OSMesa llvmpipe; measured (129, 118, 31) on the GPU mapper
// and (129, 119, 31) on the CPU (fixed point) one: both asked to be within 2/255.
TEST_F(View3DTest, VolumeRenderingCompositesAsBeerLambertOnGpuAndCpu) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(32, 32, 32);
  image->SetSpacing(1.0 / 31, 1.0 / 31, 1.0 / 31);
  image->SetOrigin(-0.5, -0.5, -0.5);
  vtkNew<vtkDoubleArray> one;
  one->SetName("one");
  for (int n = 0; n < 32 * 32 * 32; ++n) one->InsertNextValue(1.0);
  image->GetPointData()->AddArray(one);
  const double T = std::pow(1.0 - 0.02, 31);
  const ColorMap::Color c = ColorMap::byName("viridis").map(1.0);
  const Rgb b = backgroundColor(Background::dark);
  for (const std::string mapper : {"auto", "cpu"}) {
    VolumeStyle style;
    style.colormap = "viridis";
    style.range_min = 0.0;
    style.range_max = 1.0;
    style.opacity = 0.02;
    style.opacity_start = 0.0;
    style.mapper = fluidviz::choiceNamed<fluidviz::VolumeMapper>(mapper);
    const VolumeProp volume = makeVolume(image, "one", style);
    View3DParams v = plainView();
    v.background = fluidviz::Background::dark;
    Scene3D scene(v);
    scene.add(volume.volume);
    const RgbaImage picture = scene.render();
    const auto p = picture.pixel(200, 150);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(p[k], 255.0 * ((1 - T) * c[k] + T * b[k]), 2.0) << mapper << " channel " << k;
    EXPECT_TRUE(isBackground(picture, 0, 0, b)) << mapper;
    if (mapper == "auto") {
      auto* smart = vtkSmartVolumeMapper::SafeDownCast(volume.volume->GetMapper());
      ASSERT_NE(smart, nullptr);
      EXPECT_EQ(smart->GetLastUsedRenderMode(), vtkSmartVolumeMapper::GPURenderMode);
    }
  }
}

// Nodes holding NaN (resampled nodes without particle support) are transparent: the slab above
// with NaN wherever x < 0 shows the background left of the centre (the 2-node band where the
// rays interpolate between NaN and value is excluded) and the same colour as before on the
// right.
TEST_F(View3DTest, VolumeNodesWithNaNAreTransparent) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(32, 32, 32);
  image->SetSpacing(1.0 / 31, 1.0 / 31, 1.0 / 31);
  image->SetOrigin(-0.5, -0.5, -0.5);
  vtkNew<vtkDoubleArray> half;
  half->SetName("half");
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) half->InsertNextValue(i < 16 ? std::nan("") : 1.0);
  image->GetPointData()->AddArray(half);
  VolumeStyle style;
  style.colormap = "viridis";
  style.range_min = 0.0;
  style.range_max = 1.0;
  style.opacity = 0.02;
  style.opacity_start = 0.0;
  View3DParams v = plainView();
  v.background = fluidviz::Background::dark;
  Scene3D scene(v);
  scene.add(makeVolume(image, "half", style).volume);
  const RgbaImage picture = scene.render();
  const Rgb b = backgroundColor(Background::dark);
  EXPECT_TRUE(isBackground(picture, 160, 150, b));
  const double T = std::pow(1.0 - 0.02, 31);
  const ColorMap::Color c = ColorMap::byName("viridis").map(1.0);
  const auto p = picture.pixel(240, 150);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], 255.0 * ((1 - T) * c[k] + T * b[k]), 2.0) << k;
}

// N frames of a full turn, numbered from 0000 (the azimuth steps themselves are checked above);
// afterwards render() draws the picture it drew before (the turn does not move the camera).
TEST_F(View3DTest, TurntableWritesNumberedFramesOfAFullTurn) {
  const fs::path dir = fs::temp_directory_path() / "fluidviz_turntable_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  View3DParams v = plainView(160, 120);
  v.turntable_frames = 4;
  Scene3D scene(v);
  scene.add(makeSurfaceActor(sphere(0.3, Vec3(1, 0, 0)), SurfaceStyle{}).actor);
  scene.setBounds({-1.3, 1.3, -1.3, 1.3, -1.3, 1.3});
  const RgbaImage first = scene.render();
  const auto frames = scene.renderTurntable(dir / "turn");
  ASSERT_EQ(frames.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(frames[i].filename().string(), "turn_000" + std::to_string(i) + ".png");
    EXPECT_TRUE(fs::exists(frames[i]));
  }
  EXPECT_EQ(scene.render().pixels, first.pixels);  // turning leaves the camera where it was
  fs::remove_all(dir);
}

TEST_F(View3DTest, BadViewParametersNameTheirKey) {
  View3DParams v = plainView();
  v.camera.elevation = 90;
  try {
    Scene3D scene(v);
    ADD_FAILURE() << "no ParamError";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "camera.elevation");
  }
  v = plainView();
  v.camera.up = static_cast<Axis>(7);
  EXPECT_THROW(Scene3D{v}, ParamError);
}
