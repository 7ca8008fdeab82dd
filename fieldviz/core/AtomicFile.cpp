#include "fieldviz/core/AtomicFile.h"

#include <atomic>
#include <regex>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace fluidviz {

namespace {
std::filesystem::path temporaryNameFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  // The extension is kept last so that writers which check it (VTK's XML writers) accept the name.
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp" + std::to_string(getpid()) + "_" + std::to_string(counter++);
  name += target.extension().string();
  std::filesystem::path tmp = target;
  tmp.replace_filename(name);
  return tmp;
}
}  // namespace

long temporaryFileWriter(const std::filesystem::path& file) {
  // temporaryNameFor: "." stem ".tmp" pid "_" counter extension
  static const std::regex name(R"(\..*\.tmp([0-9]{1,9})_[0-9]+(\.[^.]*)?)");
  std::smatch m;
  const std::string text = file.filename().string();
  if (!std::regex_match(text, m, name)) return -1;
  return std::stol(m[1].str());
}

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write) {
  const std::filesystem::path tmp = temporaryNameFor(target);
  try {
    write(tmp);
    if (!std::filesystem::exists(tmp))
      throw std::runtime_error("writer produced no file for " + target.string());
    std::filesystem::rename(tmp, target);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

}  // namespace fluidviz
