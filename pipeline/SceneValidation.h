#pragma once
// Scene validation in one place: validateScene runs every module's own checks (scene name,
// output.images, output.lic/streamlines (FlowOutputs.h), their frames and movies
// (PictureSeries.h), output.grids/free_surface/views
// (SphGridOutputs.h), then the solver's (SolverFactory.h: its parameters and the outputs it
// supports)) and reports the first problem as scene::SceneError naming the file and the key
// from the scene's root. The helpers are what those checks share.
#include <string>
#include <utility>
#include <vector>

#include "fieldviz/core/Params.h"
#include "fieldviz/scene/SceneFile.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

/// Checks everything that needs no solver state; throws scene::SceneError.
void validateScene(const SceneParams& scene, const std::string& sceneFile);

/// Runs `check`, turning a ParamError (key from the scene's root) into scene::SceneError.
template <class F>
decltype(auto) withSceneErrors(const std::string& sceneFile, F&& check) {
  try {
    return std::forward<F>(check)();
  } catch (const ParamError& e) {
    throw scene::SceneError(sceneFile, e.key(), e.what());
  }
}

/// Runs `check`, prefixing the key of a ParamError with `prefix` ("output.lic[0]."); an empty
/// key becomes the prefix without its final '.'.
template <class F>
void withKeyPrefix(const std::string& prefix, F&& check) {
  try {
    std::forward<F>(check)();
  } catch (const ParamError& e) {
    const std::string key =
        e.key().empty() ? prefix.substr(0, prefix.empty() ? 0 : prefix.size() - 1) : prefix + e.key();
    throw ParamError(key, e.what());
  }
}

/// An output's file name: plain (no folder), ending in `extension` (".png") after a non-empty
/// stem, and not written by another output (`taken`, to which it is added). Throws ParamError
/// for `key`.
void requireOutputFileName(const std::string& key, const std::string& file,
                           const std::string& extension, std::vector<std::string>& taken);

/// output.images[]: the file, or <name>_<field>.png.
std::string imageFileName(const SceneParams& scene, const ImageOutput& image);
/// The files of output.images, in order: the start of the taken names of the other outputs.
std::vector<std::string> imageFileNames(const SceneParams& scene);

}  // namespace fluidviz
