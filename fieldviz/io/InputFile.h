#pragma once
// The first check of every reader: the path names a file that can be opened.
#include <filesystem>

namespace fluidviz {

/// Throws FileError: the file does not exist, is a folder, or cannot be opened (with the OS's
/// reason).
void requireReadableFile(const std::filesystem::path& path);

}  // namespace fluidviz
