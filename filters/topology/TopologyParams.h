#pragma once
// Parameters of the vector field topology filter: critical point detection, Poincaré index,
// Morse / non-Morse classification, stream function and separatrices.
//
// Lengths are in CELLS (index space: one cell = one grid spacing along each axis) so that the
// defaults work on any grid; "field scale" quantities are dimensionless ratios.
#include <array>
#include <string>

#include "fieldviz/core/Params.h"
#include "filters/streamlines/StreamlineParams.h"

namespace fluidviz::topology {

/// Distance from the domain boundary, in cells, within which a point is flagged on_boundary.
inline constexpr double kOnBoundaryCells = 1e-6;

/// Sparse solver for the Poisson problem lap psi = -omega: direct (Eigen SimplicialLDLT; 15 s
/// and 0.7 GB at 1024^2 nodes), cg (conjugate gradients, Jacobi preconditioner; less memory,
/// slower), auto (direct up to 1.1 million unknowns, else cg).
enum class StreamFunctionSolver { automatic, direct, cg };
constexpr std::array<Choice<StreamFunctionSolver>, 3> paramChoices(StreamFunctionSolver) {
  return {{{StreamFunctionSolver::automatic, "auto"},
           {StreamFunctionSolver::direct, "direct"},
           {StreamFunctionSolver::cg, "cg"}}};
}

/// Growth of the separating surfaces of 3D saddles (SeparatingSurfaces.h); lengths in cells.
struct SeparatingSurfaceParams {
  double max_edge = 1.0;
  double max_length = 60.0;
  int max_triangles = 200000;

  template <class V>
  static void describe(V& v) {
    v(&SeparatingSurfaceParams::max_edge,
      {.key = "max_edge",
       .unit = "cells",
       .description = "longest triangle edge; the front advances max_edge/4 per step and its "
                      "edges are split above max_edge/2",
       .min = 0.05,
       .max = 10});
    v(&SeparatingSurfaceParams::max_length,
      {.key = "max_length",
       .unit = "cells",
       .description = "arc length after which the front stops",
       .min = 0,
       .max = 100000,
       .minExclusive = true});
    v(&SeparatingSurfaceParams::max_triangles,
      {.key = "max_triangles",
       .description = "a surface stops growing at this many triangles",
       .min = 1,
       .max = 100000000});
  }
};

// Units and ranges of the members: their describe() declarations below.
struct TopologyParams {
  /// z-slice (node layer k) of a 3D field to analyse; ignored for 2D fields.
  /// The in-plane components (v_x, v_y) of that slice are analysed; v_z is ignored.
  int slice_index = 0;

  // --- Detection ------------------------------------------------------------------------------
  /// Newton iteration on the bilinear interpolant stops when the step is
  /// shorter than this.
  double newton_tolerance = 1e-12;
  /// Newton iterations before falling back to subdividing the cell.
  int newton_max_iterations = 50;
  /// Maximum number of times a cell is split in four when Newton cannot be trusted
  /// (Jacobian of the interpolant singular somewhere in the cell). Zeros are located to
  /// 2^-depth cells at the deepest level.
  int subdivision_depth = 10;
  /// Degenerate zeros of the interpolant closer than this (single linkage) form one cluster,
  /// reported as ONE critical point whose index is measured on a loop around the whole cluster.
  /// This turns the several spurious zeros the bilinear interpolant makes near a degenerate zero
  /// (e.g. a monkey saddle) into one point. A zero that is a Morse point on its own (|det J| >
  /// det_threshold * G^2 with J the interpolant's exact Jacobian at the zero) is never merged,
  /// whatever its distance to other zeros: two genuine Morse points stay two (issue 15).
  /// A cluster never grows beyond a diameter of 3 * cluster_radius (dense zeros of noisy data
  /// do not chain into one cluster).
  double cluster_radius = 1.5;

  // --- Index and sectors ------------------------------------------------------------------------
  /// Radius of the index loop beyond the cluster's extent. It shrinks so that
  /// the loop stays inside the domain and encloses no other zero.
  double loop_radius = 2.0;
  /// Samples on the index loop before adaptive refinement (the loop is refined until
  /// the field turns less than pi/16 between neighbouring samples).
  int loop_samples = 720;
  /// Hysteresis when the angle between the field and the radial direction
  /// crosses a multiple of pi (sector boundaries); wiggles smaller than this are ignored.
  double sector_hysteresis = 0.02;

  // --- Classification ---------------------------------------------------------------------------
  /// A point is Morse (non-degenerate) when
  /// |det J| > det_threshold * G^2, with G the RMS of the Frobenius norm of the field's
  /// finite-difference Jacobian over the nodes within gradient_scale_radius of the point (the
  /// typical field change per cell divided by the cell size there, 1/s). For a linear field
  /// det J / G^2 = l1 l2 / (l1^2 + l2^2) (eigenvalues l1, l2), so the default accepts
  /// eigenvalue ratios down to about 1/100.
  double det_threshold = 1e-2;
  /// Half-width of the square window over which G is averaged. Local, so that a
  /// weak but regular point is not called degenerate because of strong flow elsewhere; large
  /// enough (several cells) that at a degenerate point, where J vanishes, G still sees the
  /// field's growth around it. Use a huge value for one global G.
  double gradient_scale_radius = 8.0;
  /// Complex eigenvalues a +- ib are a centre when |a| <= tol * |b|
  /// (otherwise a spiral source/sink). On numerical data the divergence of an incompressible
  /// flow is never exactly zero, hence a tolerance.
  double centre_tolerance = 1e-2;

