#pragma once
// Comparing the output folders of two runs file by file, byte by byte (checkpoint and
// determinism tests). The one difference allowed is the date in the run record and the scene
// copy's header (pipeline/RunRecord.h): it is read as "<date>".
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <string>

#include <gtest/gtest.h>

namespace fluidviz::test {

/// Relative path -> contents of every regular file under `dir`.
inline std::map<std::string, std::string> readTree(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::string bytes(std::istreambuf_iterator<char>(in), {});
    const std::string name = entry.path().filename().string();
    const auto endsWith = [&](const std::string& tail) {
      return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    if (endsWith("_run.json") || endsWith("_scene.json"))
      bytes = std::regex_replace(bytes, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)"), "<date>");
    files[entry.path().lexically_relative(dir).generic_string()] = bytes;
  }
  return files;
}

/// The same file names with the same bytes.
inline ::testing::AssertionResult sameTrees(const std::filesystem::path& a,
                                            const std::filesystem::path& b) {
  const auto ta = readTree(a), tb = readTree(b);
  for (const auto& [name, bytes] : ta) {
    const auto it = tb.find(name);
    if (it == tb.end())
      return ::testing::AssertionFailure() << name << " is in " << a << " but not in " << b;
    if (it->second != bytes) {
      std::size_t at = 0;
      while (at < bytes.size() && at < it->second.size() && bytes[at] == it->second[at]) ++at;
      return ::testing::AssertionFailure() << name << " differs (sizes " << bytes.size() << " and "
                                           << it->second.size() << ", first difference at byte "
                                           << at << ")";
    }
  }
  for (const auto& [name, bytes] : tb)
    if (!ta.count(name))
      return ::testing::AssertionFailure() << name << " is in " << b << " but not in " << a;
  if (ta.empty()) return ::testing::AssertionFailure() << a << " holds no file";
  return ::testing::AssertionSuccess() << ta.size() << " files identical";
}

}  // namespace fluidviz::test
