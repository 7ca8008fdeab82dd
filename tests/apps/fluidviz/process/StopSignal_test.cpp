// SIGTERM and SIGINT stop `fluidviz run` cleanly (issue 8): the real program, signalled once its
// first snapshot exists, exits with 143 / 130, says where it stopped, where the checkpoint is and
// the command that continues; the checkpoint reads back and no temporary file is left; the
// resumed run (that command) ends with the same files, byte for byte, as an uninterrupted run
// with the same thread count. LBM is stopped by SIGTERM, SPH by SIGINT.
#include <csignal>
#include <filesystem>

#include <gtest/gtest.h>

#include "fieldviz/core/AtomicFile.h"
#include "pipeline/Checkpoint.h"
#include "tests/apps/fluidviz/process/ProcessScenes.h"
#include "tests/apps/fluidviz/process/ProcessSupport.h"
#include "tests/pipeline/OutputTreeSupport.h"

namespace fs = std::filesystem;

namespace fluidviz::test {
namespace {

class StopSignal : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_stop_signal_" + std::string(::testing::UnitTest::GetInstance()
                                                       ->current_test_info()->name()) +
            "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // Runs the scene to the end into "whole"; then again into "stopped", sends `signal` once the
  // first snapshot exists, checks the exit and the message, resumes, compares.
  void stopAndResume(const fs::path& scene, const std::string& name, int signal,
                     int expectedExit, const std::string& signalName) {
    const std::vector<std::string> common{"run", scene.string(), "--threads", "1"};
    auto with = [&](std::vector<std::string> extra) {
      std::vector<std::string> a = common;
      a.insert(a.end(), extra.begin(), extra.end());
      return a;
    };
    const fs::path whole = dir_ / "whole", stopped = dir_ / "stopped";
    ASSERT_EQ(runFluidviz(with({"-o", whole.string()}), dir_ / "whole.log"), 0)
        << readText(dir_ / "whole.log");

    const pid_t pid = startFluidviz(with({"-o", stopped.string()}), dir_ / "stopped.log");
    ASSERT_TRUE(waitForFile(stopped / name / (name + "_0001." + (name == "cav" ? "vti" : "vtp")),
                            std::chrono::seconds(120)));
    ::kill(pid, signal);
    const int code = waitForExit(pid);
    const std::string log = readText(dir_ / "stopped.log");
    ASSERT_EQ(code, expectedExit) << log;
    const fs::path checkpoint = stopped / (name + ".checkpoint");
    EXPECT_NE(log.find("fluidviz: interrupted by " + signalName + " at t = "), std::string::npos)
        << log;
    EXPECT_NE(log.find("checkpoint written to " + checkpoint.string() + "; continue with: "
                       "fluidviz run " + scene.string() + " --threads 1 --resume " +
                       stopped.string() + "\n"),
              std::string::npos)
        << log;
    const LoadedCheckpoint loaded = readCheckpoint(checkpoint);
    EXPECT_GT(loaded.header.step, 0);
    EXPECT_FALSE(loaded.header.snapshots.empty());
    for (const auto& entry : fs::recursive_directory_iterator(stopped))
      EXPECT_EQ(temporaryFileWriter(entry.path()), -1) << "left behind: " << entry.path();
    EXPECT_FALSE(fs::exists(stopped / (name + "_speed.png"))) << "stopped before the end";

    ASSERT_EQ(runFluidviz(with({"--resume", stopped.string()}), dir_ / "resumed.log"), 0)
        << readText(dir_ / "resumed.log");
    EXPECT_NE(readText(dir_ / "resumed.log").find("resuming from " + checkpoint.string()),
              std::string::npos);
    EXPECT_TRUE(sameTrees(whole, stopped));
  }
  fs::path dir_;
};

TEST_F(StopSignal, SigtermStopsLbmRunWithCheckpointAndExit143) {
  // 96 x 96 nodes, 3840 steps, 40 snapshots: about a second of stepping.
  stopAndResume(writeLbmScene(dir_, 96, 4.0, 40), "cav", SIGTERM, 143, "SIGTERM");
}

TEST_F(StopSignal, SigintStopsSphRunWithCheckpointAndExit130) {
  // 1600 particles, ~500 steps, 30 snapshots.
  stopAndResume(writeSphScene(dir_, 0.025, 3.0, 30), "mill", SIGINT, 130, "SIGINT");
}

}  // namespace
}  // namespace fluidviz::test
