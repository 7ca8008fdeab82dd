// fluidviz streamlines: streamlines of a vector array of a .vti file as a .vtp, optionally drawn
// over the speed or LIC picture.
#include <ostream>
#include <sstream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/FlowCommands.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/render/LicPicture.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "filters/lic/PixelVelocity.h"
#include "filters/streamlines/Seeding.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"

namespace fluidviz::app {

namespace sl = fluidviz::streamlines;

namespace {

const char* kStreamlinesHelp = R"(fluidviz streamlines FIELD.vti -a ARRAY -o OUT.vtp [options]

Streamlines of a vector array, integrated in cell units (RK2, RK4 or adaptive Dormand-Prince
RK45), written as polylines with point arrays speed and integration_time and cell arrays reason
(why each line ends; legend in the field data array reason_names), reason_backward and seed_id.

Input:
  -a, --array ARRAY        vector array (2 or 3 components)
  --slice z=K              3D fields: the z layer K to use, [0, nz-1] (required for 3D)
)";

const char* kStreamlinesHelpTail = R"(Seeds (default grid:10,10):
  --seeds line:x0,y0,x1,y1,n   n seeds on a segment (world coordinates)
  --seeds grid:nx,ny           nx x ny seeds at the cell centres of a lattice over the domain
  --seeds points:x,y;x,y;...   the listed seeds
  --evenly-spaced D            evenly spaced lines, D cells apart (Jobard & Lefer 1997)
Integration (defaults and ranges: docs/scenes.md, output.streamlines[].integration):
  --integrator rk2|rk4|rk45    (default rk4)
  --step H                 cells per step (rk45: first step), (0, 100] (default 0.25)
  --tolerance E            rk45 local error per cell, (0, 0.1] (default 1e-6)
  --min-step H, --max-step H   rk45 step limits in cells
  --direction forward|backward|both   (default both)
  --max-length L           cells per direction, (0, 1e9] (default 1000)
  --max-steps N            steps per direction, [1, 1e9] (default 100000)
  --stagnation-speed F     stop where |v| <= F max|v|, [0, 1) (default 1e-4)
Picture:
  --png OUT.png            draw the lines over a picture of the field, coloured by speed (the
                           in-plane speed |v_xy| for a z layer of a 3D field: what lines follow)
  --background speed|lic   speed image (default) or LIC image coloured by speed
  --width W                width of the field area in px (default 800)
  --line-color R,G,B       line colour, each in [0, 1] (default 1,1,1)
  --line-width PX          (default 1.5)
  --no-arrows              no arrowheads
  --colormap NAME, --title TEXT, --background-color white|dark
Outputs:
  -o, --output OUT.vtp     the lines (written atomically)

Lines stop where the field has NaN or infinite values (reason nan_in_field, reported on stderr),
at stagnation (a zero field: every line is its seed, reason stagnation), on leaving the grid
(domain_exit), after max_length or max_steps, or when they close on themselves (closed_loop).
Errors (exit code 2): missing file or array (the arrays present are listed), a scalar array for
-a, a 3D field without --slice, options outside their range.
)";

const std::vector<KeyFlag> kIntegrationFlags = {
    {"--integrator", "integrator", KeyFlag::text},
    {"--step", "step", KeyFlag::number},
    {"--tolerance", "tolerance", KeyFlag::number},
    {"--min-step", "min_step", KeyFlag::number},
    {"--max-step", "max_step", KeyFlag::number},
    {"--direction", "direction", KeyFlag::text},
    {"--max-length", "max_length", KeyFlag::number},
    {"--max-steps", "max_steps", KeyFlag::number},
    {"--stagnation-speed", "stagnation_speed", KeyFlag::number}};
const std::vector<KeyFlag> kSeedFlags = {
    {"--evenly-spaced", "evenly_spaced.separating_distance", KeyFlag::number}};
const std::vector<KeyFlag> kStyleFlags = {
    {"--line-width", "line_width", KeyFlag::number},
    {"--line-color", "line_color", KeyFlag::custom}};
const std::vector<KeyFlag> kPictureFlags = {
    {"--colormap", "colormap", KeyFlag::text},
    {"--title", "title", KeyFlag::text},
    {"--background-color", "background", KeyFlag::text}};

