#include "fieldviz/io/InputFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "fieldviz/io/FileError.h"

namespace fluidviz {

void requireReadableFile(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))
    throw FileError(path, "file " + path.string() + " does not exist");
  if (std::filesystem::is_directory(status))
    throw FileError(path, "file " + path.string() + " is a folder, not a VTK file");
  std::ifstream probe(path, std::ios::binary);
  if (!probe)
    throw FileError(path, "file " + path.string() + " cannot be opened (" +
                              std::strerror(errno) + ")");
}

}  // namespace fluidviz
