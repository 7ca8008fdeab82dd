#include "fieldviz/core/AtomicFile.h"

#include <atomic>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace fluidviz {

namespace {
std::filesystem::path temporaryNameFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  // The extension is kept last so that writers which check it (VTK's XML writers) accept the name.
  std::filesystem::path tmp = target;
  tmp.replace_filename("." + target.stem().string() + ".tmp" + std::to_string(getpid()) + "_" +
                       std::to_string(counter++) + target.extension().string());
  return tmp;
}
}  // namespace

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

void writeTextAtomically(const std::filesystem::path& target, const std::string& content) {
  writeAtomically(target, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + target.string() + ": cannot open file");
    out << content;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + target.string() + ": write failed");
  });
}

}  // namespace fluidviz
