// What a run's snapshots hold and which it writes (issue 16, defects 2, 3 and 9):
//   - an LBM snapshot (2D, one roller turning at 1 rad/s in a 1 m box) holds velocity, density,
//     speed, pressure = c_s^2 (rho - rho0) (dx/dt)^2 in Pa (to 1e-12 relative), vorticity and the
//     unsigned char vtkValidPointMask: 0 on exactly the solver's solid nodes (the roller), 1
//     elsewhere; the rigid rotation inside the roller has vorticity 2 omega = 2 1/s (1e-9);
//   - a 3D LBM snapshot (lid-driven box) holds the vorticity vector and q_criterion of its own
//     velocity (1e-12); of a rigid rotation at rate W they are (0, 0, 2 W) and W^2 (1e-12);
//   - an SPH snapshot holds mass and smoothing_length, the solver's constants;
//   - every series starts at t = 0: n + 1 entries for n snapshots, the last at the end time;
//     snapshots = 0 writes no .pvd (a stale one is removed); a run stopping early at steady state
//     lists fewer and says so in its log.
#include <cmath>
#include <filesystem>
#include <regex>

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "pipeline/FlowFields.h"
#include "solvers/lbm/LbmSolver.h"
#include "solvers/sph/SphSolver.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz::test {
namespace {

// (time, file) of each DataSet of a .pvd.
std::vector<std::pair<double, std::string>> pvdEntries(const fs::path& pvd) {
  const std::string s = readText(pvd);
  std::vector<std::pair<double, std::string>> entries;
  const std::regex re(R"re(timestep="([^"]+)"[^>]*file="([^"]+)")re");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), re); it != std::sregex_iterator(); ++it)
    entries.emplace_back(std::stod((*it)[1]), (*it)[2]);
  return entries;
}

// A 1 m box, 24 nodes across, one roller of radius 0.2 m at the centre turning at 1 rad/s.
std::string rollerScene(int snapshots, double endTime = 0.5, const std::string& extra = "") {
  return R"({"name": "roller", "solver": "lbm",
    "lbm": {"domain_size": [1.0, 1.0], "resolution": 24, "viscosity": 0.01,
            "reference_length": 0.4, "lattice_velocity": 0.05,
            "rollers": [{"center": [0.5, 0.5], "radius": 0.2, "angular_velocity": 1.0}],
            "end_time": )" + std::to_string(endTime) + extra + R"(},
    "output": {"snapshots": )" + std::to_string(snapshots) + R"(, "images": []}})";
}

double value(vtkDataArray* a, vtkIdType n, int c = 0) { return a->GetComponent(n, c); }

class SnapshotContentTest : public TempDirTest {};

TEST_F(SnapshotContentTest, LbmSnapshotHoldsPressureVorticityAndSolidMask) {
  const SceneParams scene = sceneFromText(rollerScene(1));
  runInto(scene, "out");
  const auto entries = pvdEntries(dir_ / "out" / "roller.pvd");
  ASSERT_EQ(entries.size(), 2u);
  vtkSmartPointer<vtkImageData> image = readImageData(dir_ / "out" / entries.back().second);
  vtkPointData* pd = image->GetPointData();
  for (const char* name : {"velocity", "density", "speed", "pressure", "vorticity"})
    ASSERT_NE(pd->GetArray(name), nullptr) << name;
  auto* mask = vtkUnsignedCharArray::SafeDownCast(pd->GetArray("vtkValidPointMask"));
  ASSERT_NE(mask, nullptr) << "vtkValidPointMask must be an unsigned char array";

  const auto solver = lbm::createLbmSolver(scene.lbm);
  const lbm::LatticeUnits& u = solver->units();
  const Grid& g = solver->grid();
  ASSERT_EQ(image->GetNumberOfPoints(), static_cast<vtkIdType>(g.nodeCount()));
  const double c2 = u.dx * u.dx / (3.0 * u.dt * u.dt);
  int solid = 0, deepInside = 0;
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      const vtkIdType n = static_cast<vtkIdType>(g.index(i, j));
      const bool isSolid = solver->isSolid(i, j);
      solid += isSolid;
      EXPECT_EQ(mask->GetValue(n), isSolid ? 0 : 1) << i << ", " << j;
      const double rho = value(pd->GetArray("density"), n);
      EXPECT_NEAR(value(pd->GetArray("pressure"), n), c2 * (rho - u.density),
                  1e-12 * c2 * u.density);
      // Nodes whose 4 neighbours are solid too: the differences see the rigid rotation only.
      const bool inner = isSolid && solver->isSolid(i - 1, j) && solver->isSolid(i + 1, j) &&
                         solver->isSolid(i, j - 1) && solver->isSolid(i, j + 1);
      if (inner) {
        ++deepInside;
        EXPECT_NEAR(value(pd->GetArray("vorticity"), n), 2.0, 1e-9);
      }
    }
  EXPECT_GT(solid, 30);  // pi (0.2 / (1/24))^2 = 72 nodes
  EXPECT_GT(deepInside, 10);
}

