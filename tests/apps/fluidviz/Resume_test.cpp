// `fluidviz run SCENE --resume DIR` through the command (in-process): a run stopped at a step
// (RunOptions::stopAtStep, as SIGTERM would) continues to the same files as an uninterrupted
// `fluidviz run`; bad resumes exit with 2 and a message naming the file and what is wrong:
// a corrupt checkpoint, another scene (--set), no checkpoint, -o naming another folder.
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "pipeline/Checkpoint.h"
#include "pipeline/StopSignals.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "tests/pipeline/OutputTreeSupport.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

using test::run;

class CliResume : public test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    std::ofstream(scene()) << R"({ "name": "cav",
      "lbm": { "domain_size": [1, 1], "resolution": 32, "reynolds": 100, "lattice_velocity": 0.1,
               "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}}, "end_time": 2,
               "check_interval": 100 },
      "output": { "snapshots": 4, "images": [{"field": "speed", "width": 120, "height": 100}] } })";
  }
  std::string scene() const { return (dir_ / "cav.json").string(); }
  fs::path stopped() const { return dir_ / "stopped"; }
  // Stops the scene at step 300 into stopped().
  void stopAt300() {
    SceneParams s = test::sceneFromText(test::readText(scene()));
    EXPECT_THROW(runInto(s, "stopped", false, 300), RunInterrupted);
    ASSERT_TRUE(fs::exists(stopped() / "cav.checkpoint"));
  }
};

TEST_F(CliResume, ResumedRunEqualsUninterruptedRun) {
  stopAt300();
  const test::Result whole = run({"run", scene(), "-o", (dir_ / "whole").string()});
  ASSERT_EQ(whole.code, 0) << whole.err;
  const test::Result resumed = run({"run", scene(), "--resume", stopped().string()});
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("cav: resuming from " + (stopped() / "cav.checkpoint").string() +
                             " at t = "),
            std::string::npos)
      << resumed.err;
  EXPECT_TRUE(test::sameTrees(dir_ / "whole", stopped()));
}

TEST_F(CliResume, CorruptCheckpointExitsWith2NamingTheFile) {
  stopAt300();
  const fs::path file = stopped() / "cav.checkpoint";
  std::string bytes = test::readText(file);
  bytes[bytes.size() / 2] ^= 1;
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  const test::Result r = run({"run", scene(), "--resume", stopped().string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("fluidviz run: error: checkpoint " + file.string() +
                       " is corrupt: its checksum does not match its contents; start the run "
                       "again without --resume"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(stopped() / "cav_speed.png"));
}

TEST_F(CliResume, AnotherSceneExitsWith2NamingTheKey) {
  stopAt300();
  const test::Result r =
      run({"run", scene(), "--set", "lbm.reynolds=150", "--resume", stopped().string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(scene() + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lbm.reynolds"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is 150.0 here but 100.0 in the checkpoint " +
                       (stopped() / "cav.checkpoint").string()),
            std::string::npos)
      << r.err;
}

TEST_F(CliResume, NoCheckpointAndConflictingOutputExitWith2) {
  const test::Result none = run({"run", scene(), "--resume", (dir_ / "none").string()});
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("no checkpoint " + (dir_ / "none" / "cav.checkpoint").string()),
            std::string::npos)
      << none.err;
  EXPECT_FALSE(fs::exists(dir_ / "none"));
  const test::Result both = run({"run", scene(), "-o", "a", "--resume", "b"});
  EXPECT_EQ(both.code, 2);
  EXPECT_NE(both.err.find("--resume b and -o a differ"), std::string::npos) << both.err;
  const test::Result help = run({"run", "--help"});
  EXPECT_NE(help.out.find("--resume DIR"), std::string::npos);
}

}  // namespace
}  // namespace fluidviz
