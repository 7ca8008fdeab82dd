#pragma once
// The one exception type of fluidviz's file I/O: a user's file (or an output path) is missing,
// unreadable, corrupt, or lacks what the caller asked for. The message is complete on its own
// ("file X: no point-data array 'foo'; arrays present: ..."); path and array are kept apart so
// callers (CLI, scene validation) can point at the offending key without parsing the text.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace fluidviz {

class FileError : public std::runtime_error {
 public:
  FileError(std::filesystem::path path, const std::string& message, std::string arrayName = {});

  const std::filesystem::path& path() const { return path_; }
  /// Name of the array the error is about; empty when it concerns the whole file.
  const std::string& arrayName() const { return arrayName_; }

 private:
  std::filesystem::path path_;
  std::string arrayName_;
};

}  // namespace fluidviz
