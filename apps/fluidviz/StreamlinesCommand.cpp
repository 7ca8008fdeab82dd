// fluidviz streamlines: streamlines of a vector array of a .vti file as a .vtp, optionally drawn
// over the speed or LIC picture.
#include <algorithm>
#include <memory>
#include <ostream>
#include <sstream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/FlowCommands.h"
#include "apps/fluidviz/SeedFile.h"
#include "apps/fluidviz/Streamlines3D.h"
#include "apps/fluidviz/View3DFlags.h"
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
  --slice SLICE            x=I|y=J|z=K, x@X|y@Y|z@Z or plane:ox,oy,oz,nx,ny,nz (docs/slices.md):
                           trace in that 2D slice; without it a 3D field is traced in 3D
                           (trilinear)
  --mask ARRAY             nonzero = fluid; the file's vtkValidPointMask, NaN/inf and (2D)
                           zero-velocity solids are masked without it (lines end there: reason
                           nan_in_field)
  --crop x0,x1,y0,y1       2D fields and slices: region of interest in world coordinates
)";

const char* kStreamlinesHelpSeeds = R"(Seeds (default grid:10,10 in 2D, grid:5,5,5 in 3D; world coordinates; 2D forms take x,y):
  --seeds line:x0,y0,x1,y1,n | line:x0,y0,z0,x1,y1,z1,n   n seeds on a segment, ends included
  --seeds grid:nx,ny | grid:nx,ny,nz   seeds at the cell centres of a lattice over the domain
  --seeds points:x,y;x,y;... | points:x,y,z;...   the listed seeds
  --seeds plane:ox,oy,oz,ux,uy,uz,vx,vy,vz,nu,nv   nu x nv seeds o + i/(nu-1) u + j/(nv-1) v
  --seeds box:x0,y0,z0,x1,y1,z1,nx,ny,nz   nx x ny x nz seeds filling the box, faces included
  --seeds file:PATH.csv|PATH.vtp   rows x,y,z (header row optional), or a .vtp's points
)";

const char* kStreamlinesHelpTail = R"(  --evenly-spaced D            evenly spaced lines, D cells apart (Jobard & Lefer 1997)
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
  --underlay speed|lic     under the lines: speed image (default) or LIC coloured by speed
  --width W                width of the field area in px (default 800)
  --axes                   x and y axes with round ticks in world coordinates
  --line-color R,G,B       line colour, each in [0, 1] (default 1,1,1)
  --line-width PX          (default 1.5)
  --no-arrows              no arrowheads
  --colormap NAME, --title TEXT (empty: none), --background white|dark (the backdrop)
3D picture (a 3D field without --slice): the lines inside the domain's outline
  --color-by ARRAY         speed (default), integration_time or a point array of the field
  --tubes R                tubes of radius R cells instead of lines
  --context slice:z=K | isosurface:ARRAY=V   a grey z layer of the speed, or a level set
)";

const char* kStreamlinesHelpOutputs = R"(Outputs:
  -o, --output OUT.vtp     the lines (written atomically)

Lines stop where the field has NaN or infinite values (reason nan_in_field, reported on stderr),
at stagnation (a zero field: every line is its seed, reason stagnation), on leaving the grid
(domain_exit), after max_length or max_steps, or when they close on themselves (closed_loop).
Seeds outside the grid trace nothing and are counted on stdout.
Errors (exit code 2): missing file or array (the arrays present are listed), a scalar array for
-a, a bad seeds file (its line is named), options outside their range.
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
    {"--background", "background", KeyFlag::text}};

const char* kSeedsFormat =
    "allowed: line:x0,y0[,z0],x1,y1[,z1],n | grid:nx,ny[,nz] | points:x,y[,z];... | "
    "plane:ox,oy,oz,ux,uy,uz,vx,vy,vz,nu,nv | box:x0,y0,z0,x1,y1,z1,nx,ny,nz | "
    "file:PATH.csv|PATH.vtp (world coordinates)";

// The numbers of a --seeds form that takes `count2D` (2D form) or `count3D` values.
std::vector<double> seedNumbers(const std::string& kind, const std::string& list, int count2D,
                                int count3D) {
  const int commas = static_cast<int>(std::count(list.begin(), list.end(), ','));
  return parseNumbers("--seeds " + kind, list, commas + 1 == count3D ? count3D : count2D);
}

