// libFuzzer target: scene-file bytes -> JSON parse -> scene struct (every key's type and range)
// -> checkScene (rules spanning several keys, the solvers' physical limits), as `fluidviz check`.
#include "pipeline/RunScene.h"
#include "pipeline/SceneReading.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  fuzz::expectOnlyBadInputErrors([&] {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const scene::json j = scene::parseSceneText(text, "fuzz.json");
    const SceneParams params = readSceneParams(j, "fuzz.json");
    checkScene(params, "fuzz.json");
  });
  return 0;
}
