// Defect 4 of issue 15: a solid body (velocity 0 inside it, or NaN) must not clutter topology.
// Potential flow past a circular cylinder of radius R in a uniform stream U (e.g. Batchelor 1967,
// section 6.6): u_r = U (1 - R^2/r^2) cos(theta), u_theta = -U (1 + R^2/r^2) sin(theta) for r >= R,
// with its only zeros the front and rear stagnation points (-R, 0) and (R, 0) on the circle.
// Before the masks, velocity 0 inside gave a cloud of 'unknown' points in the degenerate cells and
// missed the rear stagnation point; NaN inside was refused.
#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

#include "apps/fluidviz/Commands.h"
#include "fieldviz/core/FieldSlices.h"
#include "fieldviz/core/PointMask.h"
#include "fieldviz/core/RestingWalls.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "tests/apps/fluidviz/CliTestSupport.h"

namespace fs = std::filesystem;
using namespace fluidviz;
using fluidviz::test::Result;
using fluidviz::test::run;

namespace {

constexpr double kRadius = 1.0, kSpacing = 0.1;

// Cartesian velocity of the potential flow, `inside` for r < R.
Vec3 cylinderFlow(double x, double y, double inside) {
  const double r2 = x * x + y * y;
  if (r2 < kRadius * kRadius) return Vec3::Constant(inside);
  const double a = kRadius * kRadius / (r2 * r2);
  // u = U (1 - R^2 (x^2 - y^2) / r^4), v = -U R^2 2xy / r^4 (U = 1)
  return {1.0 - a * (x * x - y * y), -a * 2 * x * y, 0.0};
}

FieldSet cylinderField(double inside) {
  FieldSet set;
  set.grid.dims = {61, 41, 1};
  set.grid.origin = {-3.0, -2.0, 0.0};
  set.grid.spacing = {kSpacing, kSpacing, 1.0};
  VectorField v{"velocity", set.grid, {}};
  for (int j = 0; j < set.grid.dims[1]; ++j)
    for (int i = 0; i < set.grid.dims[0]; ++i) {
      const Vec3 p = set.grid.position(i, j);
      v.values.push_back(cylinderFlow(p.x(), p.y(), inside));
    }
  set.add(v);
  return set;
}

struct Point {
  double x, y;
  std::string type;
};

std::vector<Point> readCsv(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  std::vector<Point> points;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string x, y, z, type;
    std::getline(s, x, ','), std::getline(s, y, ','), std::getline(s, z, ','),
        std::getline(s, type, ',');
    points.push_back({std::stod(x), std::stod(y), type});
  }
  return points;
}

class MaskedTopology : public ::testing::TestWithParam<double> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fluidviz_masked_topology_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

}  // namespace

