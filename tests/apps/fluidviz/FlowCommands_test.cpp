// `fluidviz lic` and `fluidviz streamlines` end to end, in-process: exit codes and messages for
// bad input (nothing written), the zero field (LIC = the noise itself; lines stop at their
// seeds), NaN fields (LIC refuses, streamlines stop with nan_in_field), 3D fields and slices.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPolyData.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <regex>
#include <sstream>

#include "apps/fluidviz/Commands.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/render/ColorMap.h"
#include "fieldviz/render/LicBlend.h"
#include "filters/streamlines/Streamline.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"
#include "tests/support/PngFiles.h"

namespace fs = std::filesystem;
using fluidviz::app::dispatch;

namespace fluidviz {
namespace {

using fluidviz::test::Result;

using fluidviz::test::run;

// n x n nodes over [-1, 1]^2 with velocity f(p) and a scalar `density`.
FieldSet field2D(int n, const std::function<Vec3(const Vec3&)>& f) {
  FieldSet set;
  set.grid.dims = {n, n, 1};
  set.grid.origin = {-1, -1, 0};
  set.grid.spacing = {2.0 / (n - 1), 2.0 / (n - 1), 1.0};
  VectorField v{"velocity", set.grid, {}};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) v.values.push_back(f(set.grid.position(i, j)));
  set.add(v);
  set.add(ScalarField{"density", set.grid, std::vector<double>(set.grid.nodeCount(), 1.0)});
  return set;
}

Vec3 rotation(const Vec3& p) { return {-p.y(), p.x(), 0.0}; }

// The texture's place in the picture, as `fluidviz lic` reports it.
std::array<int, 2> textureTopLeft(const std::string& out) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(out, m, std::regex(R"(x \[(\d+), \d+\), y \[(\d+), \d+\))")))
      << out;
  return {std::stoi(m[1]), std::stoi(m[2])};
}

class FlowCommands : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_flow_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "in");
    fs::create_directories(dir_ / "out");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string input(const std::string& name, const FieldSet& set) {
    const fs::path p = dir_ / "in" / name;
    writeVti(set, p);
    return p.string();
  }
  std::string out(const std::string& name) const { return (dir_ / "out" / name).string(); }

  void expectBadInput(const std::vector<std::string>& args, const std::string& expected) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << "message was: " << r.err;
    EXPECT_TRUE(fs::is_empty(dir_ / "out")) << "bad input must not write anything";
  }

  fs::path dir_;
};

TEST_F(FlowCommands, LicBadInputExitsWithCodeTwoNamingFileArrayAndRange) {
  const std::string f = input("rot.vti", field2D(21, rotation));
  const std::string png = out("a.png");
  expectBadInput({"lic", (dir_ / "in/none.vti").string(), "-a", "velocity", "-o", png},
                 "none.vti does not exist");
  expectBadInput({"lic", f, "-a", "vel", "-o", png},
                 "rot.vti: no point-data array 'vel'; arrays present: velocity(3), density(1)");
  expectBadInput({"lic", f, "-a", "density", "-o", png},
                 "array 'density' has 1 component; a vector field needs 2 or 3");
  expectBadInput({"lic", f, "-o", png}, "needs -a ARRAY, the vector array to use; file " + f +
                                            " has: velocity(3), density(1)");
  expectBadInput({"lic", f, "-a", "velocity", "-o", png, "--length", "0"},
                 "--length is 0 px, outside the allowed range [1, 1000]");
  expectBadInput({"lic", f, "-a", "velocity", "-o", png, "--method", "slow"},
                 "--method is \"slow\", allowed one of {reference, fast}");
  expectBadInput({"lic", f, "-a", "velocity", "-o", png, "--resolution", "80y"},
                 "--resolution is '80y'; expected WxH");
  expectBadInput({"lic", f, "-a", "velocity", "-o", png, "--weight", "2"},
                 "--weight is 2, outside the allowed range [0, 1]");
  expectBadInput({"lic", f, "-a", "velocity", "-o", png, "--color-by", "pressure"},
                 "no point-data array 'pressure'; arrays present: velocity(3), density(1)");
  expectBadInput({"lic", f, "-a", "velocity", "-o", (dir_ / "out/no/a.png").string()},
                 "folder '" + (dir_ / "out/no").string() + "' does not exist");
  expectBadInput({"lic", f, "-a", "velocity", "-o", png, "--bogus"}, "unknown option '--bogus'");
}

