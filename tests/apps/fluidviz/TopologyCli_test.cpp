// fluidviz topology end to end, in-process: the CSV header and rows against the analytic critical
// points of a cellular flow, the .vtp files read back, the picture's glyphs, the 3D slice, and bad
// input (exit code 2, a message naming the file / array / key and the allowed range, nothing
// written).
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "apps/fluidviz/Commands.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "tests/support/PngFiles.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "filters/topology/SeparatingSurfaces.h"

namespace fs = std::filesystem;
using fluidviz::app::dispatch;
using fluidviz::Vec3;

namespace {

constexpr double kPi = std::numbers::pi;

using fluidviz::test::Result;

using fluidviz::test::run;

// psi = sin(pi x) sin(pi y) on [-0.9, 0.9]^2, v = (psi_y, -psi_x): centres at (+-1/2, +-1/2)
// with Jacobian [[0, -+pi^2], [+-pi^2, 0]] (det pi^4, trace 0) and a saddle at the origin with
// Jacobian diag(pi^2, -pi^2) (det -pi^4). No other zero lies in the box.
fluidviz::FieldSet cellularFlow(int layers = 1) {
  fluidviz::Grid g;
  g.dims = {61, 61, layers};
  g.origin = {-0.9, -0.9, 0.0};
  g.spacing = {1.8 / 60, 1.8 / 60, 0.25};
  fluidviz::VectorField v{"velocity", g, {}};
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const Vec3 p = g.position(i, j, k);
        v.values.emplace_back(kPi * std::sin(kPi * p.x()) * std::cos(kPi * p.y()),
                              -kPi * std::cos(kPi * p.x()) * std::sin(kPi * p.y()), 0.0);
      }
  fluidviz::FieldSet set;
  set.grid = g;
  set.add(v);
  set.add(fluidviz::magnitude(v, "speed"));
  return set;
}

struct Row {
  double x, y, z;
  std::string type;
  int index, morse;
  double det, trace;
  int hyperbolic, elliptic, parabolic;
};

std::vector<std::string> lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

Row parseRow(const std::string& line) {
  std::stringstream s(line);
  std::vector<std::string> cells;
  for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
  EXPECT_EQ(cells.size(), 11u) << line;
  if (cells.size() != 11) return {};
  return {std::stod(cells[0]), std::stod(cells[1]), std::stod(cells[2]), cells[3],
          std::stoi(cells[4]), std::stoi(cells[5]), std::stod(cells[6]), std::stod(cells[7]),
          std::stoi(cells[8]), std::stoi(cells[9]), std::stoi(cells[10])};
}

class TopologyCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_topology_cli_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string field(const fluidviz::FieldSet& set, const std::string& name = "flow.vti") {
    fluidviz::writeVti(set, dir_ / name);
    return (dir_ / name).string();
  }
  std::string out(const std::string& name) const { return (dir_ / "out" / name).string(); }

  // Bad input: exit code 2, a message containing `expected`, and nothing in out/.
  void expectBadInput(const std::vector<std::string>& args, const std::string& expected) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << "message was: " << r.err;
    EXPECT_TRUE(fs::is_empty(dir_ / "out")) << "bad input must not write anything";
  }

  fs::path dir_;
};

}  // namespace

