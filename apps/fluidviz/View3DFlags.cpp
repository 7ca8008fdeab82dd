#include "apps/fluidviz/View3DFlags.h"

#include <ostream>

#include "fieldviz/io/OutputPath.h"

namespace fluidviz::app {

namespace {

const std::vector<KeyFlag> kViewFlags = {
    {"--azimuth", "camera.azimuth", KeyFlag::number},
    {"--elevation", "camera.elevation", KeyFlag::number},
    {"--zoom", "camera.zoom", KeyFlag::number},
    {"--up", "camera.up", KeyFlag::text},
    {"--projection", "camera.projection", KeyFlag::text},
    {"--background", "background", KeyFlag::text},
    {"--turntable", "turntable_frames", KeyFlag::number},
    {"--multisamples", "multisamples", KeyFlag::number},
    {"--size", "width", KeyFlag::custom},
    {"--size", "height", KeyFlag::custom},
    {"--no-outline", "outline", KeyFlag::custom},
    {"--no-scalar-bar", "scalar_bar", KeyFlag::custom}};

}  // namespace

const char* kView3DHelp = R"(  --size WxH               picture size in px (default 800x600)
  --azimuth DEG            turn about the up axis from the front view (default 30)
  --elevation DEG          angle above the horizontal plane, [-89, 89] (default 20)
  --zoom Z                 1: the data's bounding sphere fits; 2: twice as close (default 1)
  --up x|y|z               world axis pointing up in the picture (default y)
  --projection perspective|parallel
  --background white|dark  --no-outline  --no-scalar-bar  --multisamples N (default 4)
  --turntable N            also N frames of a full turn: OUT_0000.png ... OUT_<N-1>.png
)";

std::set<std::string> view3DValuedOptions() {
  std::set<std::string> s;
  for (const KeyFlag& f : kViewFlags)
    if (f.flag.rfind("--no-", 0) != 0) s.insert(f.flag);
  return s;
}

std::set<std::string> view3DSwitches() { return {"--no-outline", "--no-scalar-bar"}; }

View3DParams readView3DFlags(const ParsedArgs& a) {
  scene::json json = scene::json::object();
  if (a.has("--size")) {
    const auto [w, h] = parseSize("--size", a.value("--size"));
    json["width"] = w;
    json["height"] = h > 0 ? h : (w * 3) / 4;
  }
  if (a.has("--no-outline")) json["outline"] = false;
  if (a.has("--no-scalar-bar")) json["scalar_bar"] = false;
  View3DParams view;
  readFlags(a, kViewFlags, view, json);
  checkWithFlagNames(kViewFlags, [&] { validateView3DParams(view); });
  return view;
}

void writeScenePictures(Scene3D& scene, const std::filesystem::path& png, std::ostream& out) {
  requireWritableFolder(png);
  scene.renderToPng(png);
  out << "wrote " << png.string() << "\n";
  if (scene.params().turntable_frames == 0) return;
  std::filesystem::path stem = png;
  stem.replace_extension();
  const auto frames = scene.renderTurntable(stem);
  out << "wrote " << frames.size() << " turntable frames " << frames.front().string() << " ... "
      << frames.back().filename().string() << "\n";
}

}  // namespace fluidviz::app
