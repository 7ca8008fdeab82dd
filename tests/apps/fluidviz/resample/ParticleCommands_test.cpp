// `fluidviz resample` and `fluidviz isosurface` end to end, in-process: a ball of particles to a
// grid, its free surface and pictures; 2D isolines; exit code 2 with messages naming the file,
// flag or array for bad input, and nothing written then.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPolyData.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "apps/fluidviz/Commands.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/render/RgbaImage.h"
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "filters/isosurface/vtk/Isosurface.h"
#include "tests/filters/resample/ParticleClouds.h"
#include "tests/support/PngFiles.h"

namespace fs = std::filesystem;
using namespace fluidviz;
using fluidviz::app::dispatch;

namespace {

constexpr double kPi = std::numbers::pi;

using fluidviz::test::Result;
using fluidviz::test::run;

class ParticleCommands : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(std::getenv("DISPLAY"), nullptr) << "tests must run without an X display";
    dir_ = fs::temp_directory_path() /
           ("fluidviz_particles_" + std::string(::testing::UnitTest::GetInstance()
                                                     ->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!std::getenv("FLUIDVIZ_KEEP_TEST_OUTPUT")) fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // A ball of radius 0.5 m (shells of spacing 0.05 m, mass and density) rotating about z, with
  // a hydrostatic pressure rho g (0.5 - y).
  std::string writeBall() {
    particles::ParticleSet ps = fluidviz::testing::shellBall(Vec3(0, 0, 0), 10, 0.05);
    particles::ParticleVectors v{"velocity", {}};
    for (const Vec3& p : ps.positions) v.values.push_back(Vec3(-p.y(), p.x(), 0.0));
    ps.vectors.push_back(v);
    fluidviz::testing::addScalar(ps, "pressure", [](const Vec3& p) { return 9810.0 * (0.5 - p.y()); });
    writeVtp(resample::toPolyData(ps), path("ball.vtp"));
    return path("ball.vtp");
  }

  // Bad input: exit code 2, a message containing `expected`, no file `output`.
  void expectBadInput(const std::vector<std::string>& args, const std::string& expected,
                      const std::string& output) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << "message was: " << r.err;
    EXPECT_FALSE(fs::exists(output)) << "bad input must not write " << output;
  }

  fs::path dir_;
};

bool isWhite(const std::array<std::uint8_t, 4>& p) {
  return p[0] == 255 && p[1] == 255 && p[2] == 255;
}

}  // namespace