TEST(FlowFields, RigidRotationHasVorticityTwiceTheRateAndQItsSquare) {
  // v = Omega x r about the z axis through (0.3, 0.2): J = [[0, -W, 0], [W, 0, 0], [0, 0, 0]],
  // linear, so central and one-sided differences are exact: curl v = (0, 0, 2 W), S = 0 and
  // Q = |Omega|^2 / 2 = W^2.
  constexpr double W = 1.7;
  VectorField v{"velocity", Grid{{5, 4, 3}, {0, 0, 0}, {0.1, 0.2, 0.3}}, {}};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i) {
        const Vec3 x = v.grid.position(i, j, k);
        v.values.push_back(Vec3(-W * (x.y() - 0.2), W * (x.x() - 0.3), 0.0));
      }
  const VectorField w = vorticityVector(v);
  const ScalarField q = qCriterion(v);
  for (std::size_t n = 0; n < v.values.size(); ++n) {
    EXPECT_NEAR((w.values[n] - Vec3(0, 0, 2 * W)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(q.values[n], W * W, 1e-12);
  }
  EXPECT_THROW(vorticityVector(sliceZ(v, 0)), std::invalid_argument);
}

TEST_F(SnapshotContentTest, Lbm3DSnapshotHoldsVorticityVectorAndQCriterion) {
  const SceneParams scene = sceneFromText(R"({"name": "box3d", "solver": "lbm",
    "lbm": {"lattice": "D3Q19", "domain_size": [1.0, 1.0], "domain_depth": 1.0,
            "resolution": 8, "reynolds": 10, "lattice_velocity": 0.1, "end_time": 0.5,
            "walls": {"y_max": {"type": "moving_wall", "velocity": [1.0, 0.0]}}},
    "output": {"snapshots": 1, "images": []}})");
  runInto(scene, "out");
  const auto entries = pvdEntries(dir_ / "out" / "box3d.pvd");
  ASSERT_EQ(entries.size(), 2u);
  const fs::path file = dir_ / "out" / entries.back().second;
  vtkSmartPointer<vtkImageData> image = readImageData(file);
  vtkDataArray* w = image->GetPointData()->GetArray("vorticity");
  vtkDataArray* q = image->GetPointData()->GetArray("q_criterion");
  ASSERT_NE(w, nullptr);
  ASSERT_NE(q, nullptr);
  EXPECT_EQ(w->GetNumberOfComponents(), 3);
  EXPECT_EQ(q->GetNumberOfComponents(), 1);
  // The arrays are those of the file's own velocity (FlowFields.h), and the lid stirs the box.
  const VectorField velocity = vectorFieldFrom(image, "velocity", file.string());
  const VectorField expectedW = vorticityVector(velocity);
  const ScalarField expectedQ = qCriterion(velocity);
  double largest = 0;
  for (vtkIdType n = 0; n < image->GetNumberOfPoints(); ++n) {
    EXPECT_NEAR(value(q, n), expectedQ.values[n], 1e-12 * (1 + std::abs(expectedQ.values[n])));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(value(w, n, c), expectedW.values[n][c], 1e-12);
    largest = std::max(largest, std::abs(value(w, n, 2)));
  }
  EXPECT_GT(largest, 0.1);  // 1/s: a lid at 1 m/s over 1/8 m cells
}

