#pragma once
// lbm.initial_flow = sketch (issue 20): the LBM's initial velocity from the scene's strokes.
//
//   strokes (lbm.sketch.strokes, lbm.sketch.file) -> filters/sketch on the LBM's node grid
//   (the solver's grid(): nodes at cell centres, spacing dx; gvf.boundary_x/y periodic exactly
//   where the walls are) -> scaled to lbm.initial_speed if that is > 0 -> its largest speed
//   becomes lbm.initial_speed of the solver's parameters, so that it counts as U_ref for
//   lattice_velocity and reynolds as the amplitude of taylor_green does: dt = lattice_velocity
//   dx / max|u|, and the largest lattice speed at t = 0 is exactly lattice_velocity.
// The solver is then built from those parameters and LbmSolver::initialise sets every node to the
// equilibrium of (lbm.density, the sketched velocity); initialise converts to lattice units.
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/sketch/SketchedFlow.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

/// The limit on the nodes of a sketch solved directly (one sparse LDLT of nx ny unknowns, about
/// 1 GB at 1024^2), as for `fluidviz sketch`.
inline constexpr long long kMaxDirectSketchNodes = 1024LL * 1024LL;
/// The limit on the points of the resampled strokes (their length over resample_spacing).
inline constexpr double kMaxSketchStrokePoints = 1e7;

/// How the LBM of a scene starts.
struct LbmStart {
  lbm::LbmParams params;          ///< the scene's; for a sketch initial_speed = max|velocity|
  std::vector<Vec3> velocity;     ///< m/s per node (x fastest); empty unless sketched
  sketch::SketchedFlow sketched;  ///< the sketch filter's result (empty unless sketched)
  std::size_t strokeCount = 0;
};

/// The LBM's node grid for `p` (as LbmSolver::grid() of a 2D scene), without building a solver.
/// Throws ParamError as computeLatticeUnits does for the geometry.
Grid lbmNodeGrid(const lbm::LbmParams& p);

/// The strokes of lbm.sketch: the inline ones, then those of the file (relative to
/// scene.folder). Throws ParamError on keys relative to lbm ("sketch.file", "sketch.strokes[1]").
std::vector<sketch::Stroke> sceneStrokes(const SceneParams& scene);

/// One line on a sketched start for `fluidviz check`: strokes, GVF solver and residual (and
/// iterations), the divergence before and after the projection, the largest speed (U_ref); empty
/// for other starts.
std::string describeSketchStart(const LbmStart& start, const SceneParams& scene);

/// The start of the scene's LBM. For initial_flow other than sketch: scene.lbm and no velocity.
/// Throws ParamError with keys relative to lbm ("sketch.gvf.boundary_x", "initial_speed").
LbmStart lbmStartOf(const SceneParams& scene);

}  // namespace fluidviz
