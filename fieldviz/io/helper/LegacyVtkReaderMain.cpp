// fluidviz-legacy-vtk-reader FILE.vtk: prints legacyVtkReport(FILE.vtk) (VtkLegacyReport.h) on
// stdout. Started by readLegacyVtk (VtkLegacyReader.cpp), not by users.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <string>

#include "fieldviz/io/VtkLegacyReport.h"

namespace {

bool writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fputs("usage: fluidviz-legacy-vtk-reader FILE.vtk\n"
               "A helper of fluidviz: reads a legacy VTK file for it in a separate process.\n",
               stderr);
    return 2;
  }
  const bool sent = writeAll(STDOUT_FILENO, fluidviz::legacyVtkReport(argv[1]));
  // _exit, not return: VTK 9.1's legacy reader leaks on its error paths, and the process ends
  // here without exit handlers (a sanitizer build's leak report among them).
  ::_exit(sent ? 0 : 1);
}
