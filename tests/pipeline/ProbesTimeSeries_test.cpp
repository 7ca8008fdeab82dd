// output.probes and output.time_series through runScene:
// - the cavity example (examples/lid_driven_cavity.json at 64^2, run to steady state) writes its
//   centreline probes with their deviation from Ghia et al. 1982 below the tolerance of the
//   LidDrivenCavity Ghia test (kGhiaRmsTolerance; measured RMS 0.0034 for u), and a
//   kinetic-energy series that starts near 0 (fluid at rest) and settles;
// - a tiny dam break writes the surge front, Z = 1 at T = 0 exactly (front particle at
//   a - dx/2), T = t sqrt(2 g / a);
// - bad keys and files are refused before the run, naming the key and what is allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fieldviz/io/CsvTable.h"
#include "fieldviz/render/RgbaImage.h"
#include "solvers/lbm/validation/CavityGhia1982.h"
#include "tests/pipeline/PipelineTestSupport.h"
#include "tests/support/PngFiles.h"

namespace fluidviz {
namespace {

namespace fs = std::filesystem;

const fs::path kExamples = fs::path(FLUIDVIZ_SOURCE_DIR) / "examples";

class ProbesTimeSeries : public test::TempDirTest {
 protected:
  SceneParams example(const std::string& file, const std::vector<std::string>& overrides) {
    scene::json j = scene::readSceneFile(kExamples / file);
    for (const std::string& o : overrides) scene::applyOverride(j, o, file);
    return scene::readScene<SceneParams>(j, file);
  }
  RunSummary runExample(const SceneParams& scene, const std::string& file) {
    RunOptions options = optionsFor("out", false, -1);
    options.sceneFile = (kExamples / file).string();
    return runScene(scene, options);
  }
  std::string errorOf(const SceneParams& scene) {
    try {
      checkScene(scene, (kExamples / "lid_driven_cavity.json").string());
    } catch (const scene::SceneError& e) {
      return e.what();
    }
    return "no error";
  }
};

// The number after `label` in the CSV's comments ("rms 0.0031 m/s").
double commentNumber(const CsvTable& t, const std::string& label) {
  for (const std::string& c : t.comments) {
    const auto at = c.find(label);
    if (at != std::string::npos) return std::stod(c.substr(at + label.size()));
  }
  return std::nan("");
}

TEST_F(ProbesTimeSeries, CavityProbesMatchGhiaAndEnergySettles) {
  const SceneParams scene = example("lid_driven_cavity.json",
                                    {"lbm.resolution=64", "lbm.steady_tolerance=1e-6",
                                     "lbm.check_interval=1000", "output.snapshots=0",
                                     "output.images=[]"});
  const RunSummary run = runExample(scene, "lid_driven_cavity.json");
  EXPECT_TRUE(run.steady);
  const fs::path out = dir_ / "out";
  for (const std::string probe : {"u_vertical_centreline", "v_horizontal_centreline"}) {
    const fs::path csv = out / ("lid_driven_cavity_" + probe + ".csv");
    const CsvTable t = readCsv(csv);
    ASSERT_EQ(t.rowCount(), 101u) << probe;
    EXPECT_EQ(t.names.back(), probe[0] == 'u' ? "velocity_x (m/s)" : "velocity_y (m/s)");
    EXPECT_TRUE(std::isnan(t.columns[4].front()));  // the wall, outside the node-centred grid
    const double rms = commentNumber(t, "rms "), max = commentNumber(t, "max ");
    EXPECT_LT(rms, lbm::kGhiaRmsTolerance) << probe;
    EXPECT_GE(max, rms);
    EXPECT_EQ(commentNumber(t, "over "), 15) << probe;  // the 17 rows less the two on the walls
    EXPECT_NE(log_.str().find("probe " + probe + ": "), std::string::npos);
    const RgbaImage png = testing::readPngImage(out / ("lid_driven_cavity_" + probe + ".png"));
    EXPECT_EQ(png.width, 900);
    EXPECT_EQ(png.height, 600);
  }
  const CsvTable series = readCsv(out / "lid_driven_cavity_time_series.csv");
  ASSERT_EQ(series.names, (std::vector<std::string>{"t (s)", "kinetic_energy (J/m)",
                                                    "max_speed (m/s)"}));
  const auto& t = series.columns[0];
  const auto& energy = series.columns[1];
  ASSERT_GE(t.size(), 10u);
  EXPECT_EQ(t[0], 0.0);
  // At rest but for the lid's row, which carries part of the lid speed from the start.
  EXPECT_LT(energy[0], 0.05 * energy.back());
  // One sample per chunk at most (a chunk here: 976 steps, 1.53 s, longer than the interval).
  for (std::size_t n = 1; n < t.size(); ++n) EXPECT_GT(t[n], t[n - 1]);
  EXPECT_NEAR(t.back(), run.time, 1.6);
  // Steady: the last two samples agree to 0.1%; the fastest fluid is below the lid's 1 m/s.
  EXPECT_NEAR(energy[energy.size() - 2], energy.back(), 1e-3 * energy.back());
  EXPECT_GT(series.columns[2].back(), 0.5);
  EXPECT_LT(series.columns[2].back(), 1.0);
  for (const char* q : {"kinetic_energy", "max_speed"})
    EXPECT_TRUE(fs::exists(out / (std::string("lid_driven_cavity_") + q + ".png")));
}

TEST_F(ProbesTimeSeries, DamBreakWritesSurgeFront) {
  // a = 0.5 m, dx = a / 10; to t = 0.1 s (T = 0.63).
  const SceneParams scene = example("dam_break_2d.json",
                                    {"sph.particle_spacing=0.05", "sph.end_time=0.1",
                                     "output.snapshots=0", "output.images=[]",
                                     "output.free_surface=[]", "output.views=[]"});
  runExample(scene, "dam_break_2d.json");
  const CsvTable t = readCsv(dir_ / "out" / "dam_break_2d_time_series.csv");
  ASSERT_EQ(t.names, (std::vector<std::string>{"t (s)", "T (1)", "Z (1)", "kinetic_energy (J/m)"}));
  ASSERT_GE(t.rowCount(), 5u);
  EXPECT_NEAR(t.columns[2][0], 1.0, 1e-12);
  const double scale = std::sqrt(2 * 9.81 / 0.5);
  for (std::size_t n = 0; n < t.rowCount(); ++n)
    EXPECT_NEAR(t.columns[1][n], t.columns[0][n] * scale, 1e-12 * scale);
  EXPECT_GT(t.columns[2].back(), 1.0);  // the front has moved out
  EXPECT_NE(log_.str().find("surge front deviates from"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "dam_break_2d_surge_front.png"));
}

TEST_F(ProbesTimeSeries, BadKeysAreRefusedBeforeTheRun) {
  const std::string probe = "output.probes.0.";
  SceneParams s = example("lid_driven_cavity.json", {probe + "reference_value=Re1000"});
  EXPECT_NE(errorOf(s).find("has no column 'Re1000'; its columns: y, Re100, Re400"),
            std::string::npos) << errorOf(s);
  EXPECT_NE(errorOf(s).find("output.probes[0].reference"), std::string::npos) << errorOf(s);
  s = example("lid_driven_cavity.json", {probe + "reference=data/none.csv"});
  EXPECT_NE(errorOf(s).find("cannot read"), std::string::npos) << errorOf(s);
  s = example("lid_driven_cavity.json", {probe + "end=[0.5, 0.0, 0.0]"});
  EXPECT_NE(errorOf(s).find("output.probes[0].end"), std::string::npos) << errorOf(s);
  s = example("lid_driven_cavity.json", {"output.time_series.quantities=energy"});
  EXPECT_NE(errorOf(s).find("allowed: kinetic_energy, max_speed, surge_front"), std::string::npos)
      << errorOf(s);
  s = example("lid_driven_cavity.json", {"output.time_series.quantities=surge_front"});
  EXPECT_NE(errorOf(s).find("solver sph offers"), std::string::npos) << errorOf(s);
  s = example("dam_break_2d.json", {"output.probes=[{\"name\": \"p\", \"start\": [0, 0, 0], "
                                    "\"end\": [1, 1, 0]}]"});
  EXPECT_NE(errorOf(s).find("solver lbm only"), std::string::npos) << errorOf(s);
}

}  // namespace
}  // namespace fluidviz
