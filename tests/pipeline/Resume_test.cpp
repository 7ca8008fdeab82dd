// Checkpoint/restart of scene runs (issue 8): a run stopped at some step (RunOptions::stopAtStep,
// which acts like SIGTERM: checkpoint, then RunInterrupted) and resumed from its checkpoint
// ends with the same files, byte for byte, as an uninterrupted run (same build, same thread
// count): snapshots, .pvd, pictures, LIC, effective scene. Cases: D2Q9 stopped mid-chunk (between
// stability checks) with a steady-state check running; D2Q9 reaching steady state after the
// resume; D3Q19; SPH model B with rollers (moving boundary particles) and an SPH dam break
// (gravity, open side), each also stopped twice, and the dam break with per-snapshot grid,
// free-surface and view series. Resume refuses another scene (naming the key and
// both values) and accepts changed final pictures.
#include <csignal>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "fieldviz/io/FileError.h"
#include "pipeline/Checkpoint.h"
#include "pipeline/PictureSeries.h"
#include "pipeline/SphGridOutputs.h"
#include "pipeline/StopSignals.h"
#include "tests/pipeline/OutputTreeSupport.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

using test::sameTrees;
using test::sceneFromText;

// 64 x 64 cavity, 1280 steps; stop requests are polled every 244 steps (4e6 / 4096 nodes... the
// slice of solvers/lbm/LbmSolverAdapter), checks every 500 steps: a stop at step 300 falls
// between two checks.
std::string cavity2d(double steadyTolerance = 1e-12, int resolution = 64, double endTime = 2.0,
                     int checkInterval = 500) {
  return R"({ "name": "cav", "solver": "lbm",
    "lbm": { "domain_size": [1, 1], "resolution": )" + std::to_string(resolution) + R"(,
             "reynolds": 100, "lattice_velocity": 0.1,
             "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}},
             "end_time": )" + std::to_string(endTime) + R"(, "steady_tolerance": )" +
         std::to_string(steadyTolerance) + R"(, "check_interval": )" +
         std::to_string(checkInterval) + R"( },
    "output": { "snapshots": 5,
                "images": [{"field": "speed", "width": 160, "height": 140},
                           {"field": "vorticity", "width": 160, "height": 140}],
                "lic": [{"width": 96, "length": 10, "color_by": "speed"}] } })";
}

std::string cavity3d() {
  return R"({ "name": "c3",
    "lbm": { "lattice": "D3Q19", "collision": "trt", "domain_size": [1, 1], "domain_depth": 0.5,
             "resolution": 16, "reynolds": 20, "lattice_velocity": 0.1,
             "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}}, "end_time": 1.0,
             "check_interval": 40 },
    "output": { "snapshots": 3, "images": [{"field": "speed", "slice_index": 4, "width": 120,
                                            "height": 100}] } })";
}

std::string sphRollers() {
  return R"({ "name": "mill", "solver": "sph",
    "sph": { "dimension": 2, "model": "B", "kernel": "wendland_c2", "particle_spacing": 0.05,
             "smoothing_length_ratio": 1.5, "speed_of_sound": 1.5, "viscosity": 0.01,
             "gravity": [0, 0, 0], "domain_upper": [1, 1, 0], "initial_pressure": "zero",
             "fluid_blocks": [{"lower": [0, 0, 0], "upper": [1, 1, 0]}],
             "rollers": [{"center": [0.3, 0.5], "radius": 0.15, "angular_velocity": 2},
                         {"center": [0.7, 0.5], "radius": 0.15, "angular_velocity": -2}],
             "end_time": 0.3 },
    "output": { "snapshots": 4, "images": [{"field": "speed", "width": 160, "height": 140}] } })";
}

std::string sphDamBreak() {
  return R"({ "name": "dam", "solver": "sph",
    "sph": { "dimension": 2, "model": "B", "particle_spacing": 0.02, "speed_of_sound": 19.8,
             "alpha": 0.1, "domain_upper": [0.8, 0.6, 0], "walls": {"y_max": "open"},
             "fluid_blocks": [{"lower": [0, 0, 0], "upper": [0.2, 0.4, 0]}],
             "end_time": 0.1 },
    "output": { "snapshots": 3, "images": [{"field": "density", "width": 160, "height": 120}] } })";
}

// The dam break with the per-snapshot grid outputs: a resampled grid and a free surface, each a
// .pvd series, and a 3D-view frame per snapshot.
std::string sphDamBreakWithGridSeries() {
  std::string scene = sphDamBreak();
  const std::string images = R"("images": [{"field": "density", "width": 160, "height": 120}])";
  scene.replace(scene.find(images), images.size(), images + R"(,
    "grids": [{"spacing": 0.04, "arrays": "speed", "every_snapshot": true}],
    "free_surface": [{"grid": {"spacing": 0.04}, "every_snapshot": true}],
    "views": [{"file": "dam_view.png", "show": "particles", "width": 120, "height": 90,
               "every_snapshot": true}])");
  return scene;
}

