#pragma once
// What an SPH run (solver = "sph", solvers/sph/SphSolverAdapter.h) writes, in
// RunOptions::outputDir:
//   <name>.pvd, <name>/<name>_NNNN.vtp  fluid particles at the snapshots (pipeline/RunLoop.h; the
//                                    last is the final state): one vertex cell per particle and
//                                    point arrays velocity (3 components, m/s), speed (m/s),
//                                    density (kg/m^3), pressure (Pa)
//   <name>_boundary.vtp              the boundary particles (walls, obstacles, rollers) at t = 0,
//                                    with their velocity (rollers turn in place: same discs)
//   output.images                    particle pictures of the final state, coloured by the image's
//                                    field (speed, density, velocity_x, velocity_y): 2D seen
//                                    orthographically in the xy plane with the boundary in grey,
//                                    3D in perspective (fieldviz/render/ParticleImage.h); with
//                                    every_snapshot also frames and movies (PictureSeries.h)
//   output.grids, free_surface, views  resampled grids, free surfaces, 3D views (SphGridOutputs.h)
//   <name>_scene.json                the effective scene (without the lbm section)
// output.lic and output.streamlines need a grid: they are rejected for SPH scenes (resample the
// .vtp with `fluidviz resample` first).
#include <filesystem>
#include <iosfwd>
#include <memory>

#include "pipeline/PictureSeries.h"
#include "pipeline/RunLoop.h"
#include "pipeline/SceneParams.h"
#include "pipeline/SphGridOutputs.h"
#include "pipeline/TimeSeries.h"
#include "solvers/sph/SphSolver.h"

namespace fluidviz {

/// The SPH rules of a scene that need no particles: the outputs SPH offers (no LIC or
/// streamlines; pictures of particle arrays) and the sph.* parameters ("sph.<key>"). Throws
/// ParamError.
void validateSphScene(const SceneParams& scene);

/// The solver of a valid scene, with the checks that need its particles: the layout (key "sph")
/// and output.grids/free_surface/views (checkSphGridOutputs). Throws ParamError.
std::unique_ptr<sph::SphSolver> createCheckedSphSolver(const SceneParams& scene);

class SphOutputs final : public SolverOutputs {
 public:
  SphOutputs(const SceneParams& scene, const sph::SphSolver& solver, std::ostream& log);
  ~SphOutputs() override;

  /// The boundary particles' file; the grid outputs' series (continued when resuming).
  void begin(const SnapshotSeries& series, bool resumed,
             std::vector<std::filesystem::path>& written) override;
  void writeSnapshot(int index, SnapshotSeries& series,
                     std::vector<std::filesystem::path>& written) override;
  void writeFinal(const SnapshotSeries& series, const scene::json& effectiveScene,
                  std::vector<std::filesystem::path>& written) override;
  std::vector<double> seriesValues(const std::vector<SeriesQuantity>& quantities) const override {
    return sphSeriesValues(solver_, quantities);
  }

 private:
  /// The output.images particle pictures of the current state that `to` takes.
  void writeImages(const PictureDestination& to, std::vector<std::filesystem::path>& written) const;

  const SceneParams& scene_;
  const sph::SphSolver& solver_;
  std::ostream& log_;
  std::unique_ptr<SphGridOutputs> grids_;
};

}  // namespace fluidviz
