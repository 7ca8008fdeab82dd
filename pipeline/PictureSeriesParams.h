#pragma once
// Scene keys shared by every picture of the scene (output.images[], output.lic[]): a frame per
// snapshot and a movie of those frames (pipeline/PictureSeries.h).
#include <array>

#include "fieldviz/core/Params.h"

namespace fluidviz {

/// The movie a picture's frames are encoded into at the end of the run.
enum class MovieFormat { none, mp4, gif };
constexpr std::array<Choice<MovieFormat>, 3> paramChoices(MovieFormat) {
  return {{{MovieFormat::none, "none"}, {MovieFormat::mp4, "mp4"}, {MovieFormat::gif, "gif"}}};
}

struct PictureSeriesParams {
  bool every_snapshot = false;  ///< also a frame <name>/<stem>_NNNN.png at every snapshot
  MovieFormat movie = MovieFormat::none;
  int fps = 10;  ///< frames per second of the movie

  template <class V>
  static void describe(V& v) {
    v(&PictureSeriesParams::every_snapshot,
      {.key = "every_snapshot",
       .description = "also draw the picture at every snapshot (t = 0 included): frames "
                      "<name>/<stem>_NNNN.png beside the snapshot files, numbered as they; "
                      "the final picture stays; needs output.snapshots > 0 (give range_min and "
                      "range_max for colours that mean the same value in every frame)"});
    v(&PictureSeriesParams::movie,
      {.key = "movie",
       .description = "movie of the frames written at the end of the run (needs every_snapshot "
                      "and ffmpeg, scripts/setup.sh): mp4 (H.264, yuv420p) <stem>.mp4, gif "
                      "(own palette, looping) <stem>.gif, or none"});
    v(&PictureSeriesParams::fps,
      {.key = "fps", .unit = "1/s", .description = "frames per second of the movie",
       .min = 1, .max = 60});
  }
};

}  // namespace fluidviz
