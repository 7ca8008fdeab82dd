// Scenes of the FHP lattice gas (solver = "fhp") through the scene pipeline (runScene): the
// averaged .vti snapshots carry the imposed flow in m/s, the forcing's acceleration, and the
// LBM's solid mask; a scene out of range or out of the lattice's reach is refused naming the key
// and writing nothing.
//   - a periodic box started at flow_velocity (1, 0.5) m/s keeps it: momentum is conserved
//     exactly, so the averaged mean differs from it only by the initial draw, sqrt(<c_x^2> / N)
//     = 0.002 links per step for N = 1.3e5 particles, 1.4 % of the flow's lattice speed; the
//     tolerance is 5 % of |U| (3.5 sigma);
//   - a periodic box at rest with body_force a reaches the mean a t over the averaging window
//     (its centre 9.5 steps before the end), within 5 %;
//   - the blocks whose 16 x 18 nodes lie inside a disc are masked (vtkValidPointMask 0), those
//     clear of it are not, and the masked ones carry the obstacle's velocity, 0;
//   - a run stopped inside an averaging window and resumed from its checkpoint writes the same
//     files, byte for byte, as an uninterrupted run (lattice, averager and forcing state saved).
#include <cmath>

#include <gtest/gtest.h>

#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/scene/SceneFile.h"
#include "solvers/fhp/FhpParams.h"
#include "pipeline/StopSignals.h"
#include "tests/pipeline/OutputTreeSupport.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz::test {
namespace {

// A 1 m square box of 256 x 288 nodes, FHP-III at d = 1/4, periodic on every side.
std::string periodicBox(const std::string& extra, double endTime, int reynolds = 120) {
  return R"({"name": "box", "solver": "fhp",
    "fhp": {"domain_size": [1.0, 1.0], "resolution": 256, "block_size": 16, "reynolds": )" + std::to_string(reynolds) + R"(,
            "walls": {"x_min": {"type": "periodic"}, "x_max": {"type": "periodic"},
                      "y_min": {"type": "periodic"}, "y_max": {"type": "periodic"}},
            "average_steps": 20, "end_time": )" + std::to_string(endTime) + ", " + extra + R"(},
    "output": {"snapshots": 1, "images": []}})";
}

Vec3 meanVelocity(const FieldSet& f) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& v : f.findVector("velocity")->values) sum += v;
  return sum / static_cast<double>(f.grid.nodeCount());
}

class FhpSceneTest : public TempDirTest {};

TEST_F(FhpSceneTest, PeriodicBoxKeepsTheImposedMeanFlow) {
  const SceneParams scene = sceneFromText(periodicBox(R"("flow_velocity": [1.0, 0.5])", 0.02));
  runInto(scene, "run");
  const FieldSet start = readVti(dir_ / "run" / "box" / "box_0000.vti");
  const FieldSet end = readVti(dir_ / "run" / "box" / "box_0001.vti");
  ASSERT_EQ(end.grid.dims[0], 16);
  ASSERT_EQ(end.grid.dims[1], 16);  // 288 rows / 18 per block
  const double tolerance = 0.05 * std::hypot(1.0, 0.5);
  for (const FieldSet* f : {&start, &end}) {
    const Vec3 mean = meanVelocity(*f);
    EXPECT_NEAR(mean.x(), 1.0, tolerance);
    EXPECT_NEAR(mean.y(), 0.5, tolerance);
  }
  // The mean density is the scene's (kg/m^3): the particles are neither made nor lost.
  double rho = 0.0;
  for (double r : end.findScalar("density")->values) rho += r;
  EXPECT_NEAR(rho / static_cast<double>(end.grid.nodeCount()), 1000.0, 5.0);
  EXPECT_NE(log_.str().find("FHP-III lattice gas 256 x 288 nodes"), std::string::npos) << log_.str();
}

TEST_F(FhpSceneTest, BodyForceAcceleratesTheBoxAtTheImposedRate) {
  const double a = 25.0;  // m/s^2: about 1 m/s after the 0.04 s run
  const SceneParams scene = sceneFromText(
      periodicBox(R"("reference_velocity": 1.0, "body_force": 25.0)", 0.04));
  const fhp::FhpUnits units = fhp::computeFhpUnits(scene.fhp);
  ASSERT_GT(units.forceProbability, 0.0);
  runInto(scene, "run");
  const FieldSet end = readVti(dir_ / "run" / "box" / "box_0001.vti");
  const double expected = a * units.dt * (static_cast<double>(units.steps) - 9.5);
  const Vec3 mean = meanVelocity(end);
  EXPECT_NEAR(mean.x(), expected, 0.05 * expected) << "steps " << units.steps;
  EXPECT_NEAR(mean.y(), 0.0, 0.05 * expected);
}