TEST_P(MaskedTopology, CylinderGivesFrontAndRearStagnationPointsAndNothingInside) {
  const fs::path vti = dir_ / "cylinder.vti", csv = dir_ / "points.csv";
  writeVti(cylinderField(GetParam()), vti);
  const Result r = run({"topology", vti.string(), "-a", "velocity", "-o", (dir_ / "p.vtp").string(),
                        "--csv", csv.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Point> points = readCsv(csv);
  // Zero inside: a wall at rest, whose points are where the flow along it changes sign
  // (WallPoints.h), an attachment at the front and a separation at the rear. NaN inside: no
  // wall known, the field continued one node into the body (withWallLayerContinued) holds the
  // stagnation points. Either way within half a cell of (-R, 0) and (R, 0).
  const double tol = 0.5 * kSpacing;
  int front = 0, rear = 0;
  for (const Point& p : points) {
    const double r2 = std::hypot(p.x, p.y);
    EXPECT_GE(r2, kRadius - tol) << "point inside the cylinder: " << p.x << ", " << p.y << " "
                                 << p.type;
    front += std::hypot(p.x + kRadius, p.y) <= tol;
    rear += std::hypot(p.x - kRadius, p.y) <= tol;
  }
  EXPECT_EQ(front, 1) << r.out;
  EXPECT_EQ(rear, 1) << r.out;
  EXPECT_EQ(points.size(), 2u) << r.out;
}

INSTANTIATE_TEST_SUITE_P(ZeroOrNaNInside, MaskedTopology,
                         ::testing::Values(0.0, std::numeric_limits<double>::quiet_NaN()),
                         [](const auto& info) {
                           return std::isnan(info.param) ? std::string("NaN") : std::string("Zero");
                         });

// Real data (tests/data/vtkdata/README.md): the office's z layer 5 cuts a zero-velocity block
// (furniture; |v| about 1e-17 of max|v| after resampling). Before the masks it held an 'unknown'
// point and a cusp inside the block. Now no point lies deeper in it than one cell diagonal from
// the nearest fluid node (points on its wall layer are stagnation points of the flow along it).
TEST(MaskedTopologyRealData, OfficeHasNoCriticalPointInsideTheZeroVelocityBlock) {
  const fs::path dir = fs::temp_directory_path() / ("fluidviz_office_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = std::string(FLUIDVIZ_TEST_DATA_DIR) + "/vtkdata/office.binary.vtk";
  const Result r = run({"topology", file, "-a", "vectors", "--slice", "z=5", "-o",
                        (dir / "p.vtp").string(), "--csv", (dir / "p.csv").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Point> points = readCsv(dir / "p.csv");
  fs::remove_all(dir);
  const VectorField layer =
      sliceAxis(vectorFieldFrom(readImageData(file), "vectors", "office"), 2, 5);
  const PointMask solid = solidNodes(layer, SolidParams{});
  ASSERT_GE(maskedCount(solid), 9u) << "the block is found as a solid";
  const Grid& g = layer.grid;
  const double diagonal = std::hypot(g.spacing[0], g.spacing[1]);
  ASSERT_FALSE(points.empty());
  for (const Point& p : points) {
    double nearestFluid = std::numeric_limits<double>::infinity();
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        if (!solid[g.index(i, j)])
          nearestFluid = std::min(nearestFluid, std::hypot(g.position(i, j).x() - p.x,
                                                           g.position(i, j).y() - p.y));
    EXPECT_LE(nearestFluid, diagonal + 1e-9) << p.type << " at " << p.x << ", " << p.y;
  }
}

// Real data: PC-MRI of a carotid (tests/data/vtkdata/README.md), whose velocity outside the
// vessels is noise; `--mask 'scalars>150'` keeps the vessels of its magnitude image. The edge of
// such a threshold is no wall (the flow goes on past it), so no zero may be made up there: every
// point lies in a cell with four fluid corners. With the wall layer continued from the fluid at
// every mask edge, as for solids, the layer gave 12 degenerate points on the vessels' edges.
TEST(MaskedTopologyRealData, CarotidThresholdMaskKeepsPointsOffTheVesselEdges) {
  const fs::path dir = fs::temp_directory_path() / ("fluidviz_carotid_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = std::string(FLUIDVIZ_TEST_DATA_DIR) + "/vtkdata/carotid_bifurcation.vtk";
  const Result r = run({"topology", file, "-a", "vectors", "--slice", "z=12", "--mask",
                        "scalars>150", "-o", (dir / "p.vtp").string(), "--csv",
                        (dir / "p.csv").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Point> points = readCsv(dir / "p.csv");
  fs::remove_all(dir);
  const ScalarField magnitude =
      sliceAxis(scalarFieldFrom(readImageData(file), "scalars", "carotid"), 2, 12);
  const Grid& g = magnitude.grid;
  ASSERT_FALSE(points.empty());
  for (const Point& p : points) {
    const int i = static_cast<int>(std::floor((p.x - g.origin[0]) / g.spacing[0]));
    const int j = static_cast<int>(std::floor((p.y - g.origin[1]) / g.spacing[1]));
    for (int dj = 0; dj <= 1; ++dj)
      for (int di = 0; di <= 1; ++di)
        EXPECT_GT(magnitude.values[g.index(std::min(i + di, g.dims[0] - 1),
                                            std::min(j + dj, g.dims[1] - 1))],
                  150.0)
            << p.type << " at " << p.x << ", " << p.y << " touches the masked region";
  }
}

TEST(MaskedTopologyRealData, ThresholdMaskThatIsNotANumberNamesTheAllowedForms) {
  const std::string file = std::string(FLUIDVIZ_TEST_DATA_DIR) + "/vtkdata/carotid_bifurcation.vtk";
  const Result r = run({"lic", file, "-a", "vectors", "--slice", "z=12", "--mask", "scalars>x",
                        "-o", (fs::temp_directory_path() / "never.png").string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--mask is 'scalars>x'; allowed: ARRAY (nonzero = fluid), ARRAY>V or "
                       "ARRAY<V"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(fs::temp_directory_path() / "never.png"));
}

// The sides a snapshot names as walls at rest (fluidviz_resting_walls, RestingWalls.h) are read
// as the file's own data: a word that names no side is bad input, named with the allowed ones,
// and nothing is written.
TEST_P(MaskedTopology, RestingSidesThatNameNoSideAreRefused) {
  const fs::path vti = dir_ / "sides.vti", out = dir_ / "p.vtp";
  FileInfo info;
  info.strings = {{kRestingSidesFieldData, "x_min left"}};
  writeVti(cylinderField(GetParam()), PointMask{}, vti, info);
  const Result r = run({"topology", vti.string(), "-a", "velocity", "-o", out.string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("fluidviz_resting_walls names 'left'; allowed: x_min, x_max, y_min, "
                       "y_max"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(vti.string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}