scene::json pointsJson(const std::vector<Vec3>& points) {
  scene::json list = scene::json::array();
  for (const Vec3& p : points) list.push_back({{"position", {p.x(), p.y(), p.z()}}});
  return list;
}

// --seeds as the keys of SeedingParams (2D forms put seeds at z = 0).
scene::json seedingJson(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  const std::string kind = spec.substr(0, colon), list = colon == std::string::npos ? "" : spec.substr(colon + 1);
  scene::json j = scene::json::object();
  if (kind == "line") {
    const auto v = seedNumbers(kind, list, 5, 7);
    const bool in3D = v.size() == 7;
    j["strategy"] = "line";
    j["line_start"] = in3D ? std::vector<double>{v[0], v[1], v[2]} : std::vector<double>{v[0], v[1], 0.0};
    j["line_end"] = in3D ? std::vector<double>{v[3], v[4], v[5]} : std::vector<double>{v[2], v[3], 0.0};
    j["line_count"] = v.back();
  } else if (kind == "grid") {
    const auto v = seedNumbers(kind, list, 2, 3);
    j["strategy"] = "grid";
    j["grid_counts"] = {v[0], v[1], v.size() == 3 ? v[2] : 1.0};
  } else if (kind == "points") {
    j["strategy"] = "points";
    std::vector<Vec3> points;
    std::stringstream s(list);
    std::string point;
    while (std::getline(s, point, ';')) {
      const auto v = seedNumbers(kind, point, 2, 3);
      points.emplace_back(v[0], v[1], v.size() == 3 ? v[2] : 0.0);
    }
    j["points"] = pointsJson(points);
  } else if (kind == "plane") {
    const auto v = parseNumbers("--seeds plane", list, 11);
    j["strategy"] = "plane";
    j["plane_origin"] = {v[0], v[1], v[2]};
    j["plane_u"] = {v[3], v[4], v[5]};
    j["plane_v"] = {v[6], v[7], v[8]};
    j["plane_counts"] = {v[9], v[10]};
  } else if (kind == "box") {
    const auto v = parseNumbers("--seeds box", list, 9);
    j["strategy"] = "box";
    j["box_min"] = {v[0], v[1], v[2]};
    j["box_max"] = {v[3], v[4], v[5]};
    j["box_counts"] = {v[6], v[7], v[8]};
  } else if (kind == "file" && !list.empty()) {
    j["strategy"] = "points";
    j["points"] = pointsJson(readSeedFile(list));
  } else {
    throw UsageError("--seeds is '" + spec + "'; " + kSeedsFormat);
  }
  return j;
}

struct StreamlineArgs {
  std::filesystem::path field, vtp, png;
  std::string array, slice, mask, crop, underlay = "speed";
  bool fileArrays = true;  ///< not --ignore-file-arrays
  bool titleGiven = false;  ///< --title (an empty one: no title)
  int width = kDefaultPictureWidth;
  sl::StreamlineParams integration;
  sl::SeedingParams seeding;
  StreamlineStyle style;
  FieldImageParams picture;
  std::optional<std::string> units;  ///< --units; nullopt: the file's or m
  Streamlines3DPicture picture3D;    ///< the picture of a 3D field without --slice
  ImageSampling sampling;            ///< --spacing
};

// Flags that only the 3D picture reads, and 2D ones it refuses.
const std::vector<std::string> k3DOnlyFlags = {"--tubes", "--context", "--color-by"};

// The 3D picture flags: the camera, size and background ones are isosurface's (View3DFlags).
Streamlines3DPicture parse3DPicture(const ParsedArgs& a, const StreamlineArgs& r) {
  Streamlines3DPicture p;
  p.view = readView3DFlags(a);
  p.color_by = a.value("--color-by", "speed");
  p.colormap = r.picture.colormap;
  if (a.has("--title")) p.title = r.picture.title;
  p.line_width = r.style.line_width;
  p.context = a.value("--context");
  if (a.has("--tubes")) {
    p.tube_radius = parseNumbers("--tubes", a.value("--tubes"), 1)[0];
    if (!(p.tube_radius > 0 && p.tube_radius <= 100))
      throw UsageError("--tubes is " + a.value("--tubes") + "; allowed: (0, 100] cells");
  }
  return p;
}

