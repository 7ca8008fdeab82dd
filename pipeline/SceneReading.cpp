#include "pipeline/SceneReading.h"

#include <filesystem>

#include "fieldviz/scene/SceneFile.h"

namespace fluidviz {

SceneParams readSceneParams(const nlohmann::json& j, const std::string& fileName) {
  SceneParams scene = scene::readScene<SceneParams>(j, fileName);
  scene.folder = std::filesystem::path(fileName).parent_path();
  return scene;
}

nlohmann::json writeSceneParams(const SceneParams& scene) { return scene::writeParams(scene); }

}  // namespace fluidviz