TEST_F(TopologyCliTest, CsvRowsAreTheAnalyticCriticalPoints) {
  const std::string vti = field(cellularFlow());
  const Result r = run({"topology", vti, "-a", "velocity", "-o", out("points.vtp"), "--csv",
                        out("points.csv"), "--png", out("points.png"), "--underlay", "speed"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("5 critical points (saddle 1, centre 4), index sum 3"), std::string::npos)
      << r.out;
  const std::vector<std::string> csv = lines(out("points.csv"));
  ASSERT_EQ(csv.size(), 6u);
  EXPECT_EQ(csv[0], "x,y,z,type,index,morse,det,trace,hyperbolic,elliptic,parabolic");
  const double pi4 = std::pow(kPi, 4);
  int centres = 0;
  for (std::size_t k = 1; k < csv.size(); ++k) {
    const Row row = parseRow(csv[k]);
    SCOPED_TRACE(csv[k]);
    // Positions: the saddle sits on a node (exact); the centres lie inside cells, where the
    // bilinear interpolant's zero is O(h^2) off (measured 3.3e-6 m = 1.1e-4 cell).
    EXPECT_EQ(row.z, 0.0);
    EXPECT_EQ(row.morse, 1);
    EXPECT_EQ(row.parabolic, 0);
    EXPECT_EQ(row.elliptic, 0);
    // det: central differences with h = 0.03 m, relative error (pi h)^2 / 6 = 0.15 % per factor
    // on a node; inside a cell the differences are interpolated too (measured 0.69 %).
    if (row.type == "saddle") {
      EXPECT_NEAR(row.x, 0.0, 1e-9);
      EXPECT_NEAR(row.y, 0.0, 1e-9);
      EXPECT_EQ(row.index, -1);
      EXPECT_EQ(row.hyperbolic, 4);
      EXPECT_NEAR(row.det, -pi4, 0.005 * pi4);
    } else {
      ++centres;
      EXPECT_EQ(row.type, "centre");
      EXPECT_NEAR(std::abs(row.x), 0.5, 1e-5);
      EXPECT_NEAR(std::abs(row.y), 0.5, 1e-5);
      EXPECT_EQ(row.index, 1);
      EXPECT_EQ(row.hyperbolic, 0);
      EXPECT_NEAR(row.det, pi4, 0.01 * pi4);
    }
    EXPECT_NEAR(row.trace, 0.0, 1e-9 * kPi * kPi);  // divergence-free by symmetry
  }
  EXPECT_EQ(centres, 4);
}

TEST_F(TopologyCliTest, VtpFilesReadBackWithTheirArrays) {
  const std::string vti = field(cellularFlow());
  ASSERT_EQ(run({"topology", vti, "-a", "velocity", "-o", out("p.vtp")}).code, 0);
  vtkSmartPointer<vtkPolyData> points = fluidviz::readVtp(out("p.vtp"));
  ASSERT_EQ(points->GetNumberOfPoints(), 5);
  auto* type = vtkStringArray::SafeDownCast(points->GetPointData()->GetAbstractArray("type"));
  ASSERT_NE(type, nullptr);
  int saddle = -1;
  for (vtkIdType i = 0; i < 5; ++i) {
    if (type->GetValue(i) == "saddle") saddle = static_cast<int>(i);
    const double index = points->GetPointData()->GetArray("index")->GetTuple1(i);
    EXPECT_EQ(index, type->GetValue(i) == "saddle" ? -1 : 1);
  }
  ASSERT_GE(saddle, 0);
  for (const char* name : {"morse", "det", "trace", "hyperbolic", "elliptic", "parabolic"})
    EXPECT_NE(points->GetPointData()->GetArray(name), nullptr) << name;
  // The saddle's four separatrices run along the axes to the box's edges.
  vtkSmartPointer<vtkPolyData> seps = fluidviz::readVtp(out("p_separatrices.vtp"));
  ASSERT_EQ(seps->GetNumberOfLines(), 4);
  for (vtkIdType c = 0; c < 4; ++c)
    EXPECT_EQ(seps->GetCellData()->GetArray("origin")->GetTuple1(c), saddle);
}

// The picture: one red saddle cross in the field and one in the legend strip below it.
TEST_F(TopologyCliTest, PictureShowsOneGlyphPerPointAndALegend) {
  const std::string vti = field(cellularFlow());
  ASSERT_EQ(run({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--png", out("p.png"),
                 "--underlay", "speed", "--width", "400", "--no-separatrices"})
                .code,
            0);
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(out("p.png").c_str());
  reader->Update();
  vtkImageData* png = reader->GetOutput();
  int dims[3];
  png->GetDimensions(dims);
  EXPECT_EQ(dims[0], 400);
  EXPECT_GT(dims[1], 400);  // the legend strip is stacked below the square picture
  int red = 0;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      auto* px = static_cast<unsigned char*>(png->GetScalarPointer(x, y, 0));
      if (px[0] > 200 && px[1] < 60 && px[2] < 60) ++red;
    }
  // The saddle's fill (0.9, 0.1, 0.1) appears exactly twice: in the field and in the legend. A
  // cross of 16 px x 1.25 fills about 90 px (measured 179 for both); viridis never comes close
  // to that red, so a missing or extra saddle glyph moves the count out of [120, 260].
  EXPECT_GT(red, 120);
  EXPECT_LT(red, 260);
  EXPECT_FALSE(fs::exists(out("p_separatrices.vtp")));
}

