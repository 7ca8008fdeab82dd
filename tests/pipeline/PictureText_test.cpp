// Picture titles from templates (pipeline/PictureText.h; issue 16, defect 5: titles were fixed
// text, so `--set lbm.reynolds=1000` still drew "Re 100", LBM pictures never showed the time,
// and an empty title, documented to give none, gave a default one).
#include "pipeline/PictureText.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include "fieldviz/scene/SceneFile.h"
#include "pipeline/SceneReading.h"
#include "pipeline/SceneValidation.h"
#include "tests/pipeline/PipelineTestSupport.h"
#include "tests/support/PngFiles.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

std::string cavity(const std::string& imagesJson) {
  return R"({ "name": "cav", "solver": "lbm",
    "lbm": { "domain_size": [1, 1], "resolution": 16, "reynolds": 100, "lattice_velocity": 0.1,
             "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}},
             "end_time": 0.25 },
    "output": { "snapshots": 0, "images": )" + imagesJson + " } }";
}

SceneParams withOverride(const std::string& text, const std::string& assignment) {
  scene::json j = scene::parseSceneText(text, "scene.json");
  scene::applyOverride(j, assignment, "scene.json");
  return readSceneParams(j, "scene.json");
}

TEST(PictureTitle, PlaceholdersFollowTheEffectiveScene) {
  const SceneParams s = withOverride(cavity("[]"), "lbm.reynolds=1000");
  const std::string t = pictureTitle(s, "k", "{name} Re {reynolds} ({lbm.reynolds}), t = {time} s",
                                     {"speed", 2.0000000000000004});
  EXPECT_EQ(t, "cav Re 1000 (1000), t = 2 s");
  EXPECT_EQ(pictureTitle(s, "k", kImageTitleTemplate, {"vorticity", 12.5}),
            "cav: vorticity (1/s), t = 12.5 s");
  EXPECT_EQ(pictureTitle(s, "k", "{solver} {resolution} {{literal}}", {"speed", 0}),
            "lbm 16 {literal}");
  EXPECT_EQ(pictureTitle(s, "k", "", {"speed", 1}), "");
}

TEST(PictureTitle, LegendTitlesCarryUnits) {
  EXPECT_EQ(legendTitleOf("speed"), "speed (m/s)");
  EXPECT_EQ(legendTitleOf("|velocity|", "velocity"), "|velocity| (m/s)");  // a 3D view's legend
  EXPECT_EQ(legendTitleOf("vorticity"), "vorticity (1/s)");
  EXPECT_EQ(legendTitleOf("pressure"), "pressure (Pa)");
  EXPECT_EQ(legendTitleOf("density"), "density (kg/m^3)");
  EXPECT_EQ(legendTitleOf("stream_function"), "stream_function (m^2/s)");
}

// An unknown or valueless placeholder stops the scene before it runs, naming the key.
TEST(PictureTitle, BadPlaceholdersAreRefusedNamingTheKey) {
  const auto expectRefused = [](const std::string& images, const std::string& key,
                                const std::string& piece) {
    try {
      validateScene(test::sceneFromText(cavity(images)), "scene.json");
      ADD_FAILURE() << images << " was accepted";
    } catch (const scene::SceneError& e) {
      EXPECT_EQ(e.key(), key);
      EXPECT_NE(std::string(e.what()).find(piece), std::string::npos) << e.what();
    }
  };
  expectRefused(R"([{"field": "speed", "title": "t = {tim} s"}])", "output.images[0].title",
                "unknown placeholder {tim}");
  expectRefused(R"([{"field": "speed"}, {"field": "density", "title": "{viscosity}"}])",
                "output.images[1].title", "no value");  // reynolds given, viscosity not
  expectRefused(R"([{"field": "speed", "title": "{type}"}])", "output.images[0].title",
                "names several keys");
  expectRefused(R"([{"field": "speed", "title": "a { b"}])", "output.images[0].title",
                "not closed");
}

// Near-black (text) pixels in the top 60 rows, where a title goes (below the padding), left of the
// legend (whose labels are black too; the darkest viridis colour is (68, 1, 84)).
int titlePixels(const fs::path& png) {
  const RgbaImage image = testing::readPngImage(png);
  int dark = 0;
  for (int y = 0; y < 60 && y < image.height; ++y)
    for (int x = 0; x < image.width / 2; ++x) {
      const auto p = image.pixel(x, y);
      dark += p[0] < 40 && p[1] < 40 && p[2] < 40;
    }
  return dark;
}

TEST(PictureTitle, DefaultTitleIsDrawnAndAnEmptyOneIsNot) {
  const fs::path dir = fs::temp_directory_path() / ("fluidviz_PictureTitle_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  RunOptions options;
  options.outputDir = dir;
  options.sceneFile = "scene.json";
  std::ostringstream log;
  options.log = &log;
  runScene(test::sceneFromText(cavity(
               R"([{"field": "speed", "file": "titled.png", "width": 300, "height": 300},
                   {"field": "speed", "file": "untitled.png", "title": "", "width": 300, "height": 300}])")),
           options);
  EXPECT_GT(titlePixels(dir / "titled.png"), 100);
  EXPECT_EQ(titlePixels(dir / "untitled.png"), 0);
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace fluidviz
