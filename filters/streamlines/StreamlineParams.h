#pragma once
// Parameters of the streamline integrator that the whole project shares (streamline output,
// separatrices of the topology filter, evenly spaced seeding).
//
// Units: lengths are in CELLS, i.e. in continuous index space of the field's grid (node i at
// coordinate i), so a step of 0.2 means a fifth of a cell whatever the grid spacing in metres.
// Speeds are compared RELATIVE to the largest speed |v| found in the field.
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz::streamlines {

struct StreamlineParams {
  /// rk2 = explicit midpoint (order 2), rk4 = classical Runge-Kutta (order 4), rk45 = embedded
  /// Dormand & Prince (1980) 5(4) pair with adaptive step (local extrapolation: the order-5
  /// solution is kept, the order-4 one only estimates the error).
  std::string integrator = "rk4";
  double step = 0.25;          ///< cells, arc length of one step (rk45: the first step), (0, 100]
  double tolerance = 1e-6;     ///< rk45 only: allowed local error per cell of arc length, (0, 0.1]
  double min_step = 1e-3;      ///< cells, rk45 smallest step (accepted even if too inaccurate), > 0
  double max_step = 2.0;       ///< cells, rk45 largest step, >= min_step, <= 100
  std::string direction = "both";  ///< forward (along v), backward (against v) or both
  double max_length = 1000.0;  ///< cells, arc length of each direction, (0, 1e9]
  int max_steps = 100000;      ///< accepted steps per direction, [1, 1e9]
  double stagnation_speed = 1e-4;  ///< stop where |v| <= this * max|v| of the field, [0, 1)
  bool loop_detection = true;  ///< stop with closed_loop when the line returns to its seed
  double closing_distance = 0.1;  ///< cells, how close the return to the seed must be, (0, 100]

  template <class V>
  static void describe(V& v) {
    v(&StreamlineParams::integrator,
      {.key = "integrator",
       .description = "rk2: midpoint, order 2; rk4: classical, order 4; rk45: Dormand-Prince "
                      "5(4) with adaptive step controlled by `tolerance`",
       .choices = {"rk2", "rk4", "rk45"}});
    v(&StreamlineParams::step, {.key = "step",
                                .unit = "cells",
                                .description = "arc length of one integration step (rk45: the "
                                               "first step); error ~ step^2 (rk2), step^4 (rk4)",
                                .min = 0,
                                .max = 100,
                                .minExclusive = true});
    v(&StreamlineParams::tolerance,
      {.key = "tolerance",
       .description = "rk45: allowed local error estimate per cell of arc length",
       .min = 0,
       .max = 0.1,
       .minExclusive = true});
    v(&StreamlineParams::min_step, {.key = "min_step",
                                    .unit = "cells",
                                    .description = "rk45: smallest step (taken even when the "
                                                   "error estimate exceeds the tolerance)",
                                    .min = 0,
                                    .max = 100,
                                    .minExclusive = true});
    v(&StreamlineParams::max_step, {.key = "max_step",
                                    .unit = "cells",
                                    .description = "rk45: largest step, >= min_step",
                                    .min = 0,
                                    .max = 100,
                                    .minExclusive = true});
    v(&StreamlineParams::direction,
      {.key = "direction",
       .description = "forward: along v; backward: against v; both: one line through the seed",
       .choices = {"forward", "backward", "both"}});
    v(&StreamlineParams::max_length, {.key = "max_length",
                                      .unit = "cells",
                                      .description = "arc length traced in each direction",
                                      .min = 0,
                                      .max = 1e9,
                                      .minExclusive = true});
    v(&StreamlineParams::max_steps,
      {.key = "max_steps", .description = "accepted steps per direction", .min = 1, .max = 1e9});
    v(&StreamlineParams::stagnation_speed,
      {.key = "stagnation_speed",
       .description = "stop where |v| <= stagnation_speed * (largest |v| of the field)",
       .min = 0,
       .max = 1});
    v(&StreamlineParams::loop_detection,
      {.key = "loop_detection",
       .description = "stop (reason closed_loop) when the line comes back to its seed"});
    v(&StreamlineParams::closing_distance,
      {.key = "closing_distance",
       .unit = "cells",
       .description = "a line closes when a step passes this close to its seed",
       .min = 0,
       .max = 100,
       .minExclusive = true});
  }
};

/// Throws ParamError naming the key for values outside their declared ranges and for bad
/// combinations (stagnation_speed must be < 1; rk45 needs min_step <= step <= max_step).
void validateStreamlineParams(const StreamlineParams& p);

}  // namespace fluidviz::streamlines