TEST_F(FhpSceneTest, ObstacleBlocksAreMaskedAsTheLbmMasksItsSolids) {
  const SceneParams scene = sceneFromText(periodicBox(
      R"("flow_velocity": [1.0, 0.0], "obstacles": [{"center": [0.5, 0.5], "radius": 0.2}])",
      1e-4));
  runInto(scene, "run");
  const FieldSet f = readVti(dir_ / "run" / "box" / "box_0001.vti");
  const ScalarField* valid = f.findScalar("vtkValidPointMask");
  ASSERT_NE(valid, nullptr);
  const double halfDiagonal = 0.5 * std::hypot(f.grid.spacing[0], f.grid.spacing[1]);
  int inside = 0, outside = 0;
  for (int j = 0; j < f.grid.dims[1]; ++j)
    for (int i = 0; i < f.grid.dims[0]; ++i) {
      const Vec3 p = f.grid.position(i, j);
      const double r = std::hypot(p.x() - 0.5, p.y() - 0.5);
      const double v = valid->values[f.grid.index(i, j)];
      if (r < 0.2 - halfDiagonal) {
        EXPECT_EQ(v, 0.0) << i << ", " << j;
        ++inside;
      } else if (r > 0.2 + halfDiagonal) {
        EXPECT_EQ(v, 1.0) << i << ", " << j;
        ++outside;
      }
    }
  EXPECT_GT(inside, 10);
  EXPECT_GT(outside, 150);
  // A masked block is the obstacle at rest: its velocity is the wall's, exactly 0 (the topology
  // commands read such solids as walls at rest, RestingWalls.h), as an LBM obstacle's is.
  const VectorField* velocity = f.findVector("velocity");
  ASSERT_NE(velocity, nullptr);
  int masked = 0;
  for (std::size_t n = 0; n < valid->values.size(); ++n)
    if (valid->values[n] == 0.0) {
      EXPECT_EQ(velocity->values[n].norm(), 0.0) << "node " << n;
      ++masked;
    }
  EXPECT_GE(masked, inside);
}

TEST_F(FhpSceneTest, SceneOutOfRangeOrOutOfReachIsRefusedNamingTheKey) {
  try {
    sceneFromText(periodicBox(R"("flow_velocity": [1.0, 0.0], "channel_density": 0.7)", 1.0));
    FAIL() << "channel_density 0.7 accepted";
  } catch (const scene::SceneError& e) {
    EXPECT_EQ(e.key(), "fhp.channel_density") << e.what();
  }
  // Re 1000 on 256 links: at most g 0.2 256 / nu = 170 at d = 1/4.
  const SceneParams far = sceneFromText(
      periodicBox(R"("flow_velocity": [1.0, 0.0])", 1.0, 1000));
  try {
    runInto(far, "far");
    FAIL() << "Re 1000 accepted";
  } catch (const scene::SceneError& e) {
    EXPECT_EQ(e.key(), "fhp.reynolds") << e.what();
    EXPECT_NE(std::string(e.what()).find("largest reachable Re at resolution 256 is 169.6"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "far" / "box.pvd"));
}

TEST_F(FhpSceneTest, ResumedRunIsByteIdenticalToAnUninterruptedOne) {
  SceneParams scene = sceneFromText(
      periodicBox(R"("reference_velocity": 1.0, "body_force": 25.0)", 0.04));
  scene.output.snapshots = 2;
  ASSERT_EQ(fhp::computeFhpUnits(scene.fhp).steps, 187);  // windows: steps 75-94 and 168-187
  runInto(scene, "whole");
  EXPECT_THROW(runInto(scene, "parts", false, 180), RunInterrupted);
  runInto(scene, "parts", true);
  EXPECT_TRUE(sameTrees(dir_ / "whole", dir_ / "parts"));
}

}  // namespace
}  // namespace fluidviz::test