TEST_F(TopologyCliTest, LayerOfA3DField) {
  const std::string vti = field(cellularFlow(3));
  // Without --slice the field is analysed in 3D: v_z = 0 everywhere, so every zero of a layer
  // continues along z as a line of zeros, and no tetrahedron holds an isolated one.
  const Result whole = run({"topology", vti, "-a", "velocity", "-o", out("whole.vtp")});
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_NE(whole.out.find("0 critical points, index sum 0 (3D)"), std::string::npos) << whole.out;
  EXPECT_EQ(fluidviz::readVtp(out("whole_separatrices.vtp"))->GetNumberOfLines(), 0);
  EXPECT_EQ(fluidviz::readVtp(out("whole_surfaces.vtp"))->GetNumberOfPolys(), 0);
  fs::remove(out("whole.vtp"));
  fs::remove(out("whole_separatrices.vtp"));
  fs::remove(out("whole_surfaces.vtp"));
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--slice", "z=3"},
                 "--slice is z=3, outside [0, 2]");
  const Result r = run({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--csv",
                        out("p.csv"), "--slice", "z=2"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<std::string> csv = lines(out("p.csv"));
  ASSERT_EQ(csv.size(), 6u);
  for (std::size_t k = 1; k < csv.size(); ++k) EXPECT_EQ(parseRow(csv[k]).z, 0.5);  // 2 * 0.25
}

// A 3D array without --slice: v = A (x - x0) with A = [[0.5, 1, 0], [-1, 0.5, 0], [0, 0, -2]]
// (eigenvalues 0.5 +- i and -2: a spiral 2-saddle, index sign(det A) = -1) and x0 off-node; the
// CSV row and the .vtp arrays carry the point, its type, index, det and eigenvalues; the
// separatrices file its two 1D separatrices.
namespace {
// v = A (x - x0), A = [[0.5, 1, 0], [-1, 0.5, 0], [0, 0, -2]], x0 off-node.
const Vec3 kSpiralSaddleAt(0.13, 0.07, -0.05);
Eigen::Matrix3d spiralSaddle2Matrix() {
  Eigen::Matrix3d a;
  a << 0.5, 1, 0, -1, 0.5, 0, 0, 0, -2;
  return a;
}
fluidviz::FieldSet spiralSaddle2Field(fluidviz::Grid& g) {
  g.dims = {12, 11, 10};
  g.origin = {-1.0, -1.0, -1.0};
  g.spacing = {0.2, 0.21, 0.22};
  const Eigen::Matrix3d a = spiralSaddle2Matrix();
  fluidviz::VectorField v{"velocity", g, {}};
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        v.values.push_back(a * (g.position(i, j, k) - kSpiralSaddleAt));
  fluidviz::FieldSet set;
  set.grid = g;
  set.add(v);
  return set;
}

/// Pixels of the picture above `rows` whose red exceeds green and blue by 20 (the unstable
/// surface's tint), and whose blue exceeds red and green by 20.
std::pair<int, int> reddishAndBluish(const fluidviz::RgbaImage& img, int rows) {
  int red = 0, blue = 0;
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = &img.pixels[4 * (std::size_t(y) * img.width + x)];
      red += p[0] > p[1] + 20 && p[0] > p[2] + 20;
      blue += p[2] > p[0] + 20 && p[2] > p[1] + 20;
    }
  return {red, blue};
}
}  // namespace

