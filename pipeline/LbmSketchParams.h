#pragma once
// lbm.sketch: the strokes and settings of lbm.initial_flow = sketch (issue 20; Judice & Giraldi
// 2012). The LBM starts from the field a user's strokes sketch: filters/sketch projects them onto
// the LBM's node grid, extends them by Gradient Vector Flow (Xu & Prince 1998) and optionally
// makes the result divergence-free (pipeline/LbmSketchStart.h). The solver itself knows nothing
// of strokes (solvers/ do not use filters/), so this section lives here, beside lbm.*.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "filters/sketch/SketchParams.h"
#include "solvers/lbm/LbmParams.h"

namespace fluidviz {

/// One stroke drawn in the scene: a streamline of the initial flow with its speed.
struct SketchStrokeParams {
  std::vector<std::array<double, 2>> points;  ///< m, in drawing order (the flow's direction)
  double speed = 1.0;                         ///< m/s along the stroke; negative reverses it

  template <class V>
  static void describe(V& v) {
    v(&SketchStrokeParams::points,
      {.key = "points",
       .unit = "m",
       .description = "the stroke's points [[x, y], ...] in drawing order (the flow's "
                      "direction), inside the box; at least two distinct ones",
       .required = true});
    v(&SketchStrokeParams::speed,
      {.key = "speed",
       .unit = "m/s",
       .description = "speed of the flow along the stroke; negative reverses its direction"});
  }
};

/// The strokes (inline and/or from a file) and the sketch filter's settings.
struct LbmSketchParams : sketch::SketchParams {
  std::vector<SketchStrokeParams> strokes;
  std::string file;  ///< .csv, .vtp or .svg (filters/sketch/vtk/StrokeFiles.h), relative to the scene

  template <class V>
  static void describe(V& v) {
    v(&LbmSketchParams::strokes,
      {.key = "strokes",
       .description = "strokes drawn in the scene (with or instead of `file`)"});
    v(&LbmSketchParams::file,
      {.key = "file",
       .description = "stroke file, relative to the scene file's folder: .csv (columns stroke, "
                      "x, y, speed) or .vtp (polylines; speed from the cell- or point-data "
                      "array \"speed\", else 1 m/s) or .svg (paths: M L H V C Z, 1 unit = 1 m, "
                      "y up within the viewBox; speed from data-speed, else 1 m/s); see "
                      "`fluidviz sketch --help`"});
    sketch::SketchParams::describe(v);
  }
};

/// The scene's lbm section: the solver's parameters and, for initial_flow = sketch, the sketch.
struct LbmSceneParams : lbm::LbmParams {
  LbmSketchParams sketch;

  template <class V>
  static void describe(V& v) {
    lbm::LbmParams::describe(v);
    v(&LbmSceneParams::sketch,
      {.key = "sketch",
       .description = "initial_flow sketch: the strokes and how they become the initial field "
                      "on the LBM's nodes (gvf.boundary_x/y must be periodic exactly where the "
                      "walls are)"});
  }
};

}  // namespace fluidviz
