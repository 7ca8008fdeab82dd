// Pictures of every snapshot and their movies (issue 16, "movies"; pipeline/PictureSeries.h):
//   - every_snapshot draws a frame <name>/<stem>_NNNN.png per snapshot, t = 0 included (n + 1
//     for n snapshots); the last frame is the final state drawn by the same function, so it is
//     byte-identical to the final picture; frames and movie are in the run's file list;
//   - movie mp4: ffprobe reads codec h264 with n + 1 frames, the picture's size padded to even;
//     movie gif (of an output.lic picture): codec gif, n + 1 frames, the picture's size;
//   - output.views[] (SPH) take the same keys and write the same frames and movies;
//   - a movie without every_snapshot, every_snapshot without snapshots and a movie without
//     ffmpeg on PATH are refused before the run, naming the key; an ffmpeg that fails leaves no
//     movie (nor its temporary file) and its message is shown.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <regex>

#include <gtest/gtest.h>

#include "pipeline/SceneValidation.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz::test {
namespace {

constexpr int kSnapshots = 4;

// A 1 m box, 24 nodes across, one roller turning at 1 rad/s; `pictures` is the output section's
// picture entries.
std::string rollerScene(const std::string& pictures, int snapshots = kSnapshots) {
  return R"({"name": "roller", "solver": "lbm",
    "lbm": {"domain_size": [1.0, 1.0], "resolution": 24, "viscosity": 0.01,
            "reference_length": 0.4, "lattice_velocity": 0.05,
            "rollers": [{"center": [0.5, 0.5], "radius": 0.2, "angular_velocity": 1.0}],
            "end_time": 0.5},
    "output": {"snapshots": )" + std::to_string(snapshots) + ", " + pictures + "}}";
}

// Width and height of a PNG from its IHDR chunk (big-endian at bytes 16 and 20).
std::array<int, 2> pngSize(const fs::path& png) {
  const std::string s = readText(png);
  auto be32 = [&](std::size_t at) {
    int v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(s.at(at + i));
    return v;
  };
  return {be32(16), be32(20)};
}

// ffprobe's "codec,width,height,frames" of the movie's first video stream.
std::string probe(const fs::path& movie) {
  const std::string command =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,width,height,nb_read_frames -of csv=p=0 '" + movie.string() + "' 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
  std::string out;
  char buffer[256];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe.get())) out += buffer;
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

int framesIn(const fs::path& folder, const std::string& stem) {
  const std::regex frame(stem + R"(_\d{4}\.png)");
  int n = 0;
  for (const auto& e : fs::directory_iterator(folder))
    n += std::regex_match(e.path().filename().string(), frame);
  return n;
}

// Files in `folder` named like the movie `name` or its temporary file (core/AtomicFile.h).
int moviesIn(const fs::path& folder, const std::string& name) {
  const fs::path movie(name);
  int n = 0;
  for (const auto& e : fs::directory_iterator(folder)) {
    const std::string f = e.path().filename().string();
    n += f.find(movie.stem().string()) != std::string::npos && e.path().extension() == movie.extension();
  }
  return n;
}

bool lists(const RunSummary& run, const fs::path& file) {
  return std::find(run.files.begin(), run.files.end(), file) != run.files.end();
}

std::string errorOf(const std::string& json) {
  try {
    validateScene(sceneFromText(json), "scene.json");
  } catch (const scene::SceneError& e) {
    return e.key() + ": " + e.what();
  }
  return "no error";
}

class PictureSeriesTest : public TempDirTest {};

TEST_F(PictureSeriesTest, FramesOfEverySnapshotAndAnMp4OfThem) {
  // Odd width and height: the mp4 is padded to even ones.
  const RunSummary run = runInto(sceneFromText(rollerScene(
      R"("images": [{"field": "speed", "width": 241, "height": 181, "range_min": 0,
                     "range_max": 0.25, "every_snapshot": true, "movie": "mp4", "fps": 5}])")),
      "out");
  const fs::path out = dir_ / "out";
  EXPECT_EQ(framesIn(out / "roller", "roller_speed"), kSnapshots + 1);
  for (int i = 0; i <= kSnapshots; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "roller_speed_%04d.png", i);
    EXPECT_TRUE(lists(run, out / "roller" / name)) << name;
  }
  // The last snapshot is the final state, drawn by the same function.
  EXPECT_EQ(readText(out / "roller" / "roller_speed_0004.png"), readText(out / "roller_speed.png"));
  EXPECT_NE(readText(out / "roller" / "roller_speed_0000.png"), readText(out / "roller_speed.png"));
  EXPECT_EQ(pngSize(out / "roller_speed.png"), (std::array<int, 2>{241, 181}));
  EXPECT_EQ(probe(out / "roller_speed.mp4"), "h264,242,182,5");
  EXPECT_TRUE(lists(run, out / "roller_speed.mp4"));
  EXPECT_EQ(moviesIn(out, "roller_speed.mp4"), 1);  // no temporary file left
}

TEST_F(PictureSeriesTest, GifOfLicFrames) {
  runInto(sceneFromText(rollerScene(
      R"("images": [], "lic": [{"width": 48, "height": 48, "color_by":
                   "speed", "scalar_bar": false, "every_snapshot": true, "movie": "gif"}])")),
      "out");
  const fs::path out = dir_ / "out";
  EXPECT_EQ(framesIn(out / "roller", "roller_lic_speed"), kSnapshots + 1);
  const std::array<int, 2> size = pngSize(out / "roller_lic_speed.png");
  EXPECT_EQ(probe(out / "roller_lic_speed.gif"),
            "gif," + std::to_string(size[0]) + "," + std::to_string(size[1]) + "," +
                std::to_string(kSnapshots + 1));
}