TEST_F(TopologyCliTest, CriticalPointsOfA3DField) {
  fluidviz::Grid g;
  const std::string vti = field(spiralSaddle2Field(g));
  const Vec3 x0 = kSpiralSaddleAt;
  const Eigen::Matrix3d a = spiralSaddle2Matrix();
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--png", out("p.png"),
                  "--width", "400"},
                 "--width: file " + vti + " array 'velocity' is 3D (12x11x10 nodes");
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--png", out("p.png"),
                  "--turntable", "8"},
                 "--turntable: the topology picture is one view");
  const Result r =
      run({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--csv", out("p.csv")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1 critical points (spiral_saddle_2 1), index sum -1 (3D)"),
            std::string::npos)
      << r.out;
  // The 2-saddle's stable axis is z (eigenvalue -2): two lines traced backward from z0 to the
  // z faces.
  vtkSmartPointer<vtkPolyData> seps = fluidviz::readVtp(out("p_separatrices.vtp"));
  ASSERT_EQ(seps->GetNumberOfLines(), 2);
  for (vtkIdType c = 0; c < 2; ++c) {
    EXPECT_EQ(seps->GetCellData()->GetArray("outgoing")->GetTuple1(c), 0);
    EXPECT_EQ(seps->GetCellData()->GetArray("origin")->GetTuple1(c), 0);
  }
  double bounds[6];
  seps->GetBounds(bounds);
  EXPECT_NEAR(bounds[0], x0.x(), 1e-6);
  EXPECT_NEAR(bounds[1], x0.x(), 1e-6);
  EXPECT_NEAR(bounds[2], x0.y(), 1e-6);
  EXPECT_NEAR(bounds[3], x0.y(), 1e-6);
  EXPECT_NEAR(bounds[4], g.origin[2], 1e-6);
  EXPECT_NEAR(bounds[5], g.origin[2] + 9 * g.spacing[2], 1e-6);
  // Its separating surface is the unstable plane z = z0 of the pair 0.5 +- i (traced forward),
  // grown to the four side faces of the box.
  vtkSmartPointer<vtkPolyData> surface = fluidviz::readVtp(out("p_surfaces.vtp"));
  ASSERT_GT(surface->GetNumberOfPolys(), 100);
  EXPECT_EQ(surface->GetCellData()->GetArray("outgoing")->GetRange()[0], 1);
  EXPECT_EQ(surface->GetCellData()->GetArray("origin")->GetRange()[1], 0);
  EXPECT_EQ(surface->GetFieldData()->GetArray("surface_end")->GetTuple1(0),
            static_cast<int>(fluidviz::topology::SurfaceEnd::front_ended));
  surface->GetBounds(bounds);
  EXPECT_NEAR(bounds[0], g.origin[0], 1e-6);
  EXPECT_NEAR(bounds[1], g.origin[0] + 11 * g.spacing[0], 1e-6);
  EXPECT_NEAR(bounds[2], g.origin[1], 1e-6);
  EXPECT_NEAR(bounds[3], g.origin[1] + 10 * g.spacing[1], 1e-6);
  EXPECT_NEAR(bounds[4], x0.z(), 1e-9);
  EXPECT_NEAR(bounds[5], x0.z(), 1e-9);
  EXPECT_NE(r.out.find("(1 separating surfaces, "), std::string::npos) << r.out;
  const std::vector<std::string> csv = lines(out("p.csv"));
  ASSERT_EQ(csv.size(), 2u);
  EXPECT_EQ(csv[0],
            "x,y,z,type,index,morse,det,trace,index_measured,cluster_size,eigenvalue1_re,"
            "eigenvalue1_im,eigenvalue2_re,eigenvalue2_im,eigenvalue3_re,eigenvalue3_im");
  std::stringstream row(csv[1]);
  std::vector<std::string> cells;
  for (std::string c; std::getline(row, c, ',');) cells.push_back(c);
  ASSERT_EQ(cells.size(), 16u);
  // The interpolant reproduces the linear field: the zero to round-off (10 significant digits
  // written), det A = -2 (0.25 + 1) = -2.5, trace -1, eigenvalues 0.5 +- i, -2.
  EXPECT_NEAR(std::stod(cells[0]), x0.x(), 1e-9);
  EXPECT_NEAR(std::stod(cells[1]), x0.y(), 1e-9);
  EXPECT_NEAR(std::stod(cells[2]), x0.z(), 1e-9);
  EXPECT_EQ(cells[3], "spiral_saddle_2");
  EXPECT_EQ(cells[4], "-1");
  EXPECT_EQ(cells[5], "1");
  EXPECT_NEAR(std::stod(cells[6]), -2.5, 1e-9);
  EXPECT_NEAR(std::stod(cells[7]), -1.0, 1e-9);
  EXPECT_EQ(cells[8], "1");
  EXPECT_EQ(cells[9], "1");
  EXPECT_NEAR(std::stod(cells[10]), 0.5, 1e-9);
  EXPECT_NEAR(std::abs(std::stod(cells[11])), 1.0, 1e-9);
  EXPECT_NEAR(std::stod(cells[14]), -2.0, 1e-9);
  EXPECT_EQ(std::stod(cells[15]), 0.0);

  vtkSmartPointer<vtkPolyData> points = fluidviz::readVtp(out("p.vtp"));
  ASSERT_EQ(points->GetNumberOfPoints(), 1);
  double p[3];
  points->GetPoint(0, p);
  EXPECT_NEAR((Vec3(p[0], p[1], p[2]) - x0).norm(), 0.0, 1e-12);
  auto* type = vtkStringArray::SafeDownCast(points->GetPointData()->GetAbstractArray("type"));
  ASSERT_NE(type, nullptr);
  EXPECT_EQ(type->GetValue(0), "spiral_saddle_2");
  EXPECT_EQ(points->GetPointData()->GetArray("index")->GetTuple1(0), -1);
  vtkDataArray* jacobian = points->GetPointData()->GetArray("jacobian");
  ASSERT_NE(jacobian, nullptr);
  ASSERT_EQ(jacobian->GetNumberOfComponents(), 9);
  for (int c = 0; c < 9; ++c) EXPECT_NEAR(jacobian->GetComponent(0, c), a(c / 3, c % 3), 1e-9);
  ASSERT_NE(points->GetPointData()->GetArray("eigenvalues_real"), nullptr);
  EXPECT_NEAR(points->GetPointData()->GetArray("eigenvalues_real")->GetComponent(0, 2), -2.0, 1e-9);
}