class Resume : public test::TempDirTest {
 protected:
  // Uninterrupted into "whole"; stopped at each of `stops` and resumed into "parts".
  void expectResumedEqualsWhole(const SceneParams& scene, std::vector<long long> stops) {
    const RunSummary whole = runInto(scene, "whole");
    for (std::size_t k = 0; k < stops.size(); ++k) {
      try {
        runInto(scene, "parts", k > 0, stops[k]);
        FAIL() << "the run did not stop at step " << stops[k];
      } catch (const RunInterrupted& e) {
        EXPECT_EQ(e.signal(), SIGTERM);
        EXPECT_GE(e.step(), stops[k]);
        EXPECT_LT(e.step(), whole.steps);
        EXPECT_TRUE(fs::exists(e.checkpoint()));
        EXPECT_EQ(e.checkpoint(), checkpointPath(dir_ / "parts", scene.name));
      }
    }
    const RunSummary resumed = runInto(scene, "parts", true);
    EXPECT_NE(log_.str().find("resuming from"), std::string::npos) << log_.str();
    EXPECT_EQ(resumed.steps, whole.steps);
    EXPECT_EQ(resumed.time, whole.time);
    EXPECT_EQ(resumed.files.size(), whole.files.size());
    EXPECT_FALSE(fs::exists(checkpointPath(dir_ / "parts", scene.name)))
        << "a completed run removes its checkpoint (checkpoint.keep = false)";
    EXPECT_TRUE(sameTrees(dir_ / "whole", dir_ / "parts"));
  }
};

TEST_F(Resume, LbmD2Q9StoppedBetweenChecksEqualsUninterruptedRun) {
  expectResumedEqualsWhole(sceneFromText(cavity2d()), {300});
}

TEST_F(Resume, PictureFramesAndMoviesOfAResumedRunEqualTheUninterruptedRun) {
  // The earlier frames are kept and listed, the later ones drawn; the movies hold all of them.
  SceneParams scene = sceneFromText(cavity2d());
  scene.output.images[1].every_snapshot = true;
  scene.output.images[1].movie = MovieFormat::gif;
  scene.output.lic[0].every_snapshot = true;
  expectResumedEqualsWhole(scene, {300});
  EXPECT_TRUE(fs::exists(dir_ / "parts" / "cav" / "cav_lic_speed_0005.png"));
  EXPECT_TRUE(fs::exists(dir_ / "parts" / "cav_vorticity.gif"));
}

TEST_F(Resume, LbmD2Q9StoppedTwiceEqualsUninterruptedRun) {
  expectResumedEqualsWhole(sceneFromText(cavity2d()), {200, 700});
}

TEST_F(Resume, LbmSteadyStateReachedAfterResumeEqualsUninterruptedRun) {
  // 32 x 32 cavity, checks every 50 steps: steady (change < 1e-4) well before end_time.
  const SceneParams scene = sceneFromText(cavity2d(1e-4, 32, 30.0, 50));
  const RunSummary probe = runInto(scene, "probe");
  ASSERT_TRUE(probe.steady);
  expectResumedEqualsWhole(scene, {probe.steps / 2});
}

TEST_F(Resume, LbmD3Q19EqualsUninterruptedRun) {
  expectResumedEqualsWhole(sceneFromText(cavity3d()), {50});
}

TEST_F(Resume, SphWithRollersStoppedTwiceEqualsUninterruptedRun) {
  expectResumedEqualsWhole(sceneFromText(sphRollers()), {7, 16});  // of 24 steps
}

TEST_F(Resume, SphDamBreakEqualsUninterruptedRun) {
  expectResumedEqualsWhole(sceneFromText(sphDamBreak()), {25});
}

TEST_F(Resume, SphGridSeriesContinueAcrossTheResume) {
  // Stopped after the first of three snapshots: the grid and free-surface .pvd series go on
  // from their first entry instead of starting again from empty.
  expectResumedEqualsWhole(sceneFromText(sphDamBreakWithGridSeries()), {150});  // of 323
}