TEST_F(SnapshotContentTest, SphSnapshotHoldsMassAndSmoothingLength) {
  const SceneParams scene = sceneFromText(R"({"name": "tank", "solver": "sph",
    "sph": {"dimension": 2, "particle_spacing": 0.05, "smoothing_length_ratio": 2.0,
            "speed_of_sound": 20, "domain_upper": [0.5, 0.5, 0], "walls": {"y_max": "open"},
            "fluid_blocks": [{"lower": [0, 0, 0], "upper": [0.5, 0.25, 0]}], "end_time": 0.01},
    "output": {"snapshots": 1, "images": []}})");
  runInto(scene, "out");
  const auto entries = pvdEntries(dir_ / "out" / "tank.pvd");
  ASSERT_EQ(entries.size(), 2u);
  vtkSmartPointer<vtkPolyData> poly = readVtp(dir_ / "out" / entries.back().second);
  const sph::SphSolver solver(scene.sph);
  vtkDataArray* mass = poly->GetPointData()->GetArray("mass");
  vtkDataArray* h = poly->GetPointData()->GetArray("smoothing_length");
  ASSERT_NE(mass, nullptr);
  ASSERT_NE(h, nullptr);
  ASSERT_EQ(poly->GetNumberOfPoints(), static_cast<vtkIdType>(solver.fluidCount()));
  EXPECT_NEAR(solver.smoothingLength(), 0.1, 1e-12);  // 2.0 x 0.05 m
  for (vtkIdType n = 0; n < poly->GetNumberOfPoints(); ++n) {
    EXPECT_DOUBLE_EQ(value(mass, n), solver.particleMass());
    EXPECT_DOUBLE_EQ(value(h, n), solver.smoothingLength());
  }
}

TEST_F(SnapshotContentTest, SeriesStartsAtTimeZeroAndEndsAtTheEndTime) {
  runInto(sceneFromText(rollerScene(3)), "out");
  const auto entries = pvdEntries(dir_ / "out" / "roller.pvd");
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries.front().first, 0.0);
  EXPECT_EQ(entries.front().second, "roller/roller_0000.vti");
  EXPECT_NEAR(entries.back().first, 0.5, 0.05);  // the last step reaching the end time
  for (const auto& e : entries) EXPECT_TRUE(fs::exists(dir_ / "out" / e.second)) << e.second;
}

TEST_F(SnapshotContentTest, NoSnapshotsWritesNoSeries) {
  const fs::path pvd = dir_ / "out" / "roller.pvd";
  fs::create_directories(pvd.parent_path());
  fluidviz::testing::writeText(pvd, "<VTKFile/>");  // a stale series of an earlier run
  RunOptions options = optionsFor("out", false, -1);
  options.replace = true;  // else the earlier run's folder is refused (RunRecord_test.cpp)
  runScene(sceneFromText(rollerScene(0)), options);
  EXPECT_FALSE(fs::exists(pvd));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "roller" / "roller_0000.vti"));
}

TEST_F(SnapshotContentTest, RunStoppedAtSteadyStateSaysWhichSnapshotsItWrote) {
  // A roller in Stokes flow is steady long before the end time (measured: 1.2 s of 100 s).
  const SceneParams scene = sceneFromText(rollerScene(
      10, 100.0, R"(, "steady_tolerance": 1e-4, "check_interval": 50)"));
  const RunSummary summary = runInto(scene, "out");
  ASSERT_TRUE(summary.steady);
  const auto entries = pvdEntries(dir_ / "out" / "roller.pvd");
  ASSERT_GE(entries.size(), 2u);
  ASSERT_LT(entries.size(), 11u);
  EXPECT_EQ(entries.front().first, 0.0);
  EXPECT_NEAR(entries.back().first, summary.time, 1e-12);  // the last is the steady state
  const std::string expected = "wrote " + std::to_string(entries.size()) + " of 11 snapshots";
  EXPECT_NE(log_.str().find(expected), std::string::npos) << log_.str();
}

}  // namespace
}  // namespace fluidviz::test