// The 3D picture of the spiral 2-saddle: its sphere, two blue stable separatrices along z and
// its unstable plane as a translucent red sheet across the box. Without separatrices the red
// and nearly all the blue go: the counts measure what is drawn (measured: see the printout).
TEST_F(TopologyCliTest, PictureOfA3DField) {
  fluidviz::Grid g;
  const std::string vti = field(spiralSaddle2Field(g));
  const auto picture = [&](const std::string& name, bool separatrices) {
    std::vector<std::string> args = {"topology", vti, "-a", "velocity", "-o", out(name + ".vtp"),
                                     "--png", out(name + ".png"), "--size", "400x300"};
    if (!separatrices) args.push_back("--no-separatrices");
    const Result r = run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return fluidviz::testing::readPngImage(out(name + ".png"));
  };
  const fluidviz::RgbaImage with = picture("with", true), without = picture("without", false);
  ASSERT_EQ(with.width, 400);
  ASSERT_GT(with.height, 300);  // the legend strip below the 400 x 300 view
  const auto [red, blue] = reddishAndBluish(with, 300);
  const auto [redWithout, blueWithout] = reddishAndBluish(without, 300);
  std::printf("3D picture: reddish %d, bluish %d px; without separatrices %d, %d\n", red, blue,
              redWithout, blueWithout);
  EXPECT_GT(red, 4000);  // the sheet spans the 2.2 x 2.1 box: a large part of the view
  EXPECT_LT(redWithout, 50);
  EXPECT_GT(blue, blueWithout + 100);  // the two stable lines
  if (const char* keep = std::getenv("FLUIDVIZ_KEEP_PICTURE"))
    fs::copy_file(out("with.png"), keep, fs::copy_options::overwrite_existing);
  fs::remove_all(dir_ / "out");
  fs::create_directories(dir_ / "out");
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--slice", "z=4",
                  "--azimuth", "40"},
                 "--azimuth: the 3D topology picture's flag");
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--slice", "z=4",
                  "--surfaces", out("s.vtp")},
                 "--surfaces: separating surfaces exist for 3D fields only");
}

TEST_F(TopologyCliTest, BadInputNamesFileArrayOrKeyAndWritesNothing) {
  fluidviz::FieldSet set = cellularFlow();
  const std::string vti = field(set);
  const std::string missing = (dir_ / "nope.vti").string();
  expectBadInput({"topology", missing, "-a", "velocity", "-o", out("p.vtp")}, missing);
  expectBadInput({"topology", vti, "-a", "vorticity", "-o", out("p.vtp")},
                 "no point-data array 'vorticity'; arrays present: velocity(3), speed(1)");
  expectBadInput({"topology", vti, "-a", "speed", "-o", out("p.vtp")}, "'speed' has 1 component");
  expectBadInput({"topology", vti, "-o", out("p.vtp")}, "needs -a ARRAY");
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--set",
                  "separating_surface.max_edge=20"},
                 "separating_surface.max_edge");
  expectBadInput({"topology", vti, "-a", "velocity"}, "needs -o POINTS.vtp");
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--set",
                  "cluster_radius=20"},
                 "key 'cluster_radius' is 20");
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--set", "clustr=1"},
                 "'clustr' is not a known key");
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--glyph-size", "1"},
                 "--glyph-size is 1 px, outside the allowed range [4, 100]");
  expectBadInput({"topology", vti, "-a", "velocity", "-o", out("p.vtp"), "--png",
                  (dir_ / "no_such_dir" / "p.png").string()},
                 "folder");

  set.vectors[0].values[set.grid.index(12, 34)].y() = std::nan("");
  const std::string nan = field(set, "nan.vti");
  // Issue 15: a NaN node is masked (no critical points in its cells), no longer refused.
  const Result masked = run({"topology", nan, "-a", "velocity", "-o", out("p.vtp")});
  EXPECT_EQ(masked.code, 0) << masked.err;
}

