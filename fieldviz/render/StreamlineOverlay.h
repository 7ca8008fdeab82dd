#pragma once
// Streamlines drawn on top of a field picture (FieldImageScene): polylines in one colour, with
// optional arrowheads pointing downstream (the order of each line's points). An outline in the
// opposite shade (black around light lines, white around dark ones) keeps them visible on every
// colour of the map.
#include <array>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/Params.h"
#include "fieldviz/render/FieldImage.h"

namespace fluidviz {

struct StreamlineStyle {
  std::array<double, 3> line_color{1.0, 1.0, 1.0};  ///< RGB in [0, 1]
  double line_width = 1.5;       ///< px, [0.5, 20]
  double outline_width = 1.0;    ///< px on each side of the line, [0, 10]; 0 = no outline
  bool arrows = true;            ///< arrowheads pointing downstream along each line
  double arrow_spacing = 120.0;  ///< px of line between arrowheads, [10, 10000]
  double arrow_size = 9.0;       ///< px, length of an arrowhead, [2, 100]

  template <class V>
  static void describe(V& v) {
    v(&StreamlineStyle::line_color,
      {.key = "line_color", .description = "RGB colour of the lines", .min = 0, .max = 1});
    v(&StreamlineStyle::line_width,
      {.key = "line_width", .unit = "px", .description = "line width", .min = 0.5, .max = 20});
    v(&StreamlineStyle::outline_width,
      {.key = "outline_width",
       .unit = "px",
       .description = "outline on each side of lines and arrowheads, in the opposite shade "
                      "(black around light lines); 0 = none",
       .min = 0,
       .max = 10});
    v(&StreamlineStyle::arrows,
      {.key = "arrows", .description = "draw arrowheads pointing downstream"});
    v(&StreamlineStyle::arrow_spacing, {.key = "arrow_spacing",
                                        .unit = "px",
                                        .description = "length of line between arrowheads (the "
                                                       "first sits half of it from the start)",
                                        .min = 10,
                                        .max = 10000});
    v(&StreamlineStyle::arrow_size, {.key = "arrow_size",
                                     .unit = "px",
                                     .description = "length of an arrowhead",
                                     .min = 2,
                                     .max = 100});
  }
};

/// Arrowhead triangles (tip, left, right corner; world coordinates at z) every `spacing` world
/// units of arc length along each line, starting at spacing / 2, pointing along the line.
std::vector<std::array<Vec3, 3>> arrowheads(const std::vector<std::vector<Vec3>>& lines,
                                            double spacing, double size, double z);

/// Adds the lines (world coordinates; drawn just above the texture overlays of the scene) and
/// their arrowheads. `pixelsPerUnit` converts the style's px to world units. Lines with fewer
/// than 2 points are not drawn. Throws ParamError for a style outside its ranges.
void addStreamlineOverlay(FieldImageScene& scene, const std::vector<std::vector<Vec3>>& lines,
                          const StreamlineStyle& style, double pixelsPerUnit);

}  // namespace fluidviz
