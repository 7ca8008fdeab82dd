#pragma once
// Shared by the libFuzzer targets of tests/fuzz (issue 8). A fuzz input is hostile user input:
// the errors fluidviz reports as "bad input" (exit code 2: SceneError, FileError, DataArrayError,
// ParamError) are the correct outcome and are swallowed here. Anything else escapes and is a
// finding: a crash or sanitizer report, an exception of another type (exit code 1 or a terminate),
// or an allocation beyond libFuzzer's -malloc_limit_mb (enormous sizes must be refused first).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "fieldviz/core/Params.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/scene/SceneFile.h"
#include "fieldviz/vtk/ImageDataAdapter.h"

namespace fluidviz::fuzz {

/// FLUIDVIZ_FUZZ_PRINT_ERRORS=1 prints each swallowed message (to see what seeds reach).
inline void noteBadInputError(const std::exception& e) {
  static const bool print = std::getenv("FLUIDVIZ_FUZZ_PRINT_ERRORS") != nullptr;
  if (print) std::fprintf(stderr, "bad input (expected): %s\n", e.what());
}

template <class F>
void expectOnlyBadInputErrors(F&& body) {
  try {
    body();
  } catch (const scene::SceneError& e) {
    noteBadInputError(e);
  } catch (const FileError& e) {
    noteBadInputError(e);
  } catch (const DataArrayError& e) {
    noteBadInputError(e);
  } catch (const ParamError& e) {
    noteBadInputError(e);
  }
}

/// A path in the temporary folder owned by this process and removed when it exits (libFuzzer ends
/// with exit(), which runs static destructors), so replays and runs leave nothing in /tmp.
class ProcessScratch {
 public:
  explicit ProcessScratch(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {}
  ~ProcessScratch() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ProcessScratch(const ProcessScratch&) = delete;
  ProcessScratch& operator=(const ProcessScratch&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// The readers take paths, so each input is written to one file per process (libFuzzer runs
/// inputs one after another in a process), named with the extension the reader expects.
inline std::filesystem::path writeInputFile(const std::uint8_t* data, std::size_t size,
                                            const char* extension) {
  static const ProcessScratch scratch(std::string("fluidviz_fuzz_") + (extension + 1));
  static const bool made = std::filesystem::create_directories(scratch.path());
  (void)made;
  const std::filesystem::path path = scratch.path() / (std::string("input") + extension);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace fluidviz::fuzz
