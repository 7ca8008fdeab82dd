#pragma once
// Parameters of the streamline integrator that the whole project shares (streamline output,
// separatrices of the topology filter, evenly spaced seeding).
//
// Units: lengths are in CELLS, i.e. in continuous index space of the field's grid (node i at
// coordinate i), so a step of 0.2 means a fifth of a cell whatever the grid spacing in metres.
// Speeds are compared RELATIVE to the largest speed |v| found in the field.
#include <array>
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz::streamlines {

/// rk2 = explicit midpoint (order 2), rk4 = classical Runge-Kutta (order 4), rk45 = embedded
/// Dormand & Prince (1980) 5(4) pair with adaptive step (local extrapolation: the order-5
/// solution is kept, the order-4 one only estimates the error).
enum class Integrator { rk2, rk4, rk45 };
constexpr std::array<Choice<Integrator>, 3> paramChoices(Integrator) {
  return {{{Integrator::rk2, "rk2"}, {Integrator::rk4, "rk4"}, {Integrator::rk45, "rk45"}}};
}

/// Along v, against v, or both ways from the seed (one line through it).
enum class TraceDirection { forward, backward, both };
constexpr std::array<Choice<TraceDirection>, 3> paramChoices(TraceDirection) {
  return {{{TraceDirection::forward, "forward"}, {TraceDirection::backward, "backward"},
           {TraceDirection::both, "both"}}};
}

struct StreamlineParams {
  // Units, ranges and meanings of the members: their describe() declarations below.
  Integrator integrator = Integrator::rk4;
  double step = 0.25;
  double tolerance = 1e-6;
  double min_step = 1e-3;  ///< accepted even if too inaccurate
  double max_step = 2.0;
  TraceDirection direction = TraceDirection::both;
  double max_length = 1000.0;
  int max_steps = 100000;
  double stagnation_speed = 1e-4;
  bool loop_detection = true;
  double closing_distance = 0.1;

  template <class V>
  static void describe(V& v) {
    v(&StreamlineParams::integrator,
      {.key = "integrator",
       .description = "rk2: midpoint, order 2; rk4: classical, order 4; rk45: Dormand-Prince "
                      "5(4) with adaptive step controlled by `tolerance`"});
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
       .description = "forward: along v; backward: against v; both: one line through the seed"});
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
       .max = 1,
       .maxExclusive = true});
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
/// combinations (rk45 needs min_step <= step <= max_step).
void validateStreamlineParams(const StreamlineParams& p);

}  // namespace fluidviz::streamlines