const char* kSeedsFormat =
    "allowed: line:x0,y0,x1,y1,n | grid:nx,ny | points:x,y;x,y;... (world coordinates)";

// --seeds as the keys of SeedingParams.
scene::json seedingJson(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  const std::string kind = spec.substr(0, colon), list = colon == std::string::npos ? "" : spec.substr(colon + 1);
  scene::json j = scene::json::object();
  if (kind == "line") {
    const auto v = parseNumbers("--seeds line", list, 5);
    j["strategy"] = "line";
    j["line_start"] = {v[0], v[1], 0.0};
    j["line_end"] = {v[2], v[3], 0.0};
    j["line_count"] = v[4];
  } else if (kind == "grid") {
    const auto v = parseNumbers("--seeds grid", list, 2);
    j["strategy"] = "grid";
    j["grid_counts"] = {v[0], v[1], 1.0};
  } else if (kind == "points") {
    j["strategy"] = "points";
    j["points"] = scene::json::array();
    std::stringstream s(list);
    std::string point;
    while (std::getline(s, point, ';')) {
      const auto v = parseNumbers("--seeds points", point, 2);
      j["points"].push_back({{"position", {v[0], v[1], 0.0}}});
    }
  } else {
    throw UsageError("--seeds is '" + spec + "'; " + kSeedsFormat);
  }
  return j;
}

struct StreamlineArgs {
  std::filesystem::path field, vtp, png;
  std::string array, slice, background = "speed";
  int width = kDefaultPictureWidth;
  sl::StreamlineParams integration;
  sl::SeedingParams seeding;
  StreamlineStyle style;
  FieldImageParams picture;
  std::optional<std::string> units;  ///< --units; nullopt: the file's or m
  ImageSampling sampling;            ///< --spacing
};

void parsePictureArgs(const ParsedArgs& a, StreamlineArgs& r) {
  r.png = a.value("--png");
  r.background = a.value("--background", "speed");
  if (r.background != "speed" && r.background != "lic")
    throw UsageError("--background is '" + r.background + "'; allowed: speed or lic");
  if (a.has("--width")) r.width = parseSize("--width", a.value("--width")).first;
  if (r.width < 16 || r.width > 8000)
    throw UsageError("--width is " + std::to_string(r.width) + "; allowed: 16 to 8000 px");
  scene::json style = scene::json::object();
  style["arrows"] = !a.has("--no-arrows");
  if (a.has("--line-color")) {
    const auto c = parseNumbers("--line-color", a.value("--line-color"), 3);
    style["line_color"] = c;
  }
  readFlags(a, kStyleFlags, r.style, style);
  readFlags(a, kPictureFlags, r.picture);
  checkWithFlagNames(kPictureFlags, [&] { validateFieldImageParams(r.picture); });
}

StreamlineArgs parseStreamlineArgs(const ParsedArgs& a) {
  StreamlineArgs r;
  if (a.positional.size() != 1)
    throw UsageError("needs exactly one field file (.vti), got " +
                     std::to_string(a.positional.size()));
  r.field = a.positional[0];
  r.array = a.value("--array");
  r.slice = a.value("--slice");
  r.vtp = a.value("--output");
  if (r.vtp.empty()) throw UsageError("needs -o OUT.vtp");
  r.units = unitsOption(a);
  r.sampling = samplingOption(a);
  readFlags(a, kIntegrationFlags, r.integration);
  checkWithFlagNames(kIntegrationFlags, [&] { sl::validateStreamlineParams(r.integration); });
  if (a.has("--seeds") && a.has("--evenly-spaced"))
    throw UsageError("give either --seeds or --evenly-spaced, not both");
  scene::json seeding = a.has("--seeds") ? seedingJson(a.value("--seeds")) : scene::json::object();
  if (a.has("--evenly-spaced")) seeding["strategy"] = "evenly_spaced";
  try {
    readFlags(a, kSeedFlags, r.seeding, seeding);
  } catch (const UsageError& e) {
    throw UsageError(std::string(a.has("--seeds") ? "--seeds: " : "") + e.what());
  }
  parsePictureArgs(a, r);
  return r;
}

