#pragma once
// What an FHP lattice-gas run (solver = "fhp", solvers/fhp/FhpSolverAdapter.h) writes, in
// RunOptions::outputDir, as an LBM run does (LbmOutputs.h):
//   <name>.pvd, <name>/<name>_NNNN.vti  the snapshots: the block- and time-averaged fields on the
//                                       grid of block centres (fhpSnapshotFields) and the solid
//                                       mask vtkValidPointMask (0 = a block less than half fluid)
//   output.streamlines, output.lic      of the final averaged state (FlowOutputs.h)
//   output.images                       field pictures of the final averaged state
//   <name>/<stem>_NNNN.png, <stem>.mp4   frames and movies (PictureSeries.h)
#include <filesystem>

#include "pipeline/FlowOutputs.h"
#include "pipeline/PictureSeries.h"
#include "pipeline/RunLoop.h"
#include "pipeline/SceneParams.h"
#include "solvers/fhp/FhpSolver.h"

namespace fluidviz {

/// The FHP rules of a scene: fhp.* parameters (keys "fhp.<key>"), and no time series (not
/// offered). Throws ParamError.
void validateFhpScene(const SceneParams& scene);

/// A snapshot: FhpSolver::averagedFields (density kg/m^3, velocity and speed m/s, pressure Pa;
/// velocity and speed 0 in solid blocks, the obstacles' own) and the vorticity (1/s) of the
/// averaged velocity.
FieldSet fhpSnapshotFields(const fhp::FhpSolver& solver);

class FhpOutputs final : public SolverOutputs {
 public:
  FhpOutputs(const SceneParams& scene, const fhp::FhpSolver& solver);

  void begin(const SnapshotSeries& series, bool resumed,
             std::vector<std::filesystem::path>& written) override;
  void writeSnapshot(int index, SnapshotSeries& series,
                     std::vector<std::filesystem::path>& written) override;
  void writeFinal(const SnapshotSeries& series, const scene::json& effectiveScene,
                  std::vector<std::filesystem::path>& written) override;

 private:
  void writePictures(const FieldSet& fields, const SceneLineOverlays& lines,
                     const PictureDestination& to,
                     std::vector<std::filesystem::path>& written) const;

  const SceneParams& scene_;
  const fhp::FhpSolver& solver_;
};

}  // namespace fluidviz
