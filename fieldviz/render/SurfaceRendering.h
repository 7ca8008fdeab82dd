#pragma once
// A shaded surface (isosurface, boundary) as an actor: Phong lighting with a solid colour, or
// coloured by one of its point arrays through a colour map.
#include <array>
#include <optional>
#include <string>

#include <vtkActor.h>
#include <vtkSmartPointer.h>

#include "fieldviz/core/Params.h"
#include "fieldviz/render/ArrayColoring.h"
#include "fieldviz/render/ColorMap.h"

class vtkPolyData;

namespace fluidviz {

struct SurfaceStyle {
  std::array<double, 3> color{0.30, 0.55, 0.85};  ///< RGB in [0, 1] when color_by is empty
  std::string color_by;               ///< point array colouring the surface; empty: `color`
  std::string colormap = "viridis";   ///< one of ColorMap::names()
  std::optional<double> range_min;    ///< value of the first colour; empty: array minimum
  std::optional<double> range_max;    ///< value of the last colour; empty: array maximum
  double opacity = 1.0;               ///< (0, 1]
  double specular = 0.3;              ///< Phong specular weight, [0, 1]
  double specular_power = 30.0;       ///< Phong exponent, [1, 200]

  template <class V>
  static void describe(V& v) {
    v(&SurfaceStyle::color, {.key = "color", .description = "RGB of an uncoloured surface",
                             .min = 0, .max = 1});
    v(&SurfaceStyle::color_by,
      {.key = "color_by", .description = "point array colouring the surface; empty: color"});
    v(&SurfaceStyle::colormap,
      {.key = "colormap", .description = "colour map", .choices = ColorMap::names()});
    v(&SurfaceStyle::range_min,
      {.key = "range_min", .description = "value of the first colour; empty: array minimum"});
    v(&SurfaceStyle::range_max,
      {.key = "range_max", .description = "value of the last colour; empty: array maximum"});
    v(&SurfaceStyle::opacity, {.key = "opacity", .description = "1: opaque", .min = 0,
                               .max = 1, .minExclusive = true});
    v(&SurfaceStyle::specular, {.key = "specular", .description = "Phong specular weight",
                                .min = 0, .max = 1});
    v(&SurfaceStyle::specular_power,
      {.key = "specular_power", .description = "Phong exponent (highlight size)", .min = 1,
       .max = 200});
  }
};

struct SurfaceActor {
  vtkSmartPointer<vtkActor> actor;
  std::optional<ArrayColoring> coloring;  ///< set when style.color_by names an array
};

/// Throws ParamError for bad style keys, std::invalid_argument for a bad color_by array.
SurfaceActor makeSurfaceActor(vtkPolyData* surface, const SurfaceStyle& style);

}  // namespace fluidviz
