#pragma once
// The 3D picture flags `fluidviz resample` and `fluidviz isosurface` share (View3DParams:
// size, camera, background, outline, legend, turntable) and writing the pictures.
#include <filesystem>
#include <iosfwd>
#include <set>
#include <string>
#include <vector>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "fieldviz/render/View3D.h"

namespace fluidviz::app {

/// Options taking a value, and switches, that readView3DFlags understands.
std::set<std::string> view3DValuedOptions();
std::set<std::string> view3DSwitches();

/// The view flags of `a`, checked (UsageError names the flag and the allowed range).
View3DParams readView3DFlags(const ParsedArgs& a);

/// Help lines describing the flags.
extern const char* kView3DHelp;

/// Renders `scene` to `png` and, if the view asks for turntable frames, to png's stem +
/// "_0000.png", ...; reports what was written on `out`.
void writeScenePictures(Scene3D& scene, const std::filesystem::path& png, std::ostream& out);

}  // namespace fluidviz::app
