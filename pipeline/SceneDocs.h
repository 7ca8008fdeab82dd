#pragma once
#include <string>

namespace fluidviz {
/// docs/scenes.md: every scene key with type, unit, default and allowed range, generated from
/// the parameter declarations so that the reference cannot drift from the code.
std::string sceneDocsMarkdown();
}  // namespace fluidviz
