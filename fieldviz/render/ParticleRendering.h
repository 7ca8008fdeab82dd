#pragma once
// Particles as spheres of a given world radius, coloured by a point array or a solid colour.
//   spheres: one lit sphere mesh instanced per particle (vtkGlyph3DMapper): true geometry,
//            exact silhouettes and shading; ~0.2 s per 10^4 particles under OSMesa llvmpipe.
//   sprites: one screen-facing square per particle, cut to a disc and darkened towards its rim
//            by a fragment shader (vtkPointGaussianMapper): a fast imitation for 10^5-10^6
//            particles. (Emissive splats draw nothing visible on a white background; the
//            mapper is used non-emissive.)
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

/// Lit sphere meshes, or shaded discs (fast for millions).
enum class ParticleMethod { spheres, sprites };
constexpr std::array<Choice<ParticleMethod>, 2> paramChoices(ParticleMethod) {
  return {{{ParticleMethod::spheres, "spheres"}, {ParticleMethod::sprites, "sprites"}}};
}

struct ParticleStyle {
  double radius = 0.0;                ///< callers often use s / 2
  ParticleMethod method = ParticleMethod::spheres;
  int sphere_resolution = 12;
  std::array<double, 3> color{0.85, 0.45, 0.2};  ///< RGB when color_by is empty
  std::string color_by;               ///< point array colouring the particles; empty: color
  std::string colormap = "viridis";   ///< one of ColorMap::names()
  std::optional<double> range_min;    ///< value of the first colour; empty: array minimum
  std::optional<double> range_max;    ///< value of the last colour; empty: array maximum

  template <class V>
  static void describe(V& v) {
    v(&ParticleStyle::radius, {.key = "radius", .unit = "m", .description = "sphere radius",
                               .min = 0, .minExclusive = true});
    v(&ParticleStyle::method, {.key = "method",
                               .description = "spheres: lit sphere meshes; sprites: shaded "
                                              "discs, fast for millions"});
    v(&ParticleStyle::sphere_resolution,
      {.key = "sphere_resolution", .description = "segments around each sphere", .min = 4,
       .max = 64});
    v(&ParticleStyle::color, {.key = "color", .description = "RGB of uncoloured particles",
                              .min = 0, .max = 1});
    v(&ParticleStyle::color_by,
      {.key = "color_by", .description = "point array colouring the particles; empty: color"});
    v(&ParticleStyle::colormap,
      {.key = "colormap", .description = "colour map", .choices = ColorMap::names()});
    v(&ParticleStyle::range_min,
      {.key = "range_min", .description = "value of the first colour; empty: array minimum"});
    v(&ParticleStyle::range_max,
      {.key = "range_max", .description = "value of the last colour; empty: array maximum"});
  }
};

struct ParticleActor {
  vtkSmartPointer<vtkActor> actor;
  std::optional<ArrayColoring> coloring;  ///< set when style.color_by names an array
};

/// The points of `particles` drawn as spheres. Throws ParamError for bad style keys,
/// std::invalid_argument for a bad color_by array.
ParticleActor makeParticleActor(vtkPolyData* particles, const ParticleStyle& style);

}  // namespace fluidviz