TEST_F(Resume, StopAfterTheLastStepResumesToTheFinalPictures) {
  // Stopped after the last snapshot (its checkpoint holds the final state): the resume only
  // writes the pictures.
  const SceneParams scene = sceneFromText(cavity3d());
  const RunSummary whole = runInto(scene, "whole");
  EXPECT_THROW(runInto(scene, "parts", false, whole.steps), RunInterrupted);
  EXPECT_FALSE(fs::exists(dir_ / "parts" / "c3_speed.png"));
  runInto(scene, "parts", true);
  EXPECT_TRUE(sameTrees(dir_ / "whole", dir_ / "parts"));
}

TEST_F(Resume, RefusesAnotherSceneNamingTheKeyAndBothValues) {
  const SceneParams scene = sceneFromText(cavity2d());
  EXPECT_THROW(runInto(scene, "parts", false, 300), RunInterrupted);
  SceneParams other = scene;
  other.lbm.reynolds = 200;
  try {
    runInto(other, "parts", true);
    FAIL() << "resumed another scene";
  } catch (const scene::SceneError& e) {
    EXPECT_EQ(e.key(), "lbm.reynolds");
    const std::string what = e.what();
    EXPECT_NE(what.find("scene.json"), std::string::npos) << what;
    EXPECT_NE(what.find("is 200.0 here but 100.0 in the checkpoint"), std::string::npos) << what;
    EXPECT_NE(what.find("cav.checkpoint"), std::string::npos) << what;
  }
  SceneParams fewerSnapshots = scene;
  fewerSnapshots.output.snapshots = 4;
  try {
    runInto(fewerSnapshots, "parts", true);
    FAIL() << "resumed with another snapshot count";
  } catch (const scene::SceneError& e) {
    EXPECT_EQ(e.key(), "output.snapshots");
  }
}

TEST_F(Resume, AcceptsChangedPicturesAndCheckpointSettings) {
  const SceneParams scene = sceneFromText(cavity2d());
  EXPECT_THROW(runInto(scene, "parts", false, 300), RunInterrupted);
  SceneParams other = scene;
  other.description = "another description";
  other.output.images.resize(1);
  other.output.lic.clear();
  other.checkpoint.keep = true;
  runInto(other, "parts", true);
  EXPECT_TRUE(fs::exists(dir_ / "parts" / "cav_speed.png"));
  EXPECT_FALSE(fs::exists(dir_ / "parts" / "cav_vorticity.png"));
  EXPECT_TRUE(fs::exists(checkpointPath(dir_ / "parts", "cav"))) << "checkpoint.keep";
}

TEST_F(Resume, MissingCheckpointIsAFileErrorNamingIt) {
  try {
    runInto(sceneFromText(cavity2d()), "nothing", true);
    FAIL() << "resumed without a checkpoint";
  } catch (const FileError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no checkpoint " + (dir_ / "nothing" / "cav.checkpoint").string()),
              std::string::npos)
        << what;
  }
  EXPECT_FALSE(fs::exists(dir_ / "nothing")) << "nothing is written";
}

