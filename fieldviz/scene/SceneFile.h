#pragma once
// Scene files: JSON text (comments allowed) -> validated parameter structs, with errors that name
// the file, the key path and the allowed range.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "fieldviz/scene/ParamVisitors.h"

namespace fluidviz::scene {

/// Bad scene input. what() is the complete message: "<file>: <key>: <problem>".
class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, std::string key, const std::string& problem);
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }

 private:
  std::string file_, key_;
};

/// Parses JSON text; syntax errors become SceneError with line and column.
json parseSceneText(const std::string& text, const std::string& fileName);

/// Reads and parses a scene file; a missing or unreadable file is a SceneError too.
json readSceneFile(const std::filesystem::path& path);

/// Applies one command-line override "key.path=value" (value parsed as JSON, else taken as a
/// string). List elements are addressed by index: "lbm.rollers.0.radius=0.1" or "rollers[0]".
void applyOverride(json& scene, const std::string& assignment, const std::string& fileName);

/// Reads a struct from the scene JSON, turning ParamError into SceneError for `fileName`.
template <class S>
S readScene(const json& j, const std::string& fileName) {
  S s{};
  try {
    readParams(j, s, "");
  } catch (const ParamError& e) {
    throw SceneError(fileName, e.key(), e.what());
  }
  return s;
}

}  // namespace fluidviz::scene
