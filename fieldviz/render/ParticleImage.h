#pragma once
// A picture of SPH particles (fieldviz/render/ParticleRendering.h spheres) coloured by a point
// array, with title, colour legend and the domain's outline: the particle counterpart of
// FieldImage. 2D sets are seen orthographically from +z (x to the right, y up), the domain box
// filling the picture left of the legend; 3D sets in perspective from azimuth 30 deg, elevation
// 20 deg (View3D.h's convention, y up). Boundary particles, if given, are drawn in light grey
// (2D only: in 3D the walls would hide the fluid).
#include <array>
#include <string>

#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/RgbaImage.h"

class vtkPolyData;

namespace fluidviz {

struct ParticlePictureParams {
  FieldImageParams picture;            ///< size, colour map, range, title, legend, background
  std::string color_by = "speed";      ///< point array of `fluid` colouring the particles
  double radius = 0.0;                 ///< m, drawn radius (> 0), e.g. half the spacing
  int dimension = 2;                   ///< 2: orthographic xy view; 3: perspective
  std::array<double, 6> domain{0, 1, 0, 1, 0, 0};  ///< framed and outlined box (xmin, xmax, ...)
};

/// Throws ParamError for bad picture keys, std::invalid_argument for a missing color_by array,
/// std::runtime_error if no OpenGL context can be made. `boundary` may be null.
RgbaImage renderParticlePicture(vtkPolyData* fluid, vtkPolyData* boundary,
                                const ParticlePictureParams& params);

}  // namespace fluidviz
