#pragma once
// The whole scene struct read from and written to JSON, compiled once.
//
// The visitor templates of fieldviz/scene/ParamVisitors.h, instantiated over the whole
// SceneParams tree, generate a large amount of code; every translation unit that called
// scene::readScene<SceneParams> or scene::writeParams(SceneParams) compiled all of it again
// (the pipeline tests spent most of their compile time there). These two functions are the one
// place that instantiates them; callers include this header instead of the templates.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "pipeline/SceneParams.h"

namespace fluidviz {

/// The scene struct of a parsed scene file; a ParamError becomes a SceneError naming `fileName`
/// (scene::readScene).
SceneParams readSceneParams(const nlohmann::json& j, const std::string& fileName);

/// Every key of the scene with its value (scene::writeParams).
nlohmann::json writeSceneParams(const SceneParams& scene);

}  // namespace fluidviz
