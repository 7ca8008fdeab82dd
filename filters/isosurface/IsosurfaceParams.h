#pragma once
// Parameters of isosurface (3D) and isoline (2D) extraction. The contouring itself is VTK's
// Flying Edges (vtk/Isosurface.h); this header is VTK-free so scenes and docs can use it.
//
// References:
//   W. Schroeder, R. Maynard, B. Geveci, "Flying edges: A high-performance scalable isocontouring
//     algorithm", IEEE LDAV 2015, 33-40.
//   G. Taubin, T. Zhang, G. Golub, "Optimal surface smoothing as filter design", ECCV 1996
//     (windowed-sinc smoothing, vtkWindowedSincPolyDataFilter).
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz::isosurface {

struct IsosurfaceParams {
  std::string array;               ///< 1-component point array of the grid to contour (required)
  double value = 0.0;              ///< iso value, in the array's units (required); must lie
                                   ///< inside the array's finite range
  bool normals = true;             ///< 3D: per-point normals (from the field gradient; recomputed
                                   ///< from the triangles after smoothing)
  bool interpolate_arrays = true;  ///< carry the grid's other point arrays onto the surface
  int smoothing_iterations = 0;    ///< windowed-sinc smoothing passes, [0, 500]; 0 = none
  double smoothing_passband = 0.1; ///< windowed-sinc pass band, (0, 2]; smaller = smoother

  template <class V>
  static void describe(V& v) {
    v(&IsosurfaceParams::array, {.key = "array",
                                 .description = "1-component point array to contour",
                                 .required = true});
    v(&IsosurfaceParams::value, {.key = "value",
                                 .description = "iso value, in the array's units, inside its "
                                                "finite range",
                                 .required = true});
    v(&IsosurfaceParams::normals,
      {.key = "normals", .description = "3D: compute per-point normals for shading"});
    v(&IsosurfaceParams::interpolate_arrays,
      {.key = "interpolate_arrays",
       .description = "interpolate the grid's other arrays onto the surface"});
    v(&IsosurfaceParams::smoothing_iterations,
      {.key = "smoothing_iterations",
       .description = "windowed-sinc smoothing passes (Taubin 1996); 0 = none",
       .min = 0,
       .max = 500});
    v(&IsosurfaceParams::smoothing_passband,
      {.key = "smoothing_passband",
       .description = "windowed-sinc pass band; smaller removes more detail",
       .min = 0,
       .max = 2,
       .minExclusive = true});
  }
};

/// Range checks of every key and a non-empty array name. Throws ParamError.
void validateIsosurfaceParams(const IsosurfaceParams& params);

}  // namespace fluidviz::isosurface
