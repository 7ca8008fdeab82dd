#pragma once
// What an LBM run (solver = "lbm", solvers/lbm/LbmSolverAdapter.h) writes, in
// RunOptions::outputDir:
//   <name>.pvd, <name>/<name>_NNNN.vti  the snapshots (pipeline/RunLoop.h) on the node-centred
//                                       grid: lbmSnapshotFields and the solid mask
//                                       vtkValidPointMask (1 = fluid, 0 = solid node)
//   output.streamlines, output.lic      of the final state (FlowOutputs.h)
//   output.images                       field pictures of the final state (a 3D scene: the
//                                       image's slice_index layer); vorticity and stream_function
//                                       are computed for them
//   <name>/<stem>_NNNN.png, <stem>.mp4   frames of every snapshot and movies of output.images
//                                       and output.lic (PictureSeries.h)
//   <name>_scene.json                   the effective scene (without the sph section)
#include <filesystem>

#include "pipeline/FlowOutputs.h"
#include "pipeline/PictureSeries.h"
#include "pipeline/RunLoop.h"
#include "pipeline/SceneParams.h"
#include "pipeline/TimeSeries.h"
#include "solvers/lbm/LbmSolver.h"

namespace fluidviz {

/// The LBM rules of a scene: lbm.* parameters (keys "lbm.<key>") and, for a 3D lattice,
/// output.images[].slice_index inside it. Throws ParamError.
void validateLbmScene(const SceneParams& scene);

/// What a snapshot holds: velocity (m/s), density (kg/m^3), speed (m/s), pressure (Pa, gauge:
/// c_s^2 (rho - rho0) in physical units, docs/units.md), and vorticity (1/s; 2D: the scalar
/// dv/dx - du/dy, 3D: the vector curl v) and, in 3D, q_criterion (1/s^2). Solid nodes carry the
/// reference density and their body's velocity.
FieldSet lbmSnapshotFields(const lbm::LbmSolver& solver);

class LbmOutputs final : public SolverOutputs {
 public:
  LbmOutputs(const SceneParams& scene, const lbm::LbmSolver& solver);

  /// A resumed run's earlier picture frames.
  void begin(const SnapshotSeries& series, bool resumed,
             std::vector<std::filesystem::path>& written) override;
  /// The .vti and, with every_snapshot, the pictures' frames.
  void writeSnapshot(int index, SnapshotSeries& series,
                     std::vector<std::filesystem::path>& written) override;
  void writeFinal(const SnapshotSeries& series, const scene::json& effectiveScene,
                  std::vector<std::filesystem::path>& written) override;
  FieldSet probeFields() const override { return solver_.fields(); }
  std::vector<double> seriesValues(const std::vector<SeriesQuantity>& quantities) const override {
    return lbmSeriesValues(solver_, scene_, quantities);
  }

 private:
  /// output.images and output.lic of `fields` (the solver's current state) that `to` takes.
  void writePictures(const FieldSet& fields, const SceneLineOverlays& lines,
                     const PictureDestination& to,
                     std::vector<std::filesystem::path>& written) const;

  const SceneParams& scene_;
  const lbm::LbmSolver& solver_;
};

}  // namespace fluidviz
