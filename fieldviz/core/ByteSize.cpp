#include "fieldviz/core/ByteSize.h"

#include <unistd.h>

#include <sstream>

namespace fluidviz {

std::string formatBytes(double bytes) {
  std::ostringstream s;
  s.precision(3);
  if (bytes >= 1e9)
    s << bytes / 1e9 << " GB";
  else if (bytes >= 1e6)
    s << bytes / 1e6 << " MB";
  else
    s << bytes / 1e3 << " kB";
  return s.str();
}

double physicalMemoryBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long pageSize = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(pageSize);
}

}  // namespace fluidviz
