#include "pipeline/PictureSeries.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string_view>

#include <unistd.h>

#include "fieldviz/core/AtomicFile.h"
#include "fieldviz/core/ChildProcess.h"
#include "fieldviz/core/ParamRanges.h"
#include "fieldviz/io/FileError.h"
#include "pipeline/Checkpoint.h"
#include "pipeline/FlowOutputs.h"
#include "pipeline/Progress.h"
#include "pipeline/SceneValidation.h"
#include "pipeline/SphGridOutputs.h"

namespace fluidviz {

namespace fs = std::filesystem;

std::vector<ScenePicture> scenePictures(const SceneParams& scene) {
  std::vector<ScenePicture> pictures;
  for (std::size_t i = 0; i < scene.output.images.size(); ++i)
    pictures.push_back({"output.images[" + std::to_string(i) + "]",
                        imageFileName(scene, scene.output.images[i]), scene.output.images[i]});
  for (std::size_t i = 0; i < scene.output.lic.size(); ++i)
    pictures.push_back({"output.lic[" + std::to_string(i) + "]",
                        licFileName(scene, scene.output.lic[i]), scene.output.lic[i]});
  for (std::size_t i = 0; i < scene.output.views.size(); ++i)
    pictures.push_back({"output.views[" + std::to_string(i) + "]", viewFile(scene, i),
                        scene.output.views[i]});
  return pictures;
}

bool anyPictureFrames(const SceneParams& scene) {
  const auto pictures = scenePictures(scene);
  return std::any_of(pictures.begin(), pictures.end(),
                     [](const ScenePicture& p) { return p.series.every_snapshot; });
}

PictureDestination PictureDestination::finalPictures(fs::path dir) {
  PictureDestination d;
  d.dir_ = std::move(dir);
  return d;
}

PictureDestination PictureDestination::frames(const SnapshotSeries& series, int index) {
  PictureDestination d;
  d.dir_ = series.dir();
  d.series_ = &series;
  d.index_ = index;
  return d;
}

std::optional<fs::path> PictureDestination::path(const std::string& file,
                                                 const PictureSeriesParams& series) const {
  if (!series_) return dir_ / file;
  if (!series.every_snapshot) return std::nullopt;
  return dir_ / series_->frameFile(index_, file);
}

std::optional<fs::path> findFfmpeg() {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  const std::string dirs = path;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate =
        fs::path(end > start ? dirs.substr(start, end - start) : ".") / "ffmpeg";
    if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate)) return candidate;
    start = end + 1;
  }
  return std::nullopt;
}

void validatePictureSeries(const SceneParams& scene, const ScenePicture& picture) {
  const PictureSeriesParams& p = picture.series;
  const std::string key = picture.key + ".";
  withKeyPrefix(key, [&] { params::checkRanges(p); });
  if (p.movie != MovieFormat::none && !p.every_snapshot)
    throw ParamError(key + "movie", "is \"" + choiceName(p.movie) +
                                        "\", but every_snapshot is false: a movie is made of the "
                                        "per-snapshot frames; set every_snapshot true or movie "
                                        "\"none\"");
  if (p.every_snapshot && scene.output.snapshots == 0)
    throw ParamError(key + "every_snapshot",
                     "is true, but output.snapshots is 0 (no snapshots, no frames); give "
                     "output.snapshots > 0 or set every_snapshot false");
  if (p.movie != MovieFormat::none && !findFfmpeg())
    throw ParamError(key + "movie", "is \"" + choiceName(p.movie) +
                                        "\", which needs ffmpeg, not found on PATH; install it "
                                        "(scripts/setup.sh, or apt-get install ffmpeg) or set "
                                        "movie \"none\"");
}

void continueEarlierFrames(const SceneParams& scene, const SnapshotSeries& series,
                           std::vector<fs::path>& written) {
  const int earlier = static_cast<int>(series.entries().size());  // frames 0 .. earlier - 1
  for (const ScenePicture& picture : scenePictures(scene)) {
    if (!picture.series.every_snapshot) continue;
    const fs::path folder = (series.dir() / series.frameFile(0, picture.file)).parent_path();
    removeLaterSnapshots(folder, fs::path(picture.file).stem().string(),
                         static_cast<std::size_t>(std::max(0, earlier - 1)));
    for (int i = 0; i < earlier; ++i) {
      const fs::path frame = series.dir() / series.frameFile(i, picture.file);
      if (!fs::exists(frame))
        throw FileError(frame, "frame " + frame.string() + " of an earlier snapshot is missing; "
                               "start the run again without --resume");
      written.push_back(frame);
    }
  }
}

