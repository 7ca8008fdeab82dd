#pragma once
// Scenes as JSON text run in-process through runScene, into per-test temporary folders.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "pipeline/RunScene.h"
#include "pipeline/SceneParams.h"
#include "pipeline/SceneReading.h"
#include "pipeline/SceneValidation.h"
#include "fieldviz/scene/SceneFile.h"
#include "tests/support/TextFiles.h"

namespace fluidviz::test {

using testing::readText;

inline SceneParams sceneFromText(const std::string& json) {
  return readSceneParams(scene::parseSceneText(json, "scene.json"), "scene.json");
}

/// The SceneError message of validateScene on the scene's text; empty if it passes.
inline std::string sceneErrorOf(const std::string& text) {
  try {
    validateScene(sceneFromText(text), "scene.json");
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "";
}

/// A fresh folder for the running test, removed by the fixture.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("fluidviz_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) std::filesystem::remove_all(dir_);
  }
  /// Runs the scene into dir_/sub; the log is kept in log_.
  RunSummary runInto(const SceneParams& scene, const std::string& sub, bool resume = false,
                     long long stopAtStep = -1) {
    return runScene(scene, optionsFor(sub, resume, stopAtStep));
  }
  /// Options of a run into dir_/sub with a fresh log_.
  RunOptions optionsFor(const std::string& sub, bool resume, long long stopAtStep) {
    RunOptions options;
    options.outputDir = dir_ / sub;
    options.sceneFile = "scene.json";
    log_.str("");
    options.log = &log_;
    options.resume = resume;
    options.stopAtStep = stopAtStep;
    return options;
  }
  std::filesystem::path dir_;
  std::ostringstream log_;
};

}  // namespace fluidviz::test