// The free surface of a resampled ball (colour field 0.5) is a sphere: area within 3% of
// 4 pi R^2 at 10 particle spacings per radius (the isosurface tests bound it more tightly).
// The pictures have a white background in the corners and the data in the centre.
TEST_F(ParticleCommands, BallToGridToSurfaceWithPictures) {
  const std::string ball = writeBall();
  const Result r = run({"resample", ball, "-o", path("ball.vti"), "--png-particles",
                        path("particles.png"), "--color-by", "velocity", "--png-volume",
                        path("volume.png"), "--volume-array", "pressure", "--size", "400x300",
                        "--multisamples", "0"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("m/rho from arrays 'mass' and 'density'"), std::string::npos) << r.out;
  const FieldSet grid = readVti(path("ball.vti"));
  for (const char* name :
       {"velocity", "pressure", "mass", "density", "color", "mask", "summation_density"})
    EXPECT_TRUE(grid.findScalar(name) || grid.findVector(name)) << name;

  const Result s = run({"isosurface", path("ball.vti"), "-a", "color", "--value", "0.5", "-o",
                        path("surface.vtp"), "--png", path("surface.png"), "--size", "400x300",
                        "--multisamples", "0"});
  ASSERT_EQ(s.code, 0) << s.err;
  const auto m = isosurface::measureSurface(readVtp(path("surface.vtp")));
  EXPECT_NEAR(m.area / (4 * kPi * 0.25), 1.0, 0.03);
  EXPECT_NE(s.out.find("enclosed volume"), std::string::npos) << s.out;
  for (const char* png : {"particles.png", "volume.png", "surface.png"}) {
    const RgbaImage image = fluidviz::testing::readPngImage(path(png));
    ASSERT_EQ(image.width, 400) << png;
    ASSERT_EQ(image.height, 300) << png;
    EXPECT_TRUE(isWhite(image.pixel(2, 2))) << png;           // background in the corner
    EXPECT_FALSE(isWhite(image.pixel(200, 150))) << png;      // the ball in the centre
  }
}

// A disc of particles in 2D: isolines of its colour field at 0.5 are a circle of length 2 pi R
// (within 3% at 10 spacings per radius), and the 2D picture is written.
TEST_F(ParticleCommands, DiscGivesIsolineOfCircleLength) {
  particles::ParticleSet disc;
  const double dx = 0.05, radius = 0.5;
  for (int j = -12; j <= 12; ++j)
    for (int i = -12; i <= 12; ++i)
      if (std::hypot(i * dx, j * dx) < radius)
        disc.positions.push_back(Vec3(i * dx, j * dx, 0.0));
  writeVtp(resample::toPolyData(disc), path("disc.vtp"));
  ASSERT_EQ(run({"resample", path("disc.vtp"), "-o", path("disc.vti")}).code, 0);
  const Result s = run({"isosurface", path("disc.vti"), "-a", "color", "--value", "0.5", "-o",
                        path("lines.vtp"), "--png", path("lines.png"), "--size", "300"});
  ASSERT_EQ(s.code, 0) << s.err;
  const auto m = isosurface::measureSurface(readVtp(path("lines.vtp")));
  EXPECT_NEAR(m.length / (2 * kPi * radius), 1.0, 0.03);
  EXPECT_TRUE(fs::exists(path("lines.png")));
}

// --order linear (filters/resample/LinearResample.h): the ball's hydrostatic pressure, linear in
// y, is reproduced to rounding (tolerance 1e-6 of its largest value) at every node the array
// resample_order marks first order, on the ball's irregular shells; the summary says how many.
TEST_F(ParticleCommands, OrderLinearReproducesALinearPressure) {
  const Result r = run({"resample", writeBall(), "-o", path("ball.vti"), "--order", "linear"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("order: linear (first order) at "), std::string::npos) << r.out;
  const FieldSet grid = readVti(path("ball.vti"));
  const ScalarField* order = grid.findScalar("resample_order");
  const ScalarField* mask = grid.findScalar("mask");
  const ScalarField* pressure = grid.findScalar("pressure");
  ASSERT_TRUE(order && mask && pressure);
  const Grid& g = grid.grid;
  std::size_t firstOrder = 0, supported = 0;
  double worst = 0.0;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const std::size_t n = g.index(i, j, k);
        supported += mask->values[n] == 1.0;
        if (order->values[n] != 1.0) continue;
        ++firstOrder;
        const double exact = 9810.0 * (0.5 - g.position(i, j, k).y());
        worst = std::max(worst, std::abs(pressure->values[n] - exact) / 9810.0);
      }
  EXPECT_GT(firstOrder, supported / 2) << firstOrder << " of " << supported;
  EXPECT_LE(worst, 1e-6);
}

TEST_F(ParticleCommands, BadResampleInputIsRefusedWithoutOutput) {
  const std::string ball = writeBall(), grid = path("grid.vti");
  expectBadInput({"resample", path("missing.vtp"), "-o", grid}, "missing.vtp", grid);
  expectBadInput({"resample", ball, "-o", grid, "--arrays", "velocity,vorticity"},
                 "'vorticity', which the particles do not have; arrays present: mass(1), "
                 "density(1), pressure(1), velocity(3)",
                 grid);
  expectBadInput({"resample", ball, "-o", grid, "--kernel", "gauss"},
                 "--kernel is \"gauss\", allowed one of {cubic_spline, wendland_c2, poly6}", grid);
  expectBadInput({"resample", ball, "-o", grid, "--order", "quadratic"},
                 "--order is \"quadratic\", allowed one of {shepard, linear}", grid);
  expectBadInput({"resample", ball, "-o", grid, "--h", "-1"}, "--h is -1", grid);
  expectBadInput({"resample", ball, "-o", grid, "--color-by", "vorticity", "--png-particles",
                  path("p.png")},
                 "--color-by names 'vorticity'", grid);
  expectBadInput({"resample", ball, "-o", grid, "--png-volume", path("v.png"), "--volume-array",
                  "velocity"},
                 "--volume-array: array 'velocity' has 3 components", grid);
  EXPECT_FALSE(fs::exists(path("v.png")));
  EXPECT_FALSE(fs::exists(path("p.png")));
}

// 1e-5 m nodes over the padded 1.21 m box: 1.8e15 nodes of 9 doubles (velocity, pressure, mass,
// density, colour, mask, summation density; the sums exist per block of layers only). Refused
// before allocating, with the memory it would need (1.27e17 bytes).
TEST_F(ParticleCommands, EnormousGridIsRefusedBeforeAllocating) {
  const std::string ball = writeBall(), grid = path("grid.vti");
  const Result r = run({"resample", ball, "-o", grid, "--spacing", "1e-5"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--spacing gives a 120896 x 120933 x 120918 grid (1.768e+15 nodes"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("would need 1.27e+08 GB"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("max_memory_mb = 4096 MB"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(grid));
}

TEST_F(ParticleCommands, BadIsosurfaceInputIsRefusedWithoutOutput) {
  ASSERT_EQ(run({"resample", writeBall(), "-o", path("ball.vti")}).code, 0);
  const std::string grid = path("ball.vti"), vtp = path("s.vtp");
  expectBadInput({"isosurface", grid, "-a", "colour", "--value", "0.5", "-o", vtp},
                 "no point-data array 'colour'; arrays present:", vtp);
  expectBadInput({"isosurface", grid, "-a", "color", "--value", "7", "-o", vtp},
                 "--value is 7, outside the range [0, ", vtp);
  expectBadInput({"isosurface", grid, "-a", "velocity", "--value", "0.1", "-o", vtp},
                 "array 'velocity' has 3 components", vtp);
  expectBadInput({"isosurface", grid, "-a", "density", "--value", "1000", "-o", vtp},
                 "NaN values (for resampled particles: nodes without particle support", vtp);
  expectBadInput({"isosurface", grid, "-a", "color", "--value", "0.5", "-o", vtp, "--smooth",
                  "1000"},
                 "--smooth is 1000, outside the allowed range [0, 500]", vtp);
  expectBadInput({"isosurface", grid, "--value", "0.5", "-o", vtp}, "-a", vtp);
}
