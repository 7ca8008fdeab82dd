// SPH scene outputs output.grids, output.free_surface and output.views
// (pipeline/SphGridOutputs.h), end to end through `fluidviz run`, in-process:
//   - none of them is written unless listed;
//   - a grid has the dims that spacing and padding give on the SPH domain box, the requested
//     arrays plus color/mask/summation_density, and every_snapshot lists one .vti per snapshot;
//   - the free surface of a tank at rest (water filled to H, after 0.05 s) is flat at H: the
//     reference is the fill height of the scene; the 0.5 level of the colour field lies within
//     dx / 4 of H everywhere more than 2h from the walls (2D isolines and 3D surface);
//   - 3D pictures: background in the corners, the water's colour below the water line only,
//     particles in their colour;
//   - bad keys: exit 2, the key named, nothing written.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "fieldviz/io/VtkXmlReaders.h"
#include "tests/apps/fluidviz/CliTestSupport.h"

namespace fs = std::filesystem;

namespace {

using fluidviz::test::run;

constexpr double kDx = 0.02;   // m, particle spacing
constexpr double kFill = 0.3;  // m, water height H of the tank

// A tank at rest, 0.6 m wide, filled to kFill; 2D or 3D (0.2 m deep), written to dir/tank.json.
std::string writeTankScene(const fs::path& dir, const std::string& outputs, int dimension,
                           int snapshots) {
  const fs::path p = dir / "tank.json";
  const std::string z = dimension == 3 ? "0.2" : "0";
  std::ofstream(p) << R"({ "name": "tank", "solver": "sph",
    "sph": { "dimension": )" << dimension << R"(, "model": "B", "particle_spacing": 0.02,
             "speed_of_sound": 25, "gravity": [0, -9.81, 0],
             "domain_upper": [0.6, 0.6, )" << z << R"(], "walls": {"y_max": "open"},
             "fluid_blocks": [{"lower": [0, 0, 0], "upper": [0.6, 0.3, )" << z << R"(]}],
             "end_time": 0.05 },
    "output": { "snapshots": )" << snapshots << R"(, "images": [])"
                   << (outputs.empty() ? "" : ", ") << outputs << "} }";
  return p.string();
}

fs::path freshSphGridDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("fluidviz_sphgrid_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

class SphGridOutputsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshSphGridDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string writeTank(const std::string& outputs, int dimension = 2, int snapshots = 2) {
    return writeTankScene(dir_, outputs, dimension, snapshots);
  }
  fs::path out() const { return dir_ / "out"; }
  std::set<std::string> filesWritten() const {
    std::set<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(out()))
      names.insert(fs::relative(e.path(), out()).string());
    return names;
  }

  fs::path dir_;
};

// Largest |y - H| of the surface points more than `margin` from the side walls, and their count.
std::pair<double, int> heightDeviation(vtkPolyData* surface, double margin, int dimension) {
  double worst = 0.0;
  int used = 0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i) {
    double x[3];
    surface->GetPoint(i, x);
    if (x[0] < margin || x[0] > 0.6 - margin) continue;
    if (dimension == 3 && (x[2] < margin || x[2] > 0.2 - margin)) continue;
    if (x[1] < 0.1) continue;  // the bottom of the closed contour (below the floor)
    worst = std::max(worst, std::abs(x[1] - kFill));
    ++used;
  }
  return {worst, used};
}

std::array<int, 3> pixel(vtkImageData* png, int x, int yFromTop) {
  const int h = png->GetDimensions()[1];
  std::array<int, 3> c{};
  for (int k = 0; k < 3; ++k)
    c[k] = static_cast<int>(png->GetScalarComponentAsDouble(x, h - 1 - yFromTop, 0, k));
  return c;
}

vtkSmartPointer<vtkImageData> readPng(const fs::path& file) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  return reader->GetOutput();
}

TEST_F(SphGridOutputsTest, NothingIsWrittenUnlessListed) {
  const auto r = run({"run", writeTank(""), "-o", out().string()});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const std::string& f : filesWritten())
    EXPECT_TRUE(f.find("grid") == std::string::npos && f.find("surface") == std::string::npos &&
                f.find("view") == std::string::npos)
        << f;
}