// SPH 3D views take the same keys: frames <name>/<stem>_NNNN.png from t = 0, the last equal to
// the final picture, and a movie of them.
TEST_F(PictureSeriesTest, GifOfSphViewFrames) {
  const std::string scene = R"({"name": "dam", "solver": "sph",
    "sph": {"dimension": 2, "model": "B", "particle_spacing": 0.04, "speed_of_sound": 19.8,
            "alpha": 0.1, "domain_upper": [0.8, 0.6, 0], "walls": {"y_max": "open"},
            "fluid_blocks": [{"lower": [0, 0, 0], "upper": [0.2, 0.4, 0]}], "end_time": 0.04},
    "output": {"snapshots": 3, "images": [],
               "views": [{"file": "v.png", "show": "particles", "width": 96, "height": 64,
                          "every_snapshot": true, "movie": "gif", "fps": 4}]}})";
  const RunSummary run = runInto(sceneFromText(scene), "out");
  const fs::path out = dir_ / "out";
  EXPECT_EQ(framesIn(out / "dam", "v"), 3 + 1);
  EXPECT_TRUE(lists(run, out / "dam" / "v_0000.png"));
  EXPECT_EQ(readText(out / "dam" / "v_0003.png"), readText(out / "v.png"));
  EXPECT_EQ(probe(out / "v.gif"), "gif,96,64,4");
  EXPECT_TRUE(lists(run, out / "v.gif"));
}

TEST_F(PictureSeriesTest, OnlyTheFinalPictureWithoutEverySnapshot) {
  runInto(sceneFromText(rollerScene(R"("images": [{"field": "speed", "width": 240, "height": 180}])")),
          "out");
  EXPECT_EQ(framesIn(dir_ / "out" / "roller", "roller_speed"), 0);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "roller_speed.png"));
}

TEST_F(PictureSeriesTest, MovieNeedsEverySnapshot) {
  const std::string e = errorOf(rollerScene(R"("images": [{"field": "speed", "movie": "mp4"}])"));
  EXPECT_NE(e.find("output.images[0].movie: "), std::string::npos) << e;
  EXPECT_NE(e.find("every_snapshot is false"), std::string::npos) << e;
}

TEST_F(PictureSeriesTest, EverySnapshotNeedsSnapshots) {
  const std::string e =
      errorOf(rollerScene(R"("images": [{"field": "speed", "every_snapshot": true}])", 0));
  EXPECT_NE(e.find("output.images[0].every_snapshot: "), std::string::npos) << e;
}

// A LIC picture with axes keeps its texture size and grows by the axes' bands: wider (y labels
// and title) and taller (x labels and title) than the same picture without them.
TEST_F(PictureSeriesTest, AxesOnALicPictureGrowItAroundTheSameTexture) {
  runInto(sceneFromText(rollerScene(
              R"("images": [], "lic": [{"width": 96, "file": "plain.png"},
                                      {"width": 96, "file": "axes.png", "axes": true}])", 1)),
          "out");
  const std::array<int, 2> plain = pngSize(dir_ / "out" / "plain.png");
  const std::array<int, 2> axes = pngSize(dir_ / "out" / "axes.png");
  EXPECT_GT(axes[0], plain[0] + 20);
  EXPECT_GT(axes[1], plain[1] + 20);
}

TEST_F(PictureSeriesTest, FpsOutOfRangeIsRefused) {
  const std::string e = errorOf(rollerScene(
      R"("lic": [{"every_snapshot": true, "movie": "gif", "fps": 0}], "images": [])"));
  EXPECT_NE(e.find("output.lic[0].fps: "), std::string::npos) << e;
}

TEST_F(PictureSeriesTest, MovieWithoutFfmpegIsRefusedBeforeTheRun) {
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", dir_.c_str(), 1);  // an empty folder: no ffmpeg
  const std::string json =
      rollerScene(R"("images": [{"field": "speed", "every_snapshot": true, "movie": "gif"}])");
  const std::string e = errorOf(json);
  RunOptions options = optionsFor("out", false, -1);
  EXPECT_THROW(runScene(sceneFromText(json), options), scene::SceneError);
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_NE(e.find("output.images[0].movie: "), std::string::npos) << e;
  EXPECT_NE(e.find("needs ffmpeg"), std::string::npos) << e;
  EXPECT_NE(e.find("scripts/setup.sh"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "roller.pvd"));  // nothing written
}

TEST_F(PictureSeriesTest, FailingFfmpegLeavesNoMovieAndShowsItsMessage) {
  // A stand-in that writes part of its output file (the last argument), complains and fails.
  const fs::path bin = dir_ / "bin";
  fs::create_directories(bin);
  testing::writeText(bin / "ffmpeg", "#!/bin/sh\nfor a; do last=$a; done\necho partial > \"$last\"\n"
                                     "echo 'fake ffmpeg: broken encoder' >&2\nexit 3\n");
  fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", (bin.string() + ":" + saved).c_str(), 1);
  std::string error = "no error";
  try {
    runInto(sceneFromText(rollerScene(R"("images": [{"field": "speed", "width": 240, "height": 180,
                                         "every_snapshot": true, "movie": "mp4"}])")),
            "out");
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_NE(error.find("output.images[0].movie: ffmpeg failed"), std::string::npos) << error;
  EXPECT_NE(error.find("exit code 3"), std::string::npos) << error;
  EXPECT_NE(error.find("fake ffmpeg: broken encoder"), std::string::npos) << error;
  EXPECT_EQ(moviesIn(dir_ / "out", "roller_speed.mp4"), 0);  // neither movie nor temporary file
  EXPECT_TRUE(fs::exists(dir_ / "out" / "roller_run.json"));  // --replace can remove the run
}

}  // namespace
}  // namespace fluidviz::test
