#include "pipeline/SceneReading.h"

#include "fieldviz/scene/SceneFile.h"

namespace fluidviz {

SceneParams readSceneParams(const nlohmann::json& j, const std::string& fileName) {
  return scene::readScene<SceneParams>(j, fileName);
}

nlohmann::json writeSceneParams(const SceneParams& scene) { return scene::writeParams(scene); }

}  // namespace fluidviz