// --background was the underlay and --background-color the backdrop before they took the names
// the other commands use (issue 16, defect 10); old command lines get told the new ones.
void refuseRetiredPictureFlags(const ParsedArgs& a) {
  if (a.has("--background-color"))
    throw UsageError("--background-color is now --background white|dark (the backdrop, as in "
                     "fluidviz lic)");
  refuseUnderlayAsBackground(a, "lines");
}

void parsePictureArgs(const ParsedArgs& a, StreamlineArgs& r) {
  refuseRetiredPictureFlags(a);
  r.png = a.value("--png");
  r.titleGiven = a.has("--title");
  r.underlay = a.value("--underlay", "speed");
  if (r.underlay != "speed" && r.underlay != "lic")
    throw UsageError("--underlay is '" + r.underlay + "'; allowed: speed or lic");
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
  r.picture.axes = a.has("--axes");
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
  r.mask = a.value("--mask");
  r.fileArrays = !a.has(kIgnoreFileArraysFlag);
  r.crop = a.value("--crop");
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
  r.picture3D = parse3DPicture(a, r);
  return r;
}

// The picture behind the lines: the speed field, or its LIC coloured by speed.
FieldPicture renderBackground(const StreamlineArgs& r, const FlowInput& in,
                              const std::vector<LineOverlay>& lines) {
  const ColourScalar speed = colourScalar(in, "speed");
  FieldImageParams picture = r.picture;
  if (!r.titleGiven)
    picture.title = "Streamlines of " + r.array + " over " +
                    (r.underlay == "lic" ? "its LIC, coloured by speed" : "its speed");
  if (picture.scalar_bar_title.empty()) picture.scalar_bar_title = speed.legendTitle;
  picture.axes_unit = in.units;
  if (r.underlay == "speed") {
    fitPictureToField(speed.field, picture, r.width);
    return renderFieldPicture(speed.field, picture, lines);
  }
  lic::LicParams params;
  params.width = r.width;
  lic::LicImage texture;
  try {
    texture = lic::computeLic(in.velocity, params, in.mask);
  } catch (const lic::NonFiniteFieldError& e) {
    throw FileError(in.file, in.source + ": " + e.message("use --underlay speed"), in.array);
  } catch (const std::invalid_argument& e) {
    throw FileError(in.file, in.source + ": " + e.what() + " (use --underlay speed)", in.array);
  }
  const LicPicture lic = renderLicPicture(texture.texture, texture.mask, speed.field, picture,
                                          LicBlendParams{}, lines);
  return {lic.image, lic.range};
}

bool hasNonFiniteValue(const VectorField& v) {
  return std::any_of(v.values.begin(), v.values.end(), [](const Vec3& x) { return !x.allFinite(); });
}

// Lines that end at NaN: a warning when the field itself holds NaN or infinite values; a plain
// count when only the mask (a snapshot's solids, --mask) made them, where ending is expected.
void report(const std::vector<sl::Streamline>& lines, const StreamlineArgs& r, bool in3D,
            bool fieldHasNonFinite, std::ostream& out, std::ostream& err,
            const std::string& prefix) {
  int nan = 0, outside = 0;
  for (const auto& l : lines) {
    nan += l.forward_end == sl::TerminationReason::nan_in_field ||
           l.backward_end == sl::TerminationReason::nan_in_field;
    outside += l.points.empty() && l.reason() == sl::TerminationReason::domain_exit;
  }
  out << "traced " << lines.size() << " lines " << (in3D ? "in 3D " : "") << "("
      << choiceName(r.integration.integrator) << ", step " << r.integration.step
      << " cells); they end by: " << sl::summarizeReasons(lines) << "\n";
  if (outside > 0)
    out << outside << " of " << lines.size() << " seeds lie outside the grid (no line)\n";
  if (nan > 0 && fieldHasNonFinite)
    err << prefix << "warning: " << nan << " lines stopped at NaN or infinite values of '"
        << r.array << "' (reason nan_in_field)\n";
  else if (nan > 0)
    out << nan << " lines end at masked nodes (solids or --mask; reason nan_in_field)\n";
}

