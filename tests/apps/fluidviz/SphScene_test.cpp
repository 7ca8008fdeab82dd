// SPH scenes end to end through the fluidviz command, in-process (fluidviz::app::dispatch):
//   - a tiny 2D dam break (Martin & Moyce geometry, a = 0.2 m, a / dx = 10: 200 particles,
//     T = t sqrt(2 g / a) = 2 at the end): exit 0, the .pvd lists the 4 snapshots at
//     end_time k / 4, the last .vtp holds 200 particles with vertex cells and the arrays
//     velocity (3 components), density, pressure, speed (1), all finite; its water front equals
//     the solver's own run to dx / 4 (measured 6.5e-8 m: only the snapshot stops differ) and lies between 2 and Ritter's
//     dry-bed bound Z < 1 + 2T = 5 (measured Z = 2.46);
//   - bad SPH keys: exit 2, the message names "sph.<key>", nothing written;
//   - instability (speed_of_sound 4 m/s, about 2x the flow speed, from zero pressure): exit 3,
//     the message says step, particle and "density error"; the .pvd lists exactly the complete
//     snapshots written before, none with a NaN;
//   - a fixed time_step past the CFL limit: the warning is printed.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "apps/fluidviz/Commands.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "solvers/sph/SphSolver.h"

namespace fs = std::filesystem;
using fluidviz::app::dispatch;

namespace {

using fluidviz::test::Result;
using fluidviz::test::run;

constexpr double kA = 0.2, kSurgeSpacing = 0.02, kEnd = 0.202;  // m, m, s (T = 2.0)

class SphSceneTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_sph_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string writeScene(int snapshots = 4) {
    const fs::path p = dir_ / "dam.json";
    std::ofstream(p) << R"({ "name": "dam", "solver": "sph",
      "sph": { "dimension": 2, "model": "B", "particle_spacing": 0.02, "speed_of_sound": 19.8,
               "alpha": 0.1, "domain_upper": [0.8, 0.6, 0], "walls": {"y_max": "open"},
               "fluid_blocks": [{"lower": [0, 0, 0], "upper": [0.2, 0.4, 0]}],
               "end_time": 0.202 },
      "output": { "snapshots": )"
                     << snapshots << R"(, "images": [{"field": "speed", "width": 320, "height": 240}] } })";
    return p.string();
  }
  fs::path out() const { return dir_ / "out"; }

  // (time, file) of each DataSet of the .pvd.
  std::vector<std::pair<double, std::string>> pvdEntries() const {
    std::ifstream in(out() / "dam.pvd");
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    std::vector<std::pair<double, std::string>> entries;
    const std::regex re(R"re(timestep="([^"]+)"[^>]*file="([^"]+)")re");
    for (auto it = std::sregex_iterator(s.begin(), s.end(), re); it != std::sregex_iterator(); ++it)
      entries.emplace_back(std::stod((*it)[1]), (*it)[2]);
    return entries;
  }

  fs::path dir_;
};

bool allFinite(vtkPolyData* poly) {
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
    const double* x = poly->GetPoint(i);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) return false;
  }
  vtkPointData* pd = poly->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a) {
    vtkDataArray* arr = pd->GetArray(a);
    for (vtkIdType t = 0; t < arr->GetNumberOfTuples(); ++t)
      for (int c = 0; c < arr->GetNumberOfComponents(); ++c)
        if (!std::isfinite(arr->GetComponent(t, c))) return false;
  }
  return true;
}

