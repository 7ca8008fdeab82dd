#pragma once
// The picture of a 3D field's topology: critical points as spheres coloured by type, the 1D
// separatrices as lines and the separating surfaces as translucent sheets (red: unstable
// manifolds, traced forward; blue: stable ones), inside the outline of the grid, seen through
// the 3D camera of `fluidviz isosurface` (View3D.h), with a legend strip below that lists the
// types present and the line and surface colours.
#include <string>
#include <vector>

#include "fieldviz/core/Grid.h"
#include "fieldviz/render/RgbaImage.h"
#include "fieldviz/render/View3D.h"
#include "filters/topology/CriticalPoint3D.h"
#include "filters/topology/SeparatingSurfaces.h"
#include "filters/topology/Separatrices3D.h"

namespace fluidviz {

struct Topology3DPictureParams {
  View3DParams view;
  std::string title;             ///< empty: none
  double glyph_size = 16.0;      ///< sphere diameter, px at zoom 1 (the data's bounding sphere
                                 ///< spans the picture height)
  double surface_opacity = 0.35;
};

/// Colour of a 3D critical point type name (the 2D glyph colours where the names agree).
Rgb criticalPoint3DColor(const std::string& typeName);

/// Renders the picture (legend strip below). Throws std::runtime_error without a GL context.
RgbaImage renderTopology3DPicture(const Grid& grid,
                                  const std::vector<topology::CriticalPoint3D>& points,
                                  const std::vector<topology::Separatrix3D>& separatrices,
                                  const std::vector<topology::SeparatingSurface>& surfaces,
                                  const Topology3DPictureParams& params);

}  // namespace fluidviz