// 2D picture flags on a 3D field, or 3D ones on a 2D field or layer: refused, naming the flag.
void checkPictureFlags(const ParsedArgs& a, bool in3D) {
  std::vector<std::string> only3D = k3DOnlyFlags;
  for (const std::string& f : view3DValuedOptions())
    if (f != "--background") only3D.push_back(f);
  for (const std::string& f : view3DSwitches()) only3D.push_back(f);
  const std::vector<std::string> only2D = {"--underlay", "--width", "--line-color",
                                           "--no-arrows", "--axes"};
  for (const std::string& f : in3D ? only2D : only3D)
    if (a.has(f))
      throw UsageError(f + (in3D ? " is for the 2D picture (a 2D field or --slice); the 3D "
                                   "picture takes --size, --background and the camera flags"
                                 : " is for the 3D picture of a 3D field traced without --slice"));
}

// A 3D field traced in 3D: the .vtp and the 3D picture.
int finish3D(const std::vector<sl::Streamline>& lines, const StreamlineArgs& r,
             const FlowInput& in, std::ostream& out, std::ostream& err,
             const std::string& prefix) {
  const vtkSmartPointer<vtkPolyData> polyData = sl::streamlinesToPolyData(lines);
  std::unique_ptr<Scene3D> scene;  // built before writing: its errors stop everything
  if (!r.png.empty()) scene = streamlinesScene(in, polyData, r.picture3D);
  writeVtp(polyData, r.vtp);
  out << "wrote " << r.vtp.string() << "\n";
  if (scene) writeScenePictures(*scene, r.png, out);
  report(lines, r, true, hasNonFiniteValue(in.velocity), out, err, prefix);
  return kSuccess;
}

}  // namespace

int streamlinesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                       bool) {
  std::set<std::string> valued = view3DValuedOptions();
  valued.insert({"--array", "--output", "--slice", "--seeds", "--evenly-spaced", "--integrator",
                 "--step", "--tolerance", "--min-step", "--max-step", "--direction",
                 "--max-length", "--max-steps", "--stagnation-speed", "--png", "--background", "--underlay",
                 "--width", "--line-color", "--line-width", "--colormap", "--title",
                 "--background-color", "--units", "--tubes", "--context", "--color-by",
                 "--mask", "--crop", "--spacing"});
  std::set<std::string> switches = view3DSwitches();
  switches.insert({"--help", "--no-arrows", "--axes", kIgnoreFileArraysFlag});
  const ParsedArgs a = parseArgs(args, valued, switches,
                                 {{"-a", "--array"}, {"-o", "--output"}, {"-h", "--help"}});
  if (a.has("--help")) {
    out << kStreamlinesHelp << ignoreFileArraysHelpLine() << unitsHelpLine() << spacingHelpLine() << kStreamlinesHelpSeeds << kStreamlinesHelpTail
        << kView3DHelp << kStreamlinesHelpOutputs;
    return kSuccess;
  }
  const StreamlineArgs r = parseStreamlineArgs(a);
  if (r.array.empty()) throwMissingArrayOption(r.field);
  const FlowInput in = readFlowInput(
      {r.field, r.array, r.slice, r.units, r.sampling, r.mask, r.crop, true, r.fileArrays});
  const bool in3D = !in.velocity.grid.is2D();
  checkPictureFlags(a, in3D);
  requireWritableFolder(r.vtp);
  if (!r.png.empty()) requirePictureFile(r.png), requireWritableFolder(r.png);
  sl::SeedingParams seeding = r.seeding;
  if (in3D && !a.has("--seeds") && !a.has("--evenly-spaced")) seeding.grid_counts = {5, 5, 5};
  std::vector<sl::Streamline> lines;
  checkWithFlagNames(kSeedFlags, [&] { lines = sl::traceSeeded(in.maskedVelocity(), seeding, r.integration); });
  if (in3D) return finish3D(lines, r, in, out, err, messagePrefix(args));
  FieldPicture picture;
  if (!r.png.empty()) {
    LineOverlay overlay{{}, r.style};
    for (const auto& l : lines) overlay.lines.push_back(l.points);
    picture = renderBackground(r, in, {overlay});
  }
  writeVtp(sl::streamlinesToPolyData(lines), r.vtp);
  out << "wrote " << r.vtp.string() << "\n";
  if (!r.png.empty()) {
    writePicture(picture.image, r.png);
    out << "wrote " << r.png.string() << " (colour range [" << picture.range[0] << ", "
        << picture.range[1] << "])\n";
  }
  report(lines, r, false, hasNonFiniteValue(in.velocity), out, err, messagePrefix(args));
  return kSuccess;
}

}  // namespace fluidviz::app