// The picture behind the lines: the speed field, or its LIC coloured by speed.
FieldPicture renderBackground(const StreamlineArgs& r, const FlowInput& in,
                              const std::vector<LineOverlay>& lines) {
  const ColourScalar speed = colourScalar(in, "speed");
  FieldImageParams picture = r.picture;
  if (picture.title.empty())
    picture.title = "Streamlines of " + r.array + " over " +
                    (r.background == "lic" ? "its LIC, coloured by speed" : "its speed");
  if (picture.scalar_bar_title.empty()) picture.scalar_bar_title = speed.legendTitle;
  if (r.background == "speed") {
    fitPictureToField(speed.field, picture, r.width);
    return renderFieldPicture(speed.field, picture, lines);
  }
  lic::LicParams params;
  params.width = r.width;
  lic::LicImage texture;
  try {
    texture = lic::computeLic(in.velocity, params);
  } catch (const lic::NonFiniteFieldError& e) {
    throw FileError(in.file, in.source + ": " + e.message("use --background speed"), in.array);
  } catch (const std::invalid_argument& e) {
    throw FileError(in.file, in.source + ": " + e.what() + " (use --background speed)", in.array);
  }
  const LicPicture lic = renderLicPicture(texture.texture, texture.mask, speed.field, picture,
                                          LicBlendParams{}, lines);
  return {lic.image, lic.range};
}

void report(const std::vector<sl::Streamline>& lines, const StreamlineArgs& r, std::ostream& out,
            std::ostream& err, const std::string& prefix) {
  int nan = 0;
  for (const auto& l : lines)
    nan += l.forward_end == sl::TerminationReason::nan_in_field ||
           l.backward_end == sl::TerminationReason::nan_in_field;
  out << "traced " << lines.size() << " lines (" << choiceName(r.integration.integrator) << ", step "
      << r.integration.step << " cells); they end by: " << sl::summarizeReasons(lines) << "\n";
  if (nan > 0)
    err << prefix << "warning: " << nan << " lines stopped at NaN or infinite values of '"
        << r.array << "' (reason nan_in_field)\n";
}

}  // namespace

int streamlinesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                       bool) {
  const ParsedArgs a = parseArgs(
      args,
      {"--array", "--output", "--slice", "--seeds", "--evenly-spaced", "--integrator", "--step",
       "--tolerance", "--min-step", "--max-step", "--direction", "--max-length", "--max-steps",
       "--stagnation-speed", "--png", "--background", "--width", "--line-color", "--line-width",
       "--colormap", "--title", "--background-color", "--units", "--spacing"},
      {"--help", "--no-arrows"}, {{"-a", "--array"}, {"-o", "--output"}, {"-h", "--help"}});
  if (a.has("--help")) {
    out << kStreamlinesHelp << unitsHelpLine() << spacingHelpLine() << kStreamlinesHelpTail;
    return kSuccess;
  }
  const StreamlineArgs r = parseStreamlineArgs(a);
  if (r.array.empty()) throwMissingArrayOption(r.field);
  const FlowInput in = readFlowInput({r.field, r.array, r.slice, r.units, r.sampling});
  requireWritableFolder(r.vtp);
  if (!r.png.empty()) requireWritableFolder(r.png);
  std::vector<sl::Streamline> lines;
  checkWithFlagNames(kSeedFlags, [&] { lines = sl::traceSeeded(in.velocity, r.seeding, r.integration); });
  FieldPicture picture;
  if (!r.png.empty()) {
    LineOverlay overlay{{}, r.style};
    for (const auto& l : lines) overlay.lines.push_back(l.points);
    picture = renderBackground(r, in, {overlay});
  }
  writeVtp(sl::streamlinesToPolyData(lines), r.vtp);
  out << "wrote " << r.vtp.string() << "\n";
  if (!r.png.empty()) {
    writePng(picture.image, r.png);
    out << "wrote " << r.png.string() << " (colour range [" << picture.range[0] << ", "
        << picture.range[1] << "])\n";
  }
  report(lines, r, out, err, messagePrefix(args));
  return kSuccess;
}

}  // namespace fluidviz::app
