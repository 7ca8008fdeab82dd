// The run loop (pipeline/RunLoop.h) drives any Solver (fieldviz/core/Solver.h): a third solver,
// defined here and in no other file, runs through the same loop as LBM and SPH, with snapshots
// in a .pvd series, a stop request (checkpoint + RunInterrupted), resume, and its own early
// stop. It proves that a new solver needs only a Solver, its SolverOutputs and (for scenes) one
// entry in pipeline/SolverFactory.cpp, and no change to the loop.
//
// The fake solver integrates dx_i/dt = -lambda x_i, x_i(0) = i + 1, by explicit Euler with a
// fixed dt: after n steps x_i = (i + 1) (1 - lambda dt)^n, the reference the snapshots are
// compared with (relative 1e-12: n <= 100 roundings of one product each). A chunk is at most 3
// steps, so that stops fall between chunk ends and targets.
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "pipeline/Checkpoint.h"
#include "pipeline/RunLoop.h"
#include "pipeline/StopSignals.h"
#include "tests/pipeline/OutputTreeSupport.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

constexpr double kLambda = 2.0, kDt = 0.01, kEndTime = 1.0;  // 100 steps
constexpr int kValues = 8;
constexpr long long kChunkSteps = 3;

class DecaySolver final : public Solver {
 public:
  /// quietLevel > 0: stops early once every |x_i| is below it (checked at chunk ends).
  explicit DecaySolver(double quietLevel = 0.0) : quietLevel_(quietLevel), x_(kValues) {
    for (int i = 0; i < kValues; ++i) x_[i] = i + 1.0;
  }

  const std::vector<double>& values() const { return x_; }

  std::string name() const override { return "decay"; }
  std::string description() const override { return "decay, dt = 0.01 s"; }
  double time() const override { return static_cast<double>(steps_) * kDt; }
  long long stepCount() const override { return steps_; }
  std::string position() const override { return "step " + std::to_string(steps_); }
  bool reached(const RunTarget& target) override {
    return quiet_ || steps_ >= (totalSteps() * target.k + target.n - 1) / target.n;
  }
  bool stoppedEarly() const override { return quiet_; }
  std::optional<SolverProgress> advance(const RunTarget& target) override {
    const long long goal = (totalSteps() * target.k + target.n - 1) / target.n;
    for (long long n = 0; n < kChunkSteps && steps_ < goal; ++n, ++steps_)
      for (double& x : x_) x -= kDt * kLambda * x;
    double largest = 0.0;
    for (double x : x_) largest = std::max(largest, std::abs(x));
    quiet_ = largest < quietLevel_;
    return std::nullopt;
  }
  SolverProgress progress() const override {
    return {static_cast<double>(steps_) / totalSteps(), position()};
  }
  std::vector<std::string> takeWarnings() override { return {}; }
  void checkStability() const override {}
  std::string summary() const override { return "done after " + std::to_string(steps_) + " steps"; }
  void saveState(StateWriter& w) const override {
    w.put<std::int64_t>(steps_);
    w.put<std::uint8_t>(quiet_ ? 1 : 0);
    w.putVector(x_);
  }
  void restoreState(StateReader& r) override {
    steps_ = r.get<std::int64_t>();
    quiet_ = r.get<std::uint8_t>() != 0;
    r.getVector(x_, kValues);
  }

 private:
  static long long totalSteps() { return std::llround(kEndTime / kDt); }

  double quietLevel_;
  long long steps_ = 0;
  bool quiet_ = false;
  std::vector<double> x_;
};

std::string valuesText(const std::vector<double>& x) {
  std::string text;
  char buf[32];
  for (double v : x) {
    std::snprintf(buf, sizeof buf, "%.17g\n", v);
    text += buf;
  }
  return text;
}

class DecayOutputs final : public SolverOutputs {
 public:
  explicit DecayOutputs(const DecaySolver& solver) : solver_(solver) {}
  void begin(const SnapshotSeries&, bool, std::vector<fs::path>&) override {}
  void writeSnapshot(int index, SnapshotSeries& series, std::vector<fs::path>& written) override {
    const fs::path relative = series.file(index, ".txt");
    writeTextOutput(series.dir() / relative, valuesText(solver_.values()));
    series.add(solver_.time(), relative, written);
  }
  void writeFinal(const SnapshotSeries& series, const scene::json&,
                  std::vector<fs::path>& written) override {
    const fs::path file = series.dir() / "decay_final.txt";
    writeTextOutput(file, valuesText(solver_.values()));
    written.push_back(file);
  }

 private:
  const DecaySolver& solver_;
};

std::vector<double> readValues(const fs::path& file) {
  std::ifstream in(file);
  std::vector<double> x;
  for (double v; in >> v;) x.push_back(v);
  return x;
}

// (i + 1) (1 - lambda dt)^steps
void expectDecayedBy(const std::vector<double>& x, long long steps) {
  ASSERT_EQ(x.size(), static_cast<std::size_t>(kValues));
  for (int i = 0; i < kValues; ++i) {
    const double exact = (i + 1.0) * std::pow(1.0 - kLambda * kDt, static_cast<double>(steps));
    EXPECT_NEAR(x[i], exact, 1e-12 * exact) << "value " << i << " after " << steps << " steps";
  }
}

