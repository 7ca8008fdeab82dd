#pragma once
// Runs a scene with solver = "sph" (solvers/sph): particles instead of grids.
//
// Writes (in RunOptions::outputDir):
//   <name>.pvd                       the snapshot series, listing only complete files
//   <name>/<name>_NNNN.vtp           fluid particles at output.snapshots evenly spaced times (the
//                                    last is the final state): one vertex cell per particle and
//                                    point arrays velocity (3 components, m/s), speed (m/s),
//                                    density (kg/m^3), pressure (Pa)
//   <name>_boundary.vtp              the boundary particles (walls, obstacles, rollers) at t = 0,
//                                    with their velocity (rollers turn in place: same discs)
//   output.images                    particle pictures of the final state, coloured by the image's
//                                    field (speed, density, velocity_x, velocity_y): 2D seen
//                                    orthographically in the xy plane with the boundary in grey,
//                                    3D in perspective (fieldviz/render/ParticleImage.h)
//   <name>_scene.json                the effective scene
// output.lic and output.streamlines need a grid: they are rejected for SPH scenes (resample the
// .vtp with `fluidviz resample` first).
// Time-step warnings of the solver are printed as they appear. An sph::InstabilityError stops
// the run and is passed on: the snapshots written before it stay complete and listed.
#include <string>

#include "pipeline/RunScene.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

/// checkScene for SPH: scene rules, SPH parameters ("sph.<key>"), particle layout. Throws
/// scene::SceneError. Returns a description (particle counts, h, mass, time-step limits).
std::string checkSphScene(const SceneParams& scene, const std::string& sceneFile);

/// runScene for SPH (see above). Throws scene::SceneError before writing anything.
RunSummary runSphScene(const SceneParams& scene, const RunOptions& options);

}  // namespace fluidviz
