#pragma once
// Memory sizes in messages ("would need 2.4e+08 GB"), and the memory of this machine, so that
// readers and grid planners can refuse a request before allocating it.
#include <string>

namespace fluidviz {

/// "12.3 MB", "4.1 GB", "2.4e+08 GB" (decimal units, 3 significant digits).
std::string formatBytes(double bytes);

/// Physical memory of this machine in bytes (sysconf); 0 if it cannot be told.
double physicalMemoryBytes();

}  // namespace fluidviz
