#pragma once
// Checks and atomic writing shared by every fluidviz writer. Output goes to a temporary file in
// the destination folder and is renamed into place (core/AtomicFile.h); failures become FileError
// naming the target and the operating system's reason.
#include <filesystem>
#include <functional>
#include <string>

namespace fluidviz {

/// The folder a file is written into: its parent, or "." for a bare file name.
std::filesystem::path folderOf(const std::filesystem::path& file);

/// Throws FileError if the folder `target` would be written into is missing, is not a folder or
/// is not writable ("cannot write out/a.vti: folder 'out' does not exist (No such file or ...)").
void requireWritableFolder(const std::filesystem::path& target);

/// Throws FileError unless `folder` is a writable folder or can be created: its nearest existing
/// ancestor must be a writable folder ("cannot create output folder a.json/out: 'a.json' is not
/// a folder"). Creates nothing, so a run refused later leaves no folder behind.
void requireCreatableFolder(const std::filesystem::path& folder);

/// requireWritableFolder, then writeAtomically(target, write), with any std::filesystem or
/// std::runtime_error failure rethrown as FileError naming the target. No file is left behind.
void writeOutputAtomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& tmp)>& write);

/// Atomic text file; write errors carry the OS reason.
void writeTextOutput(const std::filesystem::path& target, const std::string& content);

}  // namespace fluidviz