class ThirdSolver : public test::TempDirTest {
 protected:
  ThirdSolver() {
    scene_.name = "decay";
    scene_.output.snapshots = 4;
    effective_ = {{"name", "decay"}, {"solver", "decay"}, {"decay", {{"lambda", kLambda}}},
                  {"output", {{"snapshots", 4}}}};
  }
  RunSummary runDecay(const std::string& sub, bool resume = false, long long stopAtStep = -1,
                      double quietLevel = 0.0) {
    DecaySolver solver(quietLevel);
    DecayOutputs outputs(solver);
    return runLoop(solver, outputs, scene_, effective_, optionsFor(sub, resume, stopAtStep));
  }
  SceneParams scene_;
  scene::json effective_;
};

TEST_F(ThirdSolver, WritesEvenlySpreadSnapshotsThroughTheLoop) {
  const RunSummary run = runDecay("whole");
  EXPECT_EQ(run.steps, 100);
  EXPECT_DOUBLE_EQ(run.time, 1.0);
  const std::string pvd = test::readText(dir_ / "whole" / "decay.pvd");
  for (int k = 1; k <= 4; ++k) {  // at step ceil(100 k / 4) = 25 k
    char file[32];
    std::snprintf(file, sizeof file, "decay/decay_%04d.txt", k);
    expectDecayedBy(readValues(dir_ / "whole" / file), 25 * k);
    EXPECT_NE(pvd.find("file=\"" + std::string(file) + "\""), std::string::npos) << pvd;
  }
  EXPECT_EQ(pvd.find("decay_0005"), std::string::npos) << pvd;
  expectDecayedBy(readValues(dir_ / "whole" / "decay_final.txt"), 100);
  EXPECT_TRUE(fs::exists(dir_ / "whole" / "decay_scene.json"));
  EXPECT_NE(log_.str().find("decay: decay, dt = 0.01 s"), std::string::npos) << log_.str();
  EXPECT_NE(log_.str().find("decay: done after 100 steps"), std::string::npos) << log_.str();
}

TEST_F(ThirdSolver, StoppedTwiceAndResumedEqualsTheUninterruptedRun) {
  const RunSummary whole = runDecay("whole");
  // Step 37 falls inside a chunk before target 2 (step 50); step 76 just after target 3 (75).
  for (long long stop : {37LL, 76LL}) {
    try {
      runDecay("parts", stop != 37, stop);
      FAIL() << "the run did not stop at step " << stop;
    } catch (const RunInterrupted& e) {
      EXPECT_EQ(e.signal(), SIGTERM);
      EXPECT_GE(e.step(), stop);
      EXPECT_LT(e.step(), stop + kChunkSteps);
      EXPECT_EQ(readCheckpoint(e.checkpoint()).header.solver, "decay");
    }
  }
  const RunSummary resumed = runDecay("parts", true);
  EXPECT_NE(log_.str().find("decay: resuming from"), std::string::npos) << log_.str();
  EXPECT_NE(log_.str().find("(4 snapshots written)"), std::string::npos) << log_.str();
  EXPECT_EQ(resumed.steps, whole.steps);
  EXPECT_EQ(resumed.time, whole.time);
  EXPECT_EQ(resumed.files, [&] {
    std::vector<fs::path> files;
    for (const fs::path& f : whole.files) files.push_back(dir_ / "parts" / f.lexically_relative(dir_ / "whole"));
    return files;
  }());
  EXPECT_FALSE(fs::exists(checkpointPath(dir_ / "parts", "decay")));
  EXPECT_TRUE(test::sameTrees(dir_ / "whole", dir_ / "parts"));
}

TEST_F(ThirdSolver, ItsOwnStopConditionEndsTheRunWithASnapshot) {
  // max |x| = 8 (0.98)^n: 4.03 at n = 34, 3.94 at n = 35. Chunks end at 3, 6, ..., 24, the
  // target 25, then 28, ..., 34, 37: the check at step 37 stops the run, with snapshot 2 (of 4).
  const RunSummary run = runDecay("quiet", false, -1, 4.0);
  EXPECT_EQ(run.steps, 37);
  EXPECT_TRUE(fs::exists(dir_ / "quiet" / "decay" / "decay_0002.txt"));
  EXPECT_FALSE(fs::exists(dir_ / "quiet" / "decay" / "decay_0003.txt"));
  expectDecayedBy(readValues(dir_ / "quiet" / "decay" / "decay_0002.txt"), 37);
}

TEST_F(ThirdSolver, RefusesACheckpointOfAnotherSolver) {
  EXPECT_THROW(runDecay("parts", false, 37), RunInterrupted);
  LoadedCheckpoint ckpt = readCheckpoint(checkpointPath(dir_ / "parts", "decay"));
  ckpt.header.solver = "other";
  std::vector<std::uint8_t> bytes(ckpt.state.remaining());  // loop and solver state, unchanged
  ckpt.state.getBytes(bytes.data(), bytes.size());
  writeCheckpoint(checkpointPath(dir_ / "parts", "decay"), ckpt.header,
                  [&](StateWriter& w) { w.putBytes(bytes.data(), bytes.size()); });
  try {
    runDecay("parts", true);
    FAIL() << "resumed another solver's checkpoint";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("it was written by solver other, the scene runs decay"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fluidviz
