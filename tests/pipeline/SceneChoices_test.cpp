// Choices are enums read and written by their names: the SPH models' old names "A" and "B" are
// still read (old scenes keep running) but the effective scene writes the new ones, and the
// retired key slice_z gets a message naming the two keys that replace it.
#include <gtest/gtest.h>

#include <string>

#include "fieldviz/scene/ParamVisitors.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fluidviz::test {
namespace {

std::string sceneError(const std::string& json) {
  try {
    sceneFromText(json);
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneChoices, OldSphModelNamesAreReadAndTheNewOnesWritten) {
  for (const auto& [old, now] : {std::pair{"A", sph::SphModel::muller2003},
                                 std::pair{"B", sph::SphModel::weakly_compressible}}) {
    const SceneParams s = sceneFromText(R"({"solver": "sph", "sph": {"model": ")" +
                                        std::string(old) + R"(", "end_time": 1}})");
    EXPECT_EQ(s.sph.model, now) << old;
    EXPECT_EQ(writeSceneParams(s)["sph"]["model"], choiceName(now)) << old;
  }
  const SceneParams s =
      sceneFromText(R"({"solver": "sph", "sph": {"model": "muller2003", "end_time": 1}})");
  EXPECT_EQ(s.sph.model, sph::SphModel::muller2003);
  const std::string e = sceneError(R"({"solver": "sph", "sph": {"model": "C", "end_time": 1}})");
  EXPECT_NE(e.find("sph.model' is \"C\", allowed one of {muller2003, weakly_compressible}"),
            std::string::npos)
      << e;
}

TEST(SceneChoices, RetiredSliceZNamesTheKeysThatReplaceIt) {
  std::string e = sceneError(R"({"output": {"images": [{"slice_z": 3}]}})");
  EXPECT_NE(e.find("output.images[0].slice_z' was split: give slice_index"), std::string::npos)
      << e;
  EXPECT_NE(e.find("slice_height"), std::string::npos) << e;
  e = sceneError(R"({"output": {"lic": [{"slice_z": 0.5}]}})");
  EXPECT_NE(e.find("output.lic[0].slice_z' was split: give slice_height (m"), std::string::npos)
      << e;
  const SceneParams s = sceneFromText(
      R"({"output": {"images": [{"slice_index": 3}], "lic": [{"slice_height": 0.5}]}})");
  EXPECT_EQ(s.output.images[0].slice_index, 3);
  EXPECT_EQ(s.output.lic[0].slice_height, 0.5);
}

TEST(SceneChoices, ExclusiveMaximumIsPrintedAndEnforced) {
  const std::string e = sceneError(R"({"output": {"lic": [{"mask_speed": 1}]}})");
  EXPECT_NE(e.find("mask_speed' is 1, outside the allowed range [0, 1)"), std::string::npos) << e;
  EXPECT_EQ(
      sceneFromText(R"({"output": {"lic": [{"mask_speed": 0.999}]}})").output.lic[0].mask_speed,
      0.999);
}

}  // namespace
}  // namespace fluidviz::test