TEST_F(FlowCommands, NaNInTheFieldStopsLicWithTheArrayNamedAndStreamlinesWithReasonNaN) {
  const std::string f = input("nan.vti", field2D(41, [](const Vec3& p) {
    return p.x() > 0.5 ? Vec3::Constant(std::numeric_limits<double>::quiet_NaN()) : rotation(p);
  }));
  // Issue 15: NaN nodes are masked (drawn in the mask colour), no longer refused.
  const Result licRun = run({"lic", f, "-a", "velocity", "-o", out("n.png")});
  EXPECT_EQ(licRun.code, 0) << licRun.err;
  EXPECT_TRUE(fs::exists(out("n.png")));
  // A circle of radius 0.8 runs into x > 0.5 and stops there; one of radius 0.3 closes.
  const Result r = run({"streamlines", f, "-a", "velocity", "-o", out("n.vtp"), "--seeds",
                        "points:0,0.8;0,0.3", "--direction", "forward"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: 1 lines stopped at NaN or infinite values of 'velocity' "
                       "(reason nan_in_field)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("closed_loop 1, nan_in_field 1"), std::string::npos) << r.out;
  vtkSmartPointer<vtkPolyData> lines = readVtp(out("n.vtp"));
  auto* reason = lines->GetCellData()->GetArray("reason");
  ASSERT_EQ(lines->GetNumberOfLines(), 2);
  EXPECT_EQ(reason->GetTuple1(0), static_cast<int>(streamlines::TerminationReason::nan_in_field));
  EXPECT_EQ(reason->GetTuple1(1), static_cast<int>(streamlines::TerminationReason::closed_loop));
  // The stopped line ends at the last finite cell (x <= 0.5), after turning through the left
  // half plane: from (0, 0.8) anticlockwise round to x = 0.5 at y = -0.62.
  const auto points = streamlines::polylinePoints(lines);
  const Vec3 end = points[0].back();
  EXPECT_LE(end.x(), 0.5 + 1e-6);
  EXPECT_GT(end.x(), 0.5 - 0.05);  // within one cell (0.05 m) of the NaN region
  EXPECT_NEAR(end.y(), -std::sqrt(0.64 - end.x() * end.x()), 1e-3);
}

// Zero velocity: with the contrast stretch off, every LIC pixel is its noise value (uniform on
// [0, 1): mean 1/2, standard deviation 1/sqrt(12) = 0.2887, neighbours uncorrelated), and the
// picture is that noise over the middle colour of the map (a constant speed sets no range).
TEST_F(FlowCommands, LicOfAZeroFieldIsThePlainNoise) {
  const std::string f = input("zero.vti", field2D(21, [](const Vec3&) { return Vec3::Zero(); }));
  const Result r = run({"lic", f, "-a", "velocity", "-o", out("z.png"), "--vti", out("z.vti"),
                        "--no-contrast", "--resolution", "200x200", "--seed", "7"});
  ASSERT_EQ(r.code, 0) << r.err;
  const ScalarField lic = readScalarField(out("z.vti"), "lic");
  ASSERT_EQ(lic.values.size(), 40000u);
  double sum = 0, sum2 = 0, cross = 0;
  for (int j = 0; j < 200; ++j)
    for (int i = 0; i < 200; ++i) {
      const double v = lic.values[j * 200 + i] - 0.5;
      sum += v, sum2 += v * v;
      if (i + 1 < 200) cross += v * (lic.values[j * 200 + i + 1] - 0.5);
    }
  const double mean = 0.5 + sum / 40000, sd = std::sqrt(sum2 / 40000 - (sum / 40000) * (sum / 40000));
  // Tolerances ~4 standard errors of N = 40000 samples: mean 0.0014, sd 0.0006, correlation 0.005.
  EXPECT_NEAR(mean, 0.5, 0.006);
  EXPECT_NEAR(sd, 1.0 / std::sqrt(12.0), 0.003);
  EXPECT_NEAR(cross / (200 * 199) / (sd * sd), 0.0, 0.02);
  // Picture: pixel = clamp(viridis(1/2) + 0.6 (lic - 1/2)), checked on a row of the texture.
  const RgbaImage png = fluidviz::testing::readPngImage(out("z.png"));
  const auto [left, top] = textureTopLeft(r.out);
  const ColorMap::Color mid = ColorMap::byName("viridis").map(0.5);
  double worst = 0;
  for (int i = 0; i < 200; ++i) {
    const ColorMap::Color c = blendLicColor(mid, lic.values[100 * 200 + i], 0.6);
    const auto p = png.pixel(left + i, top + 199 - 100);
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(p[k] - 255.0 * std::clamp(c[k], 0.0, 1.0)));
  }
  EXPECT_LE(worst, 1.0);
}

TEST_F(FlowCommands, StreamlinesOfAZeroFieldStopAtTheirSeedsWithReasonStagnation) {
  const std::string f = input("zero.vti", field2D(11, [](const Vec3&) { return Vec3::Zero(); }));
  const Result r = run({"streamlines", f, "-a", "velocity", "-o", out("z.vtp"), "--seeds",
                        "grid:2,2", "--png", out("z.png")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("traced 4 lines (rk4, step 0.25 cells); they end by: stagnation 4"),
            std::string::npos)
      << r.out;
  vtkSmartPointer<vtkPolyData> lines = readVtp(out("z.vtp"));
  ASSERT_EQ(lines->GetNumberOfLines(), 4);
  EXPECT_EQ(lines->GetNumberOfPoints(), 8);  // each line is its seed (twice: zero length)
  for (vtkIdType c = 0; c < 4; ++c)
    EXPECT_EQ(lines->GetCellData()->GetArray("reason")->GetTuple1(c),
              static_cast<int>(streamlines::TerminationReason::stagnation));
  EXPECT_TRUE(fs::exists(out("z.png")));
}

// --axes on the pictures of streamlines (speed and LIC underlays), lic and topology: tick labels and axis
// titles add dark (text) pixels; the axes themselves are checked in
// FieldImage.AxesPutATickAtEveryRoundCoordinate and LicPicture.AxesGrowThePicture...
TEST_F(FlowCommands, AxesFlagAddsTickLabelsToStreamlineLicAndTopologyPictures) {
  const std::string f = input("rot.vti", field2D(41, rotation));
  const auto darkPixels = [](const std::string& png) {
    const RgbaImage image = fluidviz::testing::readPngImage(png);
    int n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const auto p = image.pixel(x, y);
        n += p[0] < 64 && p[1] < 64 && p[2] < 64;
      }
    return n;
  };
  const auto withAndWithout = [&](std::vector<std::string> line, const std::string& stem) {
    line.push_back(out(stem + "_n.png"));
    EXPECT_EQ(run(line).code, 0) << stem;
    line.back() = out(stem + "_a.png");
    line.push_back("--axes");
    EXPECT_EQ(run(line).code, 0) << stem;
    EXPECT_GT(darkPixels(out(stem + "_a.png")), darkPixels(out(stem + "_n.png")) + 100) << stem;
  };
  for (const std::string underlay : {"speed", "lic"})
    withAndWithout({"streamlines", f, "-a", "velocity", "-o", out("l.vtp"), "--seeds",
                    "points:0,0.5", "--underlay", underlay, "--png"},
                   underlay);
  withAndWithout({"lic", f, "-a", "velocity", "--resolution", "200x200", "-o"}, "lic");
  withAndWithout({"topology", f, "-a", "velocity", "-o", out("t.vtp"), "--width", "200", "--png"},
                 "topology");
}

TEST_F(FlowCommands, StreamlinesBadInputExitsWithCodeTwo) {
  const std::string f = input("rot.vti", field2D(21, rotation));
  const std::string vtp = out("a.vtp");
  expectBadInput({"streamlines", f, "-a", "vel", "-o", vtp}, "no point-data array 'vel'");
  expectBadInput({"streamlines", f, "-a", "density", "-o", vtp}, "array 'density' has 1 component");
  expectBadInput({"streamlines", f, "-a", "velocity", "-o", vtp, "--seeds", "circle:3"},
                 "--seeds is 'circle:3'; allowed: line:x0,y0[,z0],x1,y1[,z1],n | grid:nx,ny[,nz]");
  expectBadInput({"streamlines", f, "-a", "velocity", "-o", vtp, "--seeds", "line:0,0,1,1,0"},
                 "--seeds: line_count is 0, outside the allowed range [1, 1000000]");
  expectBadInput({"streamlines", f, "-a", "velocity", "-o", vtp, "--step", "0"},
                 "--step is 0 cells, outside the allowed range (0, 100]");
  expectBadInput({"streamlines", f, "-a", "velocity", "-o", vtp, "--integrator", "rk3"},
                 "--integrator is \"rk3\", allowed one of {rk2, rk4, rk45}");
  expectBadInput({"streamlines", f, "-a", "velocity", "-o", vtp, "--integrator", "rk45", "--step",
                  "5"},
                 "--step is 5 cells; with integrator rk45 it is the first step and must lie in");
  expectBadInput({"streamlines", f, "-a", "velocity", "-o", vtp, "--png", out("a.png"),
                  "--line-color", "1,2,0"},
                 "--line-color[1] is 2, outside the allowed range [0, 1]");
  expectBadInput({"streamlines", f, "-a", "velocity", "-o", vtp, "--evenly-spaced", "0.1"},
                 "--evenly-spaced is 0.1 cells, outside the allowed range [0.5, 10000]");
}

TEST_F(FlowCommands, ThreeDimensionalFieldsNeedASliceForLicAndUseThatLayer) {
  FieldSet set;
  set.grid.dims = {9, 9, 4};
  set.grid.spacing = {0.25, 0.25, 0.5};
  VectorField v{"velocity", set.grid, {}};
  for (int k = 0; k < 4; ++k)
    for (int n = 0; n < 81; ++n) v.values.emplace_back(k == 2 ? 1.0 : 0.0, 0.0, 0.3);
  set.add(v);
  const std::string f = input("3d.vti", set);
  expectBadInput({"lic", f, "-a", "velocity", "-o", out("a.png")},
                 "array 'velocity' is 3D (9x9x4 nodes");
  // (streamlines trace a 3D field in 3D without --slice: Streamlines3D_test.cpp)
  expectBadInput({"lic", f, "-a", "velocity", "-o", out("a.png"), "--slice", "z=4"},
                 "--slice is z=4, outside [0, 3]");
  expectBadInput({"lic", f, "-a", "velocity", "-o", out("a.png"), "--slice", "4"},
                 "--slice is '4'; expected x=I, y=J or z=K (node index)");
  // Layer 2 flows along +x at 1 m/s: a line across the whole width, at z = 1 m.
  const Result r = run({"streamlines", f, "-a", "velocity", "-o", out("s.vtp"), "--slice", "z=2",
                        "--seeds", "points:1,1"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto points = streamlines::polylinePoints(readVtp(out("s.vtp")));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].front().x(), 0.0, 1e-9);
  EXPECT_NEAR(points[0].back().x(), 2.0, 1e-9);
  EXPECT_NEAR(points[0].back().z(), 1.0, 1e-12);
  EXPECT_EQ(run({"lic", f, "-a", "velocity", "-o", out("s.png"), "--slice", "z=2",
                 "--resolution", "64"}).code,
            0);
}

// Rigid rotation has vorticity 2 everywhere: coloured by vorticity, the symmetric range is
// [-2, 2] and every pixel (with --weight 0) shows the top colour of coolwarm, the default map
// for vorticity.
TEST_F(FlowCommands, VorticityColouringUsesASymmetricRangeOnCoolwarm) {
  const std::string f = input("rot.vti", field2D(21, rotation));
  const Result r = run({"lic", f, "-a", "velocity", "-o", out("v.png"), "--color-by", "vorticity",
                        "--weight", "0", "--resolution", "100"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("colour range [-2, 2]"), std::string::npos) << r.out;
  const RgbaImage png = fluidviz::testing::readPngImage(out("v.png"));
  const auto [left, top] = textureTopLeft(r.out);
  const ColorMap::Color red = ColorMap::byName("coolwarm").map(1.0);
  for (int k : {0, 37, 99}) {
    const auto p = png.pixel(left + k, top + 99 - k);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], 255.0 * red[c], 1.0) << "pixel " << k;
  }
}

}  // namespace
}  // namespace fluidviz