// Spacing 0.02 m and padding 0.04 m on the domain [0, 0.6] x [0, 0.6]: 0.68 / 0.02 + 1 = 35
// nodes per axis, origin -0.04 m; one node in z (2D).
TEST_F(SphGridOutputsTest, GridHasTheRequestedDimsAndArrays) {
  const auto r = run({"run",
                      writeTank(R"("grids": [{"spacing": 0.02, "padding": 0.04,
                                   "arrays": "pressure,velocity", "every_snapshot": true}])",
                                2, 3),
                      "-o", out().string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto grid = fluidviz::readImageData(out() / "tank_grid.vti");
  int dims[3];
  grid->GetDimensions(dims);
  EXPECT_EQ(dims[0], 35);
  EXPECT_EQ(dims[1], 35);
  EXPECT_EQ(dims[2], 1);
  double origin[3], spacing[3];
  grid->GetOrigin(origin);
  grid->GetSpacing(spacing);
  EXPECT_NEAR(origin[0], -0.04, 1e-12);
  EXPECT_NEAR(origin[1], -0.04, 1e-12);
  EXPECT_NEAR(spacing[0], 0.02, 1e-12);
  vtkPointData* pd = grid->GetPointData();
  ASSERT_NE(pd->GetArray("pressure"), nullptr);
  ASSERT_NE(pd->GetArray("velocity"), nullptr);
  EXPECT_EQ(pd->GetArray("velocity")->GetNumberOfComponents(), 3);
  for (const char* a : {"color", "mask", "summation_density"}) EXPECT_NE(pd->GetArray(a), nullptr) << a;
  EXPECT_EQ(pd->GetArray("speed"), nullptr);  // not asked for
  EXPECT_EQ(pd->GetNumberOfArrays(), 5);
  // Summation density in the middle of the water is rest density within 2% (the kernel sum of
  // a full neighbourhood).
  const vtkIdType middle = 15 + 35 * 8;  // x = 0.26 m, y = 0.12 m
  EXPECT_NEAR(pd->GetArray("summation_density")->GetComponent(middle, 0), 1000.0, 20.0);
  for (int k = 1; k <= 3; ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "tank_grid/tank_grid_%04d.vti", k);
    EXPECT_TRUE(fs::exists(out() / name)) << name;
  }
  EXPECT_TRUE(fs::exists(out() / "tank_grid.pvd"));
}

// The scene key order (ResampleParams.h) reaches the grid: with "linear" the grid carries
// resample_order, 1 at the nodes inside the water (a full neighbourhood supports the linear fit,
// LinearResample.h) and 0 wherever mask is 0. The summation density (not interpolated) is the
// same as with the default order, bit for bit.
TEST_F(SphGridOutputsTest, OrderKeyMakesTheGridFirstOrder) {
  const auto grids = [&](const char* order) {
    return std::string(R"("grids": [{"file": ")") + order +
           R"(.vti", "spacing": 0.02, "padding": 0.04, "arrays": "pressure", "order": ")" +
           order + R"("}])";
  };
  for (const char* order : {"linear", "shepard"}) {
    const auto r = run({"run", writeTank(grids(order)), "-o", (out() / order).string()});
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const auto linear = fluidviz::readImageData(out() / "linear" / "linear.vti");
  const auto shepard = fluidviz::readImageData(out() / "shepard" / "shepard.vti");
  vtkPointData* pd = linear->GetPointData();
  vtkDataArray* order = pd->GetArray("resample_order");
  ASSERT_NE(order, nullptr);
  EXPECT_EQ(shepard->GetPointData()->GetArray("resample_order"), nullptr);
  const vtkIdType middle = 15 + 35 * 8;  // x = 0.26 m, y = 0.12 m: inside the water
  EXPECT_EQ(order->GetComponent(middle, 0), 1.0);
  vtkDataArray* mask = pd->GetArray("mask");
  vtkDataArray* rho = pd->GetArray("summation_density");
  vtkDataArray* rhoShepard = shepard->GetPointData()->GetArray("summation_density");
  for (vtkIdType n = 0; n < order->GetNumberOfTuples(); ++n) {
    if (mask->GetComponent(n, 0) == 0.0) EXPECT_EQ(order->GetComponent(n, 0), 0.0) << n;
    ASSERT_EQ(rho->GetComponent(n, 0), rhoShepard->GetComponent(n, 0)) << n;
  }
}

