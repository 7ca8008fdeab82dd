#pragma once
// Pictures of every snapshot and their movies (output.images[], output.lic[] and output.views[]
// keys of PictureSeriesParams):
//   - with every_snapshot each snapshot draws the picture again, by the very function that draws
//     the final one, as the frame <name>/<stem>_NNNN.png (SnapshotSeries::frameFile) beside the
//     snapshot files, t = 0 included; the final picture <stem>.png stays;
//   - at the end of the run a movie != none encodes the frames with ffmpeg (a subprocess, no
//     shell) into <stem>.mp4 (H.264, yuv420p, padded to even width and height) or <stem>.gif
//     (palettegen/paletteuse, looping forever), written under a temporary name and renamed when
//     complete (fieldviz/core/AtomicFile.h), with a progress bar (pipeline/Progress.h).
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/RunLoop.h"
#include "pipeline/SceneParams.h"

namespace fluidviz {

/// One picture entry of the scene: its key ("output.lic[0]"), final file name and series keys.
struct ScenePicture {
  std::string key;
  std::string file;
  PictureSeriesParams series;
};

/// output.images[], output.lic[], then output.views[] (SPH).
std::vector<ScenePicture> scenePictures(const SceneParams& scene);

/// True if some picture draws a frame at every snapshot.
bool anyPictureFrames(const SceneParams& scene);

/// Where the pictures being drawn go: the final pictures dir/<file>, or the frames of snapshot
/// `index` (only pictures with every_snapshot).
class PictureDestination {
 public:
  static PictureDestination finalPictures(std::filesystem::path dir);
  static PictureDestination frames(const SnapshotSeries& series, int index);
  /// The file of the picture `file`; empty when this picture draws no frames.
  std::optional<std::filesystem::path> path(const std::string& file,
                                            const PictureSeriesParams& series) const;

 private:
  std::filesystem::path dir_;
  const SnapshotSeries* series_ = nullptr;
  int index_ = -1;
};


/// The ffmpeg found on PATH; empty if none.
std::optional<std::filesystem::path> findFfmpeg();

/// The keys of PictureSeriesParams of the picture at `key`: ranges, movie only with
/// every_snapshot, every_snapshot only with snapshots, ffmpeg on PATH for a movie. Throws
/// ParamError with the full key ("output.images[0].movie").
void validatePictureSeries(const SceneParams& scene, const ScenePicture& picture);

/// A resumed run's frames: each picture's earlier frames (one per entry of `series`) are
/// appended to `written` (FileError for a missing one), later ones (as a kill between a frame
/// and its checkpoint leaves them) are removed.
void continueEarlierFrames(const SceneParams& scene, const SnapshotSeries& series,
                       std::vector<std::filesystem::path>& written);

/// Encodes the frames of every picture with a movie (frames 0 .. series.entries().size() - 1)
/// into series.dir(), appending each movie to `written`. Throws std::runtime_error with
/// ffmpeg's messages if it fails (no movie is left then).
void writeMovies(const SceneParams& scene, const SnapshotSeries& series, std::ostream& log,
                 bool interactive, std::vector<std::filesystem::path>& written);

}  // namespace fluidviz
