#pragma once
// Evenly spaced streamlines in 2D, after B. Jobard and W. Lefer, "Creating evenly-spaced
// streamlines of arbitrary density", Visualization in Scientific Computing 1997, pp. 43-55.
//
// Every line is traced in both directions from a seed that lies at least d_sep from all existing
// lines, and a branch stops (reason too_close) before a point comes closer than
// d_test = test_ratio * d_sep to another line - or to a part of its own line more than
// 3 d_sep of arc length away (spirals). New seeds are taken at distance d_sep on both sides of
// every point of every accepted line, in the order lines were accepted; when that queue runs
// dry, a scan of candidate points every d_sep / 2 over the domain fills regions the queue could
// not reach (flow regions separated by stagnation). Distance queries use a uniform background
// grid with cells of size d_sep, so each query looks at 3 x 3 cells.
//
// Distances are in world units measured as multiples of the smaller in-plane grid spacing
// ("cells"), so the spacing looks even on a grid with non-square cells.
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/Params.h"
#include "filters/streamlines/Streamline.h"

namespace fluidviz::streamlines {

struct EvenlySpacedParams {
  double separating_distance = 8.0;  ///< cells, d_sep between neighbouring lines, [0.5, 1e4]
  double test_ratio = 0.5;           ///< d_test / d_sep, (0, 1]
  int max_lines = 10000;             ///< stop after this many lines, [1, 1e7]

  template <class V>
  static void describe(V& v) {
    v(&EvenlySpacedParams::separating_distance,
      {.key = "separating_distance",
       .unit = "cells",
       .description = "distance d_sep between neighbouring lines (Jobard & Lefer 1997), in "
                      "multiples of the smaller in-plane grid spacing",
       .min = 0.5,
       .max = 1e4});
    v(&EvenlySpacedParams::test_ratio,
      {.key = "test_ratio",
       .description = "d_test / d_sep: a line stops before coming closer than d_test to another",
       .min = 0,
       .max = 1,
       .minExclusive = true});
    v(&EvenlySpacedParams::max_lines,
      {.key = "max_lines", .description = "largest number of lines", .min = 1, .max = 1e7});
  }
};

/// Evenly spaced streamlines of a 2D field. `integration.direction` is ignored (lines are traced
/// both ways). Throws std::invalid_argument naming the array for a 3D field, ParamError for
/// parameters outside their ranges. Lines that are only a seed (stagnation) are dropped.
std::vector<Streamline> evenlySpacedStreamlines(const VectorField& field,
                                                const EvenlySpacedParams& params,
                                                const StreamlineParams& integration);

}  // namespace fluidviz::streamlines
