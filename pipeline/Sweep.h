#pragma once
// Parameter sweeps: a scene run N times with one numeric key set to evenly spaced values (the
// --set mechanism, scene::applyOverride), the topology of each final velocity field, and the
// bifurcation diagram of the critical points against the parameter.
//
// Output folder layout (DIR):
//   step_KK/                         each run's own output (scene files, final snapshot, images)
//   step_KK/<name>_critical_points.vtp / .csv   that run's critical points
//   <name>_step_KK_topology.png      glyphs and separatrices over the LIC picture of run KK
//   <name>_bifurcation.csv           step,parameter,x,y,z,type,index,morse,det,trace,hyperbolic,
//                                    elliptic,parabolic (one row per critical point per step)
//   <name>_bifurcation.png           the diagram (x and y of each point against the parameter)
// Critical points inside solid rollers are left out: roller nodes carry the roller's rigid
// rotation, whose centre is a "centre" of the velocity array but not a point of the flow.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/SceneParams.h"
#include "pipeline/TopologyOutputs.h"
#include "fieldviz/scene/ParamVisitors.h"
#include "filters/topology/CriticalPoint.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz {

struct SweepParams {
  std::string parameter;              ///< key path set at each step, e.g. lbm.rollers.0.angular_velocity
  double from = 0.0, to = 1.0;        ///< first and last value
  int steps = 5;                      ///< number of runs, [1, 1000]; values evenly spaced
  std::vector<std::string> overrides; ///< further key.path=value settings for every run
  topology::TopologyParams topology;  ///< detection and classification
  TopologyPictureParams picture;      ///< per-step pictures
  bool pictures = true;               ///< write the per-step topology pictures
  /// Only points inside [xmin, ymin, xmax, ymax] (m) go into the diagram's PNG (the CSV has
  /// all); empty: all points.
  std::optional<std::array<double, 4>> region;
};

/// Value of step k (0-based).
double sweepValue(const SweepParams& p, int k);

struct SweepStep {
  double value = 0.0;
  std::vector<topology::CriticalPoint> points;  ///< outside solid bodies
  std::filesystem::path directory;
};

struct SweepResult {
  std::string sceneName;
  std::vector<SweepStep> steps;
  std::vector<std::filesystem::path> files;  ///< everything written by the sweep itself
};

/// The scene of step k: `sceneJson` with the overrides and the parameter applied, read and
/// checked. Throws scene::SceneError naming the file and key (also for a parameter that is not
/// a number key of the scene).
SceneParams sweepScene(const scene::json& sceneJson, const std::string& sceneFile,
                       const SweepParams& p, int k);

/// Checks every step's scene and the sweep's own settings before anything runs (SceneError /
/// ParamError), then runs the steps with progress on `log`. The solver's instability error
/// passes through (files of finished steps stay).
SweepResult runSweep(const scene::json& sceneJson, const std::string& sceneFile,
                     const SweepParams& p, const std::filesystem::path& dir, std::ostream& log,
                     bool interactive);

/// The last snapshot (.vti) of a finished run. Throws FileError when it wrote none.
std::filesystem::path finalSnapshot(const std::vector<std::filesystem::path>& runFiles);
/// The final velocity of a finished run (its last snapshot, read back). Throws FileError.
VectorField finalVelocity(const std::vector<std::filesystem::path>& runFiles);

/// The bifurcation table (header and rows) of a sweep.
std::string bifurcationCsv(const SweepResult& r);

}  // namespace fluidviz