namespace {

// An ffmpeg input pattern naming the files literally ('%' doubled) but for the frame number.
std::string framePattern(const SnapshotSeries& series, const std::string& pictureFile) {
  std::string frame0 = (series.dir() / series.frameFile(0, pictureFile)).string();
  std::string pattern;
  for (char c : frame0.substr(0, frame0.size() - std::string("0000.png").size()))
    pattern += c == '%' ? std::string("%%") : std::string(1, c);
  return pattern + "%04d.png";
}

// mp4: H.264 needs even width and height for yuv420p, so odd sizes get one padding pixel.
// gif: one palette made from all frames (palettegen) applied to each (paletteuse); loop 0 is
// forever.
std::vector<std::string> encoderArguments(MovieFormat format) {
  if (format == MovieFormat::mp4)
    return {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
            "-movflags", "+faststart", "-f", "mp4"};
  return {"-filter_complex", "split[a][b];[a]palettegen[p];[b][p]paletteuse", "-loop", "0",
          "-f", "gif"};
}

// ffmpeg's -progress lines ("frame=12") from its stdout, which arrives in arbitrary pieces.
class LineSplitter {
 public:
  explicit LineSplitter(std::function<void(const std::string&)> onLine) : onLine_(std::move(onLine)) {}
  void operator()(std::string_view piece) {
    pending_.append(piece);
    for (std::size_t eol; (eol = pending_.find('\n')) != std::string::npos; pending_.erase(0, eol + 1))
      onLine_(pending_.substr(0, eol));
  }

 private:
  std::function<void(const std::string&)> onLine_;
  std::string pending_;
};

// ffmpeg writes a temporary file beside the movie, renamed when complete (core/AtomicFile.h).
void encodeMovie(const fs::path& ffmpeg, const SnapshotSeries& series, const ScenePicture& picture,
                 int frames, const fs::path& movie, ProgressReporter& progress) {
  auto onLine = [&](const std::string& line) {
    if (line.rfind("frame=", 0) != 0) return;
    const int done = std::atoi(line.c_str() + 6);
    progress.update(static_cast<double>(done) / frames,
                    "frame " + std::to_string(done) + " of " + std::to_string(frames));
  };
  writeAtomically(movie, [&](const fs::path& tmp) {
    std::vector<std::string> argv = {ffmpeg.string(), "-nostdin", "-hide_banner", "-loglevel",
                                     "error", "-nostats", "-progress", "pipe:1", "-y",
                                     "-framerate", std::to_string(picture.series.fps),
                                     "-start_number", "0", "-i", framePattern(series, picture.file),
                                     "-frames:v", std::to_string(frames)};
    for (std::string& a : encoderArguments(picture.series.movie)) argv.push_back(std::move(a));
    argv.push_back(tmp.string());
    const ChildProcessResult r = runChildProcess(argv, LineSplitter(onLine));
    if (!exitedWithZero(r.status) || !fs::exists(tmp))
      throw std::runtime_error(picture.key + ".movie: ffmpeg failed to encode " + movie.string() +
                               " (" + exitDescription(r.status) + "); no movie written; ffmpeg "
                               "said:\n" + r.errors);
  });
}

}  // namespace

void writeMovies(const SceneParams& scene, const SnapshotSeries& series, std::ostream& log,
                 bool interactive, std::vector<fs::path>& written) {
  const int frames = static_cast<int>(series.entries().size());
  for (const ScenePicture& picture : scenePictures(scene)) {
    if (picture.series.movie == MovieFormat::none || frames == 0) continue;
    const std::optional<fs::path> ffmpeg = findFfmpeg();
    if (!ffmpeg)  // validation checked it before the run; PATH may have changed since
      throw std::runtime_error(picture.key + ".movie: ffmpeg is no longer on PATH; install it "
                               "(scripts/setup.sh) and encode the frames again");
    const std::string ext = "." + choiceName(picture.series.movie);
    const fs::path movie = series.dir() / (fs::path(picture.file).stem().string() + ext);
    ProgressReporter progress(log, interactive, scene.name + ": " + movie.filename().string());
    progress.update(0.0, "frame 0 of " + std::to_string(frames));
    encodeMovie(*ffmpeg, series, picture, frames, movie, progress);
    progress.finish("encoded " + std::to_string(frames) + " frames at " +
                    std::to_string(picture.series.fps) + " fps");
    written.push_back(movie);
  }
}

}  // namespace fluidviz