TEST_F(Resume, MissingSnapshotIsAFileErrorNamingIt) {
  const SceneParams scene = sceneFromText(cavity2d());
  EXPECT_THROW(runInto(scene, "parts", false, 700), RunInterrupted);
  fs::remove(dir_ / "parts" / "cav" / "cav_0001.vti");
  try {
    runInto(scene, "parts", true);
    FAIL() << "resumed without a snapshot it lists";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("lists snapshot " +
                                         (dir_ / "parts" / "cav" / "cav_0001.vti").string() +
                                         ", which is missing"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(Resume, MissingGridSeriesFileIsAFileErrorNamingIt) {
  const SceneParams scene = sceneFromText(sphDamBreakWithGridSeries());
  EXPECT_THROW(runInto(scene, "parts", false, 150), RunInterrupted);
  const fs::path lost = dir_ / "parts" / "dam_free_surface" / "dam_free_surface_0001.vtp";
  ASSERT_TRUE(fs::exists(lost));
  fs::remove(lost);
  try {
    runInto(scene, "parts", true);
    FAIL() << "resumed without a series file of an earlier snapshot";
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), lost);
    EXPECT_NE(std::string(e.what()).find("snapshot 1 of the run being resumed wrote " +
                                         lost.string() + ", which is missing"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(Resume, GridSeriesFilesAfterTheCheckpointAreRemoved) {
  // As a kill between a snapshot and its checkpoint would leave them: series files and view
  // frames numbered after the checkpoint's snapshots. A resumed run starts by removing them
  // (a run that then stopped early would otherwise leave files outside the .pvd).
  const SceneParams scene = sceneFromText(sphDamBreakWithGridSeries());
  EXPECT_THROW(runInto(scene, "parts", false, 150), RunInterrupted);
  const fs::path parts = dir_ / "parts";
  const fs::path laterGrid = parts / "dam_grid" / "dam_grid_0002.vti";
  const fs::path laterFrame = parts / "dam" / "dam_view_0002.png";
  fs::copy_file(parts / "dam_grid" / "dam_grid_0001.vti", laterGrid);
  fs::copy_file(parts / "dam" / "dam_view_0001.png", laterFrame);
  const auto earlier = readCheckpoint(checkpointPath(parts, "dam")).header.snapshots;
  ASSERT_EQ(earlier.size(), 2u);  // t = 0 and snapshot 1 (issue 16)
  // SphOutputs::begin hands the grids the targets' entries only (not the t = 0 one).
  SphGridOutputs outputs(scene, parts, log_, true, {earlier.begin() + 1, earlier.end()});
  EXPECT_FALSE(fs::exists(laterGrid));
  EXPECT_TRUE(fs::exists(parts / "dam_grid" / "dam_grid_0001.vti"));
  EXPECT_EQ(outputs.earlierFiles().size(), 2u);  // grid and free surface of snapshot 1
  // The view's frames are pictures' frames: t = 0 and snapshot 1 kept and listed, 2 removed.
  const SnapshotSeries series(parts, "dam", earlier);
  std::vector<fs::path> written;
  continueEarlierFrames(scene, series, written);
  EXPECT_FALSE(fs::exists(laterFrame));
  EXPECT_EQ(written, (std::vector<fs::path>{parts / "dam" / "dam_view_0000.png",
                                            parts / "dam" / "dam_view_0001.png"}));
}

TEST_F(Resume, RemovesLaterSnapshotsAndDeadWritersTemporaryFiles) {
  // Checkpoints only on a timer that never fires: the stop's checkpoint is the only one, and
  // snapshot files beyond it (as a kill between a snapshot and its checkpoint would leave) and
  // a dead writer's temporary file are removed by the resume.
  SceneParams scene = sceneFromText(cavity2d());
  scene.checkpoint.at_snapshots = false;
  EXPECT_THROW(runInto(scene, "parts", false, 300), RunInterrupted);
  const fs::path series = dir_ / "parts" / "cav";
  fs::copy_file(series / "cav_0001.vti", series / "cav_0004.vti");
  const fs::path stale = series / ".cav_0002.tmp999999999_0.vti";  // no such process
  std::ofstream(stale) << "half a file";
  const fs::path live = series / (".cav_0003.tmp" + std::to_string(::getppid()) + "_0.vti");
  std::ofstream(live) << "a running writer's file";
  {
    // The checkpoint lists t = 0 and one snapshot: cav_0004.vti is a later one.
    auto loaded = readCheckpoint(checkpointPath(dir_ / "parts", "cav"));
    ASSERT_EQ(loaded.header.snapshots.size(), 2u);
  }
  runInto(scene, "parts", true);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live)) << "a file of a running process is left alone";
  fs::remove(live);
  const RunSummary whole = runInto(scene, "whole");
  EXPECT_TRUE(sameTrees(dir_ / "whole", dir_ / "parts"));
}

TEST_F(Resume, FreshRunRemovesAnEarlierCheckpoint) {
  const SceneParams scene = sceneFromText(cavity3d());
  EXPECT_THROW(runInto(scene, "out", false, 50), RunInterrupted);
  SceneParams noSnapshotCheckpoints = scene;
  noSnapshotCheckpoints.checkpoint.at_snapshots = false;
  // A fresh run into the interrupted run's folder must be told to replace it (RunRecord.h).
  EXPECT_THROW(runInto(noSnapshotCheckpoints, "out"), FileError);
  EXPECT_TRUE(fs::exists(checkpointPath(dir_ / "out", "c3")));
  RunOptions replace = optionsFor("out", false, -1);
  replace.replace = true;
  runScene(noSnapshotCheckpoints, replace);
  EXPECT_FALSE(fs::exists(checkpointPath(dir_ / "out", "c3")));
}

TEST_F(Resume, IntervalWritesCheckpointsWithoutSnapshots) {
  // interval 1e-9 s: a checkpoint after every chunk; keep it to read it back.
  SceneParams scene = sceneFromText(cavity3d());
  scene.output.snapshots = 0;
  scene.checkpoint.at_snapshots = false;
  scene.checkpoint.interval = 1e-9;
  scene.checkpoint.keep = true;
  const RunSummary whole = runInto(scene, "out");
  const LoadedCheckpoint last = readCheckpoint(checkpointPath(dir_ / "out", "c3"));
  EXPECT_EQ(last.header.step, whole.steps);
  EXPECT_EQ(last.header.solver, "lbm");
  EXPECT_TRUE(last.header.snapshots.empty());
}

}  // namespace
}  // namespace fluidviz
