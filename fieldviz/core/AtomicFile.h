#pragma once
// Every output is written under a temporary name in its destination folder and renamed into place
// when complete, so a crash, a kill or a full disk never leaves a half-written file behind.
#include <filesystem>
#include <functional>

namespace fluidviz {

/// Calls write(tmp) with a temporary path next to `target`, then renames tmp to target.
/// If write throws, the temporary file is removed and the exception propagates.
/// (fieldviz/io/OutputPath.h adds folder checks and OS reasons on top, for user-facing outputs.)
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp)>& write);

/// The process id in the name of a temporary file writeAtomically made (a kill may leave one
/// behind), or -1 if `file` is not named like one.
long temporaryFileWriter(const std::filesystem::path& file);

}  // namespace fluidviz
