#pragma once
// The grid-based outputs of SPH scenes, each computed only when listed in the scene:
//   output.grids         the particles resampled onto a grid (filters/resample): <file>.vti of
//                        the final state; with every_snapshot also <stem>.pvd listing
//                        <stem>/<stem>_NNNN.vti at every snapshot
//   output.free_surface  the level set of the resampled colour field (filters/isosurface,
//                        Flying Edges): isolines in 2D, a surface with normals in 3D, as .vtp
//                        (final state; every_snapshot: <stem>.pvd of <stem>/<stem>_NNNN.vtp)
//   output.views         3D pictures (fieldviz/render/View3D.h): the shaded free surface and/or
//                        the particles as spheres coloured by an array, framed on the SPH domain
//                        with its outline; every_snapshot and movie as output.images[]
//                        (pipeline/PictureSeries.h), turntable_frames (final state)
//                        <stem>_turntable_NNNN.png
// Every grid covers the SPH domain box (sph.domain_lower/upper) plus the padding, so a series
// has the same grid at every snapshot and its memory is known before the run. Particle volumes
// are m/rho (the solver's particle mass and density). A free surface that does not exist (the
// level outside the colour field's range, e.g. no fluid left) is written as an empty .vtp
// with a warning in the log.
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <vector>

#include "fieldviz/io/PvdSeries.h"
#include "pipeline/PictureSeries.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

namespace sph {
class SphSolver;
}

/// The PNG file of output.views[i]: its file, or <name>_view.png (<name>_view2.png, ...).
std::string viewFile(const SceneParams& scene, std::size_t i);

/// Rules of output.grids / free_surface / views that need no solver: file names (plain, right
/// extension, unique among themselves and output.images), the views' 3D parameters. Throws
/// ParamError with the scene key ("output.grids[0].file").
void validateSphGridOutputs(const SceneParams& scene);

/// Checks that need the particles, done on the initial state: the arrays named exist, every
/// grid fits max_memory_mb (the grid is fixed, so this holds for the whole run). Throws
/// ParamError with the scene key.
void checkSphGridOutputs(const SceneParams& scene, const sph::SphSolver& solver);

class SphGridOutputs {
 public:
  /// Starts the .pvd series of the every_snapshot outputs in `dir`. A resumed run passes the
  /// snapshots written before (the main series' entries): the series go on from them, and
  /// their files numbered after them are removed. Throws FileError naming a file of the
  /// earlier snapshots that is missing.
  SphGridOutputs(const SceneParams& scene, std::filesystem::path dir, std::ostream& log,
                 bool resumed = false, const std::vector<PvdSeries::Entry>& earlierSnapshots = {});
  ~SphGridOutputs();

  /// Snapshot number `index` (0: t = 0, 1, 2, ...) of the solver's state: the every_snapshot
  /// grids and surfaces (from index 1 on; their series follow the targets) and the frames of
  /// the every_snapshot views, drawn to `frames`.
  void snapshot(const sph::SphSolver& solver, int index, const PictureDestination& frames,
                std::vector<std::filesystem::path>& written);
  /// The files the earlier snapshots of a resumed run left in the grid and surface series (the
  /// views' frames are pictures: continueEarlierFrames, PictureSeries.h).
  const std::vector<std::filesystem::path>& earlierFiles() const;
  /// The final state: every listed output.
  void finalState(const sph::SphSolver& solver, std::vector<std::filesystem::path>& written);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fluidviz