TEST_F(SphSceneTest, DamBreakWritesSeriesArraysAndPicture) {
  const Result r = run({"run", writeScene(), "-o", out().string()});
  ASSERT_EQ(r.code, 0) << r.err << r.out;

  const auto entries = pvdEntries();
  ASSERT_EQ(entries.size(), 5u);  // t = 0 and the 4 snapshots (issue 16)
  for (std::size_t k = 0; k < entries.size(); ++k) {
    EXPECT_NEAR(entries[k].first, kEnd * k / 4, 1e-12);
    EXPECT_TRUE(fs::exists(out() / entries[k].second)) << entries[k].second;
  }
  auto last = fluidviz::readVtp(out() / entries.back().second);
  ASSERT_EQ(last->GetNumberOfPoints(), 200);  // (0.2 / 0.02) x (0.4 / 0.02)
  EXPECT_EQ(last->GetNumberOfVerts(), 200);   // one vertex cell each: ParaView draws them
  vtkPointData* pd = last->GetPointData();
  const std::vector<std::pair<std::string, int>> arrays = {
      {"velocity", 3}, {"density", 1}, {"pressure", 1}, {"speed", 1}};
  for (const auto& [name, components] : arrays) {
    ASSERT_NE(pd->GetArray(name.c_str()), nullptr) << name;
    EXPECT_EQ(pd->GetArray(name.c_str())->GetNumberOfComponents(), components) << name;
  }
  EXPECT_TRUE(allFinite(last));

  // The same run in-process: the file holds the solver's final state.
  fluidviz::sph::SphParams p;
  p.particle_spacing = kSurgeSpacing;
  p.speed_of_sound = 19.8;
  p.alpha = 0.1;
  p.domain_upper = {0.8, 0.6, 0};
  p.walls.y_max = fluidviz::sph::SphSide::open;
  p.fluid_blocks = {{{0, 0, 0}, {kA, 2 * kA, 0}}};
  p.end_time = kEnd;
  fluidviz::sph::SphSolver solver(p);
  solver.run();
  double frontSolver = 0, frontFile = 0;
  for (const auto& x : solver.state().x) frontSolver = std::max(frontSolver, x[0]);
  for (vtkIdType i = 0; i < last->GetNumberOfPoints(); ++i)
    frontFile = std::max(frontFile, last->GetPoint(i)[0]);
  // The scene's steps are cut at the 4 snapshot times, so the runs differ in rounding only
  // (measured 6.5e-8 m); a quarter spacing would mean the file is not the solver's state.
  EXPECT_NEAR(frontFile, frontSolver, 0.25 * kSurgeSpacing);
  const double T = kEnd * std::sqrt(2 * 9.81 / kA), Z = (frontFile + 0.5 * kSurgeSpacing) / kA;
  EXPECT_GT(Z, 2.0);
  EXPECT_LT(Z, 1 + 2 * T);  // Ritter's dry-bed bound
  std::printf("[measured] tiny dam break: Z = %.3f at T = %.3f (Ritter bound %.3f)\n", Z, T,
              1 + 2 * T);

  // Boundary once, picture, effective scene.
  auto boundary = fluidviz::readVtp(out() / "dam_boundary.vtp");
  EXPECT_EQ(static_cast<std::size_t>(boundary->GetNumberOfPoints()),
            solver.boundaryParticles().size());
  EXPECT_TRUE(fs::exists(out() / "dam_speed.png"));
  EXPECT_TRUE(fs::exists(out() / "dam_scene.json"));
}

TEST_F(SphSceneTest, BadSphKeysExitTwoNamingTheKey) {
  const std::string scene = writeScene();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"sph.particle_spacing=-0.1", "sph.particle_spacing"},
      {"sph.model=\"C\"", "sph.model"},
      {"sph.fluid_blocks=[{\"lower\":[0,0,0],\"upper\":[2,0.4,0]}]", "sph.fluid_blocks[0]"},
      {"sph.cfl_factor=2", "sph.cfl_factor"}};
  for (const auto& [set, key] : cases) {
    const Result r = run({"run", scene, "-o", out().string(), "--set", set});
    EXPECT_EQ(r.code, 2) << set << ": " << r.err;
    EXPECT_NE(r.err.find(key), std::string::npos) << set << ": " << r.err;
    EXPECT_FALSE(fs::exists(out())) << set << ": bad input must not write anything";
  }
  const Result lic = run({"run", scene, "-o", out().string(), "--set", "output.lic=[{}]"});
  EXPECT_EQ(lic.code, 2) << lic.err;
  EXPECT_NE(lic.err.find("output.lic"), std::string::npos) << lic.err;
  EXPECT_FALSE(fs::exists(out()));
  // Grid-only picture fields are refused before the run, not after it.
  const Result vort =
      run({"run", scene, "-o", out().string(), "--set", "output.images=[{\"field\": \"vorticity\"}]"});
  EXPECT_EQ(vort.code, 2) << vort.err;
  EXPECT_NE(vort.err.find("key 'output.images[0].field' is \"vorticity\", not available for solver sph"),
            std::string::npos)
      << vort.err;
  EXPECT_FALSE(fs::exists(out()));
}

TEST_F(SphSceneTest, InstabilityExitsThreeAndKeepsCompleteSnapshots) {
  const Result r = run({"run", writeScene(20), "-o", out().string(), "--set",
                        "sph.speed_of_sound=4", "--set", "sph.initial_pressure=\"zero\""});
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("SPH unstable at step"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("density error"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("speed_of_sound"), std::string::npos) << r.err;
  const auto entries = pvdEntries();
  ASSERT_GE(entries.size(), 1u);   // measured: 5 of 20 (unstable at t = 0.052 s)
  ASSERT_LT(entries.size(), 20u);
  for (const auto& [time, file] : entries) {
    ASSERT_TRUE(fs::exists(out() / file)) << file;
    auto poly = fluidviz::readVtp(out() / file);
    EXPECT_EQ(poly->GetNumberOfPoints(), 200) << file;
    EXPECT_TRUE(allFinite(poly)) << file;
  }
  // No file beyond those listed.
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(out() / "dam")) files += e.path().extension() == ".vtp";
  EXPECT_EQ(files, entries.size());
  EXPECT_FALSE(fs::exists(out() / "dam_speed.png"));
}

TEST_F(SphSceneTest, FixedStepPastTheLimitIsWarned) {
  const Result r = run({"run", writeScene(1), "-o", out().string(), "--set",
                        "sph.time_step=0.0005", "--set", "output.images=[]"});
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string all = r.out + r.err;
  EXPECT_NE(all.find("warning: time_step 0.0005 s exceeds the stable limit"), std::string::npos)
      << all;
}

}  // namespace
