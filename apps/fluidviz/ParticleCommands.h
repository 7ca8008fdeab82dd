#pragma once
// The commands on particle data and grids in 3D: `fluidviz resample` (ResampleCommand.cpp) and
// `fluidviz isosurface` (IsosurfaceCommand.cpp). Signature: Commands.h CommandFunction.
#include <iosfwd>
#include <string>
#include <vector>

namespace fluidviz::app {

int resampleCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                    bool interactive);
int isosurfaceCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                      bool interactive);

}  // namespace fluidviz::app
