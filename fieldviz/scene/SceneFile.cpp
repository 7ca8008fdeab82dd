#include "fieldviz/scene/SceneFile.h"

#include <fstream>
#include <sstream>

namespace fluidviz::scene {

SceneError::SceneError(std::string file, std::string key, const std::string& problem)
    : std::runtime_error(file + ": " + (key.empty() ? "" : "key '" + key + "' ") + problem),
      file_(std::move(file)),
      key_(std::move(key)) {}

namespace {
// Nesting deeper than any scene needs is refused before nlohmann's recursive parser sees it.
constexpr int kMaxNesting = 64;

std::string lineAndColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < std::min(byte, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

std::vector<std::string> splitKeyPath(const std::string& path) {
  std::vector<std::string> parts;
  std::string current;
  for (char c : path) {
    if (c == '.' || c == '[' || c == ']') {
      if (!current.empty()) parts.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) parts.push_back(current);
  return parts;
}

bool isIndex(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}
}  // namespace

json parseSceneText(const std::string& text, const std::string& fileName) {
  int depth = 0;
  auto limitDepth = [&](int d, json::parse_event_t event, json&) {
    if (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start)
      depth = std::max(depth, d + 1);
    if (depth > kMaxNesting)
      throw SceneError(fileName, "", "nesting deeper than " + std::to_string(kMaxNesting) +
                                         " levels; scenes need at most a few");
    return true;
  };
  try {
    return json::parse(text, limitDepth, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    const auto colon = what.rfind(": ");
    throw SceneError(fileName, "",
                     "is not valid JSON at " + lineAndColumn(text, e.byte ? e.byte - 1 : 0) +
                         ": " + (colon == std::string::npos ? what : what.substr(colon + 2)));
  }
}

json readSceneFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw SceneError(path.string(), "", "does not exist");
  if (std::filesystem::is_directory(path, ec))
    throw SceneError(path.string(), "", "is a folder, expected a scene file (.json)");
  constexpr std::uintmax_t kMaxBytes = 16u << 20;
  if (std::filesystem::file_size(path, ec) > kMaxBytes)
    throw SceneError(path.string(), "", "is larger than 16 MiB; a scene file is a few KiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path.string(), "", "cannot be opened for reading");
  std::ostringstream s;
  s << in.rdbuf();
  return parseSceneText(s.str(), path.string());
}

void applyOverride(json& scene, const std::string& assignment, const std::string& fileName) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SceneError(fileName, assignment, "--set needs the form key.path=value");
  const std::string keyPath = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  json value;
  try {
    value = json::parse(text);
  } catch (const json::parse_error&) {
    value = text;  // a bare word such as `bgk` is a string
  }
  json* node = &scene;
  const auto parts = splitKeyPath(keyPath);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const bool last = i + 1 == parts.size();
    if (node->is_array()) {
      if (!isIndex(parts[i]) || std::stoul(parts[i]) >= node->size())
        throw SceneError(fileName, keyPath,
                         "--set: '" + parts[i] + "' is not an index of a list of " +
                             std::to_string(node->size()) + " elements");
      node = &(*node)[std::stoul(parts[i])];
    } else {
      if (node->is_null()) *node = json::object();
      if (!node->is_object())
        throw SceneError(fileName, keyPath, "--set: '" + parts[i] + "' is inside a plain value");
      node = &(*node)[parts[i]];
    }
    if (last) *node = value;
  }
}

}  // namespace fluidviz::scene