// The reference: the fill height H = 0.3 m of a tank at rest. The colour field's 0.5 level is
// where the kernel-smoothed step of the particle volumes is half, H for a symmetric kernel on
// a uniform lattice; tolerance dx / 20 = 1 mm (measured 2D: 0.13 mm, 3D: 0.26 mm).
void expectFlatSurfaceAtTheFillHeight(const fs::path& out, int dimension) {
  const auto surface = fluidviz::readVtp(out / "tank_free_surface.vtp");
  EXPECT_EQ(dimension == 2 ? surface->GetNumberOfLines() : surface->GetNumberOfPolys(),
            surface->GetNumberOfCells());
  const double margin = 2.0 * 1.3 * kDx;  // 2h from the walls
  const auto [worst, used] = heightDeviation(surface, margin, dimension);
  EXPECT_GE(used, dimension == 2 ? 20 : 100) << dimension << "D";
  EXPECT_LT(worst, 0.05 * kDx) << dimension << "D";
  std::printf("%dD free surface: max |y - H| = %.2e m over %d points\n", dimension, worst, used);
}

TEST_F(SphGridOutputsTest, FreeSurfaceOfATankAtRestIsFlatAtTheFillHeight2D) {
  const auto r = run({"run", writeTank(R"("free_surface": [{"grid": {"spacing": 0.01}}])", 2),
                      "-o", out().string()});
  ASSERT_EQ(r.code, 0) << r.err;
  expectFlatSurfaceAtTheFillHeight(out(), 2);
}

// The 3D picture: white corners, the surface colour (0.3, 0.55, 0.85) only below the middle row
// (the water, 0.3 m, fills half of the 0.6 m domain the camera frames; the padding and
// perspective-free view keep it there), and the particles' orange in the particle picture.
void expectWaterBelowTheWaterLine(const fs::path& out) {
  const auto surface = readPng(out / "tank_view.png");
  for (auto [x, y] : {std::pair{0, 0}, {239, 0}, {0, 239}, {239, 239}})
    EXPECT_EQ(pixel(surface, x, y), (std::array<int, 3>{255, 255, 255})) << x << "," << y;
  auto isWater = [](const std::array<int, 3>& c) { return c[2] > c[0] + 60 && c[2] > 120; };
  int topWaterRow = 240, waterPixels = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 240; ++x)
      if (isWater(pixel(surface, x, y))) topWaterRow = std::min(topWaterRow, y), ++waterPixels;
  EXPECT_GT(topWaterRow, 120 - 2);   // nothing of the water above the middle
  EXPECT_LT(topWaterRow, 120 + 20);  // and the water line close to it
  EXPECT_GT(waterPixels, 240 * 240 / 5);  // the water covers about 240 x 120 px
  const auto particles = readPng(out / "tank_view2.png");
  int orange = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 240; ++x) {
      const auto c = pixel(particles, x, y);
      orange += c[0] > c[2] + 60 && c[0] > 120;
    }
  EXPECT_GT(orange, 240 * 240 / 8);
}

// One 3D run (the longest of this file, under ASan especially) for its surface and for two
// pictures seen from the front (azimuth 0, elevation 0, parallel): the surface and the particles.
TEST_F(SphGridOutputsTest, Tank3DSurfaceIsFlatAndPicturesShowTheWaterBelowTheWaterLine) {
  const auto r = run({"run", writeTank(R"("free_surface": [{"grid": {"spacing": 0.01}}],
      "views": [
      {"width": 240, "height": 240, "multisamples": 0, "outline": false,
       "camera": {"azimuth": 0, "elevation": 0, "projection": "parallel"}},
      {"show": "particles", "width": 240, "height": 240, "multisamples": 0,
       "particles": {"color_by": ""},
       "camera": {"azimuth": 0, "elevation": 0, "projection": "parallel"}}])", 3),
                      "-o", out().string()});
  ASSERT_EQ(r.code, 0) << r.err;
  expectFlatSurfaceAtTheFillHeight(out(), 3);
  expectWaterBelowTheWaterLine(out());
}

TEST_F(SphGridOutputsTest, BadKeysExitWith2AndWriteNothing) {
  const std::pair<std::string, std::string> cases[] = {
      {R"("grids": [{"arrays": "vorticity"}])", "output.grids[0].arrays"},
      {R"("grids": [{"spacing": 1e-5, "max_memory_mb": 1}])", "output.grids[0].spacing"},
      {R"("free_surface": [{"file": "surface.vti"}])", "output.free_surface[0].file"},
      {R"("views": [{"particles": {"color_by": "vorticity"}, "show": "particles"}])",
       "output.views[0].particles.color_by"},
      {R"("views": [{"camera": {"elevation": 95}}])", "output.views[0].camera.elevation"}};
  for (const auto& [outputs, key] : cases) {
    fs::remove_all(out());
    const auto r = run({"run", writeTank(outputs), "-o", out().string()});
    EXPECT_EQ(r.code, 2) << outputs;
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out()) && !fs::is_empty(out())) << outputs;
  }
}

}  // namespace
