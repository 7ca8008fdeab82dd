#pragma once
#include <string>
#include <vector>

namespace fluidviz {
/// docs/scenes.md: every scene key with type, unit, default and allowed range, generated from
/// the parameter declarations so that the reference cannot drift from the code.
std::string sceneDocsMarkdown();

/// Every scene key ("lbm.reynolds", "output.images[].title"), in the order of docs/scenes.md.
std::vector<std::string> sceneKeys();

/// The reference of the keys `query` names, as plain text: the key itself, the keys below it
/// ("lbm.walls" gives lbm.walls.*), or every key whose last part it is ("reynolds"). Empty if
/// none matches.
std::string sceneKeyDocs(const std::string& query);

/// Up to `count` keys that contain `query`, for a "did you mean" message.
std::vector<std::string> similarSceneKeys(const std::string& query, std::size_t count = 8);
}  // namespace fluidviz
