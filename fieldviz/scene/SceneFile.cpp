#include "fieldviz/scene/SceneFile.h"

#include <fstream>
#include <set>
#include <sstream>
#include <vector>

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

// Bytes that are not printable ASCII (a Latin-1 'é' in a UTF-8 file) as \xNN, so that the message
// itself is valid text.
std::string printable(const std::string& text) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : text) {
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
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

namespace {

// Follows the parser's events to know the key path being parsed: nlohmann's callback sees keys
// but not where they are, and keeps the last of duplicate keys silently.
class KeyTracker {
 public:
  explicit KeyTracker(const std::string& fileName) : fileName_(fileName) {}

  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    using E = json::parse_event_t;
    if (event == E::object_start || event == E::array_start) {
      if (depth + 1 > kMaxNesting)
        throw SceneError(fileName_, "", "nesting deeper than " + std::to_string(kMaxNesting) +
                                                " levels; scenes need at most a few");
      open_.push_back({event == E::array_start, {}, {}, 0});
    } else if (event == E::key) {
      Level& level = open_.back();
      level.key = parsed.get<std::string>();
      if (!level.keys.insert(level.key).second)
        throw SceneError(fileName_, path(), "is given twice in the same object; give each key "
                                            "once (JSON parsers disagree on which one counts)");
    } else if (event == E::object_end || event == E::array_end) {
      open_.pop_back();
      countElement();
    } else if (event == E::value) {
      countElement();
    }
    return true;
  }

  /// Dotted path of the value being parsed ("lbm.rollers[1].radius"); "" at the top.
  std::string path() const {
    std::string p;
    for (const Level& level : open_) {
      if (level.isArray)
        p += "[" + std::to_string(level.index) + "]";
      else if (!level.key.empty())
        p += (p.empty() ? "" : ".") + level.key;
    }
    return p;
  }

 private:
  struct Level {
    bool isArray;
    std::string key;            // objects: the key whose value is being parsed
    std::set<std::string> keys; // objects: keys seen so far
    std::size_t index;          // arrays: index of the element being parsed
  };
  void countElement() {
    if (!open_.empty() && open_.back().isArray) ++open_.back().index;
  }

  const std::string& fileName_;
  std::vector<Level> open_;
};

}  // namespace

json parseSceneText(const std::string& text, const std::string& fileName) {
  KeyTracker tracker(fileName);
  auto callback = [&](int depth, json::parse_event_t event, json& parsed) {
    return tracker(depth, event, parsed);
  };
  try {
    return json::parse(text, callback, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    // "[json.exception.parse_error.101] parse error at line 3, column 2: syntax error ...; last
    // read: '...'": our own line and column (comments counted), then nlohmann's reason.
    const std::string what = e.what();
    const auto column = what.find("column ");
    const auto colon = what.find(": ", column == std::string::npos ? 0 : column);
    const std::string inside = tracker.path();
    throw SceneError(fileName, "",
                     "is not valid JSON at " + lineAndColumn(text, e.byte ? e.byte - 1 : 0) +
                         ": " + printable(colon == std::string::npos ? what : what.substr(colon + 2)) +
                         (inside.empty() ? "" : "; inside key '" + inside + "'"));
  } catch (const json::exception& e) {
    // A number beyond double's range ("1e400") is json::out_of_range, raised while the value of
    // the key being parsed is read.
    std::string what = e.what();
    const auto bracket = what.find("] ");
    throw SceneError(fileName, tracker.path(),
                     "is not a usable value: " +
                         (bracket == std::string::npos ? what : what.substr(bracket + 2)) +
                         " (numbers must lie within +-1.8e308)");
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
  } catch (const json::exception&) {
    throw SceneError(fileName, keyPath, "--set: '" + text + "' is not a usable value (numbers "
                                        "must lie within +-1.8e308)");
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
