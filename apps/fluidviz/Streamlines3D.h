#pragma once
// The 3D picture of `fluidviz streamlines` on a 3D field: the lines (or tubes) coloured by an
// array, the domain's outline, optional context (a z slice of the speed or an isosurface), with
// the camera flags of `fluidviz isosurface` (View3DFlags).
#include <memory>
#include <optional>
#include <string>

#include <vtkPolyData.h>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "fieldviz/render/View3D.h"

namespace fluidviz::app {

struct Streamlines3DPicture {
  View3DParams view;
  std::string color_by = "speed";  ///< speed, integration_time, or a point array of the field
  std::string colormap = "viridis";
  double line_width = 1.5;         ///< px (lines)
  double tube_radius = 0.0;        ///< cells; > 0 draws tubes instead of lines
  std::string context;             ///< "", "slice:z=K" or "isosurface:ARRAY=V"
  std::optional<std::string> title;  ///< --title (empty: none); unset: says what it shows
};

/// The scene, built before any output is written so that its errors (UsageError naming the
/// flag, FileError naming the file) stop the command first.
std::unique_ptr<Scene3D> streamlinesScene(const FlowInput& in, vtkPolyData* lines,
                                          const Streamlines3DPicture& picture);

}  // namespace fluidviz::app
