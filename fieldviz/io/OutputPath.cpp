#include "fieldviz/io/OutputPath.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <sys/stat.h>
#include <unistd.h>

#include "fieldviz/core/AtomicFile.h"
#include "fieldviz/io/FileError.h"

namespace fluidviz {

namespace {

[[noreturn]] void throwCannotWrite(const std::filesystem::path& target, const std::string& why) {
  throw FileError(target, "cannot write " + target.string() + ": " + why);
}

std::string osReason(int error) { return std::strerror(error); }

void closeOrThrow(std::FILE* file, const std::filesystem::path& target) {
  if (std::fclose(file) != 0) throwCannotWrite(target, osReason(errno));
}

}  // namespace

std::filesystem::path folderOf(const std::filesystem::path& file) {
  const std::filesystem::path parent = file.parent_path();
  return parent.empty() ? std::filesystem::path(".") : parent;
}

void requireWritableFolder(const std::filesystem::path& target) {
  const std::filesystem::path folder = folderOf(target);
  struct stat info {};
  if (::stat(folder.c_str(), &info) != 0) {
    const int error = errno;
    throwCannotWrite(target, "folder '" + folder.string() + "' " +
                                 (error == ENOENT ? "does not exist" : "cannot be accessed") +
                                 " (" + osReason(error) + ")");
  }
  if (!S_ISDIR(info.st_mode))
    throwCannotWrite(target, "'" + folder.string() + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throwCannotWrite(target, "folder '" + folder.string() + "' is not writable (" +
                                 osReason(errno) + ")");
  std::error_code ignored;  // e.g. a name too long: the write itself will report that
  if (std::filesystem::is_directory(target, ignored))
    throwCannotWrite(target, "a folder of that name exists");
}

void requireCreatableFolder(const std::filesystem::path& folder) {
  // Walk up to the nearest path that exists; ENOTDIR means a component on the way is a file.
  std::filesystem::path existing = folder.empty() ? std::filesystem::path(".") : folder;
  auto cannot = [&](const std::string& problem) {
    const std::string name = existing.string();
    throw FileError(folder, "cannot create output folder " + folder.string() + ": '" + name +
                                "' " + problem);
  };
  struct stat info {};
  while (::stat(existing.c_str(), &info) != 0) {
    const int error = errno;
    if (error != ENOENT && error != ENOTDIR) cannot("cannot be accessed (" + osReason(error) + ")");
    std::filesystem::path parent = existing.parent_path();
    if (parent.empty()) parent = ".";
    if (parent == existing) cannot("does not exist");
    existing = parent;
  }
  if (!S_ISDIR(info.st_mode)) cannot("is not a folder");
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    cannot("is a folder that is not writable (" + osReason(errno) + ")");
}

void writeOutputAtomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& tmp)>& write) {
  requireWritableFolder(target);
  try {
    writeAtomically(target, write);
  } catch (const FileError&) {
    throw;
  } catch (const std::filesystem::filesystem_error& e) {
    throwCannotWrite(target, e.code().message());
  } catch (const std::runtime_error& e) {
    throwCannotWrite(target, e.what());
  }
}

void writeTextOutput(const std::filesystem::path& target, const std::string& content) {
  writeOutputAtomically(target, [&](const std::filesystem::path& tmp) {
    std::FILE* file = std::fopen(tmp.c_str(), "wb");
    if (!file) throwCannotWrite(target, osReason(errno));
    if (std::fwrite(content.data(), 1, content.size(), file) != content.size()) {
      const int error = errno;
      std::fclose(file);
      throwCannotWrite(target, osReason(error));
    }
    closeOrThrow(file, target);
  });
}

}  // namespace fluidviz
