#pragma once
// Parameters of sketched flows (issue 20; Judice & Giraldi 2012): how strokes are filtered,
// projected onto the grid, smoothed and extended over the domain by Gradient Vector Flow
// (Xu & Prince 1998). Each member is declared once, with unit and range, in describe().
#include <array>
#include <optional>

#include "fieldviz/core/Params.h"

namespace fluidviz::sketch {

/// How Gradient Vector Flow's steady state is reached.
/// explicit_euler: the time-marching scheme of Xu & Prince 1998, stable limit enforced.
/// direct: one sparse factorisation of (mu lap - b) v = -b v0 (Eigen SimplicialLDLT).
enum class GvfSolver { explicit_euler, direct };
constexpr std::array<Choice<GvfSolver>, 2> paramChoices(GvfSolver) {
  return {{{GvfSolver::explicit_euler, "explicit"}, {GvfSolver::direct, "direct"}}};
}

/// What lies beyond a side of the grid: zero flux across the face half a cell outside the last
/// node (Neumann, the image-border rule of Xu & Prince), or the opposite side (periodic: node
/// dims - 1 neighbours node 0).
enum class SketchBoundary { zero_flux, periodic };
constexpr std::array<Choice<SketchBoundary>, 2> paramChoices(SketchBoundary) {
  return {{{SketchBoundary::zero_flux, "zero_flux"}, {SketchBoundary::periodic, "periodic"}}};
}

/// Gradient Vector Flow, Xu & Prince 1998 with the edge map's gradient replaced by the
/// projected strokes v0: dv/dt = mu lap(v) - b (v - v0), b = |v0|^2 / max|v0|^2 (or another
/// weight in [0, 1], gvf/GradientVectorFlow.h). The weight is normalised to [0, 1] as Xu & Prince
/// normalise their edge map, so the pseudo-time t has no unit and mu is a squared length: given
/// here in cells^2 (mu hx hy in m^2) so that one value suits every grid spacing. Where b = 0 the
/// steady state is harmonic whatever mu; mu only trades following v0 (small) against smoothing
/// it (large) where b > 0.
struct GvfParams {
  GvfSolver solver = GvfSolver::direct;
  double mu = 0.2;
  std::optional<double> time_step;  ///< unset: 0.9 x the largest stable step
  int max_iterations = 200000;
  double tolerance = 1e-10;
  SketchBoundary boundary_x = SketchBoundary::zero_flux;
  SketchBoundary boundary_y = SketchBoundary::zero_flux;

  template <class V>
  static void describe(V& v) {
    v(&GvfParams::solver, {.key = "solver",
                           .description = "explicit: Euler time marching (Xu & Prince 1998), "
                                          "step limits enforced; direct: sparse LDLT solve of "
                                          "the steady state"});
    v(&GvfParams::mu, {.key = "mu",
                       .unit = "cells^2",
                       .description = "smoothness weight of GVF (mu hx hy in m^2): larger "
                                      "smooths the strokes' velocities more, smaller follows "
                                      "them more closely; the empty grid is filled either way",
                       .min = 0,
                       .max = 1e12,
                       .minExclusive = true});
    v(&GvfParams::time_step, {.key = "time_step",
                              .description = "explicit: pseudo-time step; must satisfy mu dt "
                                             "sum(1/h^2) <= 1/2, dt max b <= 1 and dt (4 mu "
                                             "sum(1/h^2) + max b) <= 2 (mu in m^2); unset = "
                                             "0.9 x the largest stable step",
                              .min = 0,
                              .max = 1e12,
                              .minExclusive = true});
    v(&GvfParams::max_iterations, {.key = "max_iterations",
                                   .description = "explicit: iterations before giving up "
                                                  "(error naming the residual reached)",
                                   .min = 1,
                                   .max = 100000000});
    v(&GvfParams::tolerance, {.key = "tolerance",
                              .description = "explicit: stop when the largest residual "
                                             "|mu lap v - b (v - v0)| is below tolerance x "
                                             "max|v0|",
                              .min = 0,
                              .max = 1,
                              .minExclusive = true});
    v(&GvfParams::boundary_x, {.key = "boundary_x",
                               .description = "sides x = min, max: zero_flux or periodic"});
    v(&GvfParams::boundary_y, {.key = "boundary_y",
                               .description = "sides y = min, max: zero_flux or periodic"});
  }
};

/// The data weight b of GVF around the strokes (c: the strokes' coverage of a node, 1 on a
/// stroke, fading like the Gaussian off it; U: a stroke's speed).
/// speed: b = (c U)^2 / max (c U)^2, Xu & Prince's |v0|^2: a slow stroke binds the field less.
/// coverage: b = c^2, every stroke binds alike whatever its speed.
enum class GvfWeight { speed, coverage };
constexpr std::array<Choice<GvfWeight>, 2> paramChoices(GvfWeight) {
  return {{{GvfWeight::speed, "speed"}, {GvfWeight::coverage, "coverage"}}};
}

/// From strokes to the initial field: filtering, projection, smoothing, GVF, divergence.
struct SketchParams {
  double resample_spacing = 0.25;
  double stroke_smoothing = 0.0;
  double sigma = 1.0;
  GvfWeight weight = GvfWeight::coverage;
  GvfParams gvf;
  bool divergence_free = false;

  template <class V>
  static void describe(V& v) {
    v(&SketchParams::resample_spacing,
      {.key = "resample_spacing",
       .unit = "cells",
       .description = "strokes are resampled at this arc length (in grid spacings) before "
                      "they are projected",
       .min = 0.01,
       .max = 1});
    v(&SketchParams::stroke_smoothing,
      {.key = "stroke_smoothing",
       .unit = "cells",
       .description = "Gaussian sigma along each stroke (in grid spacings) that removes the "
                      "jitter of a hand-drawn curve; 0 = none",
       .min = 0,
       .max = 1000});
    v(&SketchParams::sigma, {.key = "sigma",
                             .unit = "cells",
                             .description = "Gaussian sigma (in grid spacings) of the smoothing "
                                            "of the projected strokes; 0 = none",
                             .min = 0,
                             .max = 1000});
    v(&SketchParams::weight, {.key = "weight",
                              .description = "GVF data weight near the strokes: speed = "
                                             "|v0|^2 (Xu & Prince; slow strokes bind less), "
                                             "coverage = the same for every stroke"});
    v(&SketchParams::gvf, {.key = "gvf", .description = "Gradient Vector Flow"});
    v(&SketchParams::divergence_free,
      {.key = "divergence_free",
       .description = "project the result onto discretely divergence-free fields (least "
                      "change in L2, a Poisson solve) for an incompressible LBM start"});
  }
};

/// Throws ParamError naming the key for values outside their declared ranges.
void validateSketchParams(const SketchParams& p);
void validateGvfParams(const GvfParams& p);

}  // namespace fluidviz::sketch
