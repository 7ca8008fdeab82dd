#pragma once
// Which fluidviz made a file: the version and git commit of the build (provenance of every run,
// `fluidviz --version`). Generated at build time by cmake/BuildInfo.cmake.
#include <string>

namespace fluidviz {

struct BuildInfo {
  std::string version;  ///< the CMake project version, e.g. "0.1.0"
  std::string commit;   ///< full git commit hash of the sources, or "unknown" without git
  bool dirty = false;   ///< tracked files differed from that commit when the build ran

  /// "0.1.0 (commit 008bf10c1a2b, modified)" or "0.1.0 (commit unknown)".
  std::string describe() const {
    const std::string shortCommit = commit == "unknown" ? commit : commit.substr(0, 12);
    return version + " (commit " + shortCommit + (dirty ? ", modified" : "") + ")";
  }
};

const BuildInfo& buildInfo();

}  // namespace fluidviz