  // --- Stream function --------------------------------------------------------------------------
  StreamFunctionSolver stream_function_solver = StreamFunctionSolver::automatic;
  /// Relative residual at which conjugate gradients stop.
  double stream_function_tolerance = 1e-10;

  // --- Separatrices -----------------------------------------------------------------------------
  /// A Morse saddle's separatrices start this far from the point along its
  /// eigenvectors. (Those of non-Morse points start on the index loop, where their directions
  /// were measured.)
  double separatrix_offset = 0.5;
  /// A separatrix ends when it comes this close to a critical point (other than
  /// its own, which it may reach only after leaving it by more than twice this distance).
  double separatrix_stop_radius = 1.0;
  /// The shared streamline integrator's settings for separatrices; `direction` is ignored
  /// (outgoing separatrices are traced forward, incoming ones backward).
  streamlines::StreamlineParams separatrix_integration;
  /// Separating surfaces of 3D saddles (their integrator: separatrix_integration).
  SeparatingSurfaceParams separating_surface;

  template <class V>
  static void describe(V& v) {
    v(&TopologyParams::slice_index,
      {.key = "slice_index",
       .description = "z node layer of a 3D field whose in-plane components (vx, vy) are "
                      "analysed; ignored for 2D fields",
       .min = 0});
    v(&TopologyParams::newton_tolerance,
      {.key = "newton_tolerance",
       .unit = "cells",
       .description = "Newton step length at which the sub-cell location of a zero stops",
       .min = 1e-14,
       .max = 1e-3});
    v(&TopologyParams::newton_max_iterations,
      {.key = "newton_max_iterations",
       .description = "Newton iterations before the cell is subdivided instead",
       .min = 1,
       .max = 200});
    v(&TopologyParams::subdivision_depth,
      {.key = "subdivision_depth",
       .description = "how often a cell is split in four where Newton cannot be trusted "
                      "(zeros located to 2^-depth cells there)",
       .min = 0,
       .max = 20});
    v(&TopologyParams::cluster_radius,
      {.key = "cluster_radius",
       .unit = "cells",
       .description = "degenerate zeros (|det J| <= det_threshold * G^2) closer than this form "
                      "one critical point (index measured around the whole cluster); Morse zeros "
                      "are never merged",
       .min = 0,
       .max = 10});
    v(&TopologyParams::loop_radius,
      {.key = "loop_radius",
       .unit = "cells",
       .description = "radius of the index loop beyond the cluster's extent (shrinks to stay in "
                      "the domain and away from other zeros)",
       .min = 0,
       .max = 20,
       .minExclusive = true});
    v(&TopologyParams::loop_samples,
      {.key = "loop_samples",
       .description = "samples on the index loop before adaptive refinement",
       .min = 64,
       .max = 1e5});
    v(&TopologyParams::sector_hysteresis,
      {.key = "sector_hysteresis",
       .unit = "rad",
       .description = "angle by which the field must pass the radial direction to count as a "
                      "sector boundary",
       .min = 0,
       .max = 0.5});
    v(&TopologyParams::det_threshold,
      {.key = "det_threshold",
       .description = "Morse when |det J| > det_threshold * G^2 (G: RMS Jacobian norm of the "
                      "field around the point)",
       .min = 0,
       .max = 1});
    v(&TopologyParams::gradient_scale_radius,
      {.key = "gradient_scale_radius",
       .unit = "cells",
       .description = "half-width of the window over which the reference Jacobian norm G is "
                      "averaged",
       .min = 1,
       .max = 1e6});
    v(&TopologyParams::centre_tolerance,
      {.key = "centre_tolerance",
       .description = "complex eigenvalues a +- ib are a centre when |a| <= tolerance * |b|",
       .min = 0,
       .max = 1});
    v(&TopologyParams::stream_function_solver,
      {.key = "stream_function_solver",
       .description = "sparse solver of the stream function's Poisson problem"});
    v(&TopologyParams::stream_function_tolerance,
      {.key = "stream_function_tolerance",
       .description = "relative residual at which conjugate gradients stop",
       .min = 1e-14,
       .max = 1e-3});
    v(&TopologyParams::separatrix_offset,
      {.key = "separatrix_offset",
       .unit = "cells",
       .description = "distance from a Morse saddle at which its separatrices start",
       .min = 0,
       .max = 5,
       .minExclusive = true});
    v(&TopologyParams::separatrix_stop_radius,
      {.key = "separatrix_stop_radius",
       .unit = "cells",
       .description = "a separatrix ends this close to a critical point",
       .min = 0,
       .max = 10,
       .minExclusive = true});
    v(&TopologyParams::separatrix_integration,
      {.key = "separatrix_integration",
       .description = "streamline integrator settings for separatrices (direction is ignored)"});
    v(&TopologyParams::separating_surface,
      {.key = "separating_surface",
       .description = "advancing-front growth of the separating surfaces of 3D saddles"});
  }
};

/// Checks every member against its declared range and choices. Throws ParamError naming the key.
void validateTopologyParams(const TopologyParams& p);

}  // namespace fluidviz::topology