TEST_F(TopologyCliTest, HelpListsOutputsAndCsvColumns) {
  const Result r = run({"topology", "--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("x,y,z,type,index,morse,det,trace,hyperbolic,elliptic,parabolic"),
            std::string::npos);
  EXPECT_NE(run({"--help"}).out.find("fluidviz topology FIELD.vti"), std::string::npos);
}

// fluidviz sweep end to end on a small four-roll mill (32 nodes, two runs).
TEST_F(TopologyCliTest, SweepWritesTablesPicturesAndDiagram) {
  const fs::path scene = dir_ / "four.json";
  std::ofstream(scene) << R"({"name": "four", "lbm": {"domain_size": [1, 1], "resolution": 32,
      "reynolds": 10, "rollers": [
        {"center": [0.25, 0.25], "radius": 0.15, "angular_velocity": 1.0},
        {"center": [0.75, 0.25], "radius": 0.15, "angular_velocity": -1.0},
        {"center": [0.25, 0.75], "radius": 0.15, "angular_velocity": -1.0},
        {"center": [0.75, 0.75], "radius": 0.15, "angular_velocity": 1.0}],
      "end_time": 10, "steady_tolerance": 1e-6}, "output": {"images": []}})";
  const std::string sweepDir = out("sweep");
  const Result r = run({"sweep", scene.string(), "--param", "lbm.rollers.0.angular_velocity",
                        "--from", "1", "--to", "2", "--steps", "2", "-o", sweepDir,
                        "--underlay", "speed"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("sweep 2/2: lbm.rollers.0.angular_velocity = 2: "), std::string::npos)
      << r.err;
  for (const char* f : {"four_bifurcation.csv", "four_bifurcation.png", "four_step_00_topology.png",
                        "four_step_01_topology.png", "step_01/four_critical_points.csv"})
    EXPECT_TRUE(fs::exists(fs::path(sweepDir) / f)) << f;
  const std::vector<std::string> csv = lines(fs::path(sweepDir) / "four_bifurcation.csv");
  ASSERT_GE(csv.size(), 3u);
  EXPECT_EQ(csv[0], "step,parameter,x,y,z,type,index,morse,det,trace,hyperbolic,elliptic,parabolic");
  // At the symmetric speed the saddle sits at the centre of the box (on the lattice's mirror
  // lines: exactly, up to rounding).
  bool centreSaddle = false;
  for (std::size_t k = 1; k < csv.size(); ++k)
    if (csv[k].rfind("0,1,0.5,0.5,0,saddle,-1,1,", 0) == 0) centreSaddle = true;
  EXPECT_TRUE(centreSaddle);
}

TEST_F(TopologyCliTest, SweepRejectsBadArgumentsBeforeRunning) {
  const std::string scene = std::string(FLUIDVIZ_SOURCE_DIR) + "/examples/six_roll_mill.json";
  const std::string o = out("sweep");
  expectBadInput({"sweep", scene, "--param", "lbm.viscosity", "--from", "0.01", "--to", "0.02",
                  "--steps", "0", "-o", o},
                 "--steps is 0; allowed: a whole number from 1 to 1000");
  expectBadInput({"sweep", scene, "--from", "1", "--to", "2", "--steps", "2", "-o", o},
                 "needs --param");
  expectBadInput({"sweep", scene, "--param", "lbm.rollers.0.speed", "--from", "1", "--to", "2",
                  "--steps", "2", "-o", o},
                 "key 'lbm.rollers[0].speed' is not a known key");
  expectBadInput({"sweep", scene, "--param", "lbm.viscosity", "--from", "0.01", "--to", "100",
                  "--steps", "2", "-o", o},
                 "tau");
  expectBadInput({"sweep", scene, "--param", "lbm.viscosity", "--from", "0.01", "--to", "0.02",
                  "--steps", "2", "-o", o, "--topology", "loop_radius=0"},
                 "--topology: key 'loop_radius' is 0");
  EXPECT_EQ(run({"sweep", "--help"}).code, 0);
}
