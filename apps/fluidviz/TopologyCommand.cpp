// fluidviz topology: critical points (Morse and non-Morse), their Poincare index and sectors, and
// separatrices of a vector array of a .vti file, as .vtp, CSV and a picture; for a 3D array
// without --slice the critical points of the 3D field (VolumeTopology.h) as .vtp and CSV.
#include <vtkPolyData.h>

#include <ostream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/TopologyCommands.h"
#include "apps/fluidviz/View3DFlags.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/FlowFields.h"
#include "pipeline/TopologyOutputs.h"
#include "pipeline/TopologyPicture3D.h"
#include "fieldviz/scene/SceneFile.h"
#include "filters/topology/VectorFieldTopology.h"
#include "filters/topology/Separatrices3D.h"
#include "filters/topology/VolumeTopology.h"
#include "filters/topology/vtk/TopologyPolyData.h"

namespace fluidviz::app {

namespace {

namespace fs = std::filesystem;
namespace topo = fluidviz::topology;

const char* kTopologyHelp = R"(fluidviz topology FIELD.vti -a ARRAY -o POINTS.vtp [options]

Critical points of a planar vector array: zeros of the bilinear interpolant, grouped into
clusters (a degenerate point such as a monkey saddle is ONE point), each with its Poincare index
measured on a loop around it, its sectors (hyperbolic, elliptic, parabolic), its Jacobian and its
type: Morse (saddle, source, sink, spiral source/sink, centre) or non-Morse (monkey saddle,
saddle-node, cusp, dipole, degenerate). Separatrices are traced from every saddle-like point.

A 3D array without --slice is analysed in 3D: zeros of the piecewise-linear interpolant on six
tetrahedra per cell, clustered the same way, each with its index (degree of v/|v| on a sphere
around it) and type (source, sink, saddle_1, saddle_2, their spiral variants, centre; degenerate
when non-Morse), the 1D separatrices of its saddles (the lone eigendirection's manifold) and
their separating surfaces (the 2D manifold of the other two eigenvectors, grown as stream
surfaces by an advancing front; --set separating_surface.max_edge=CELLS sets their resolution);
written as .vtp and CSV, and a 3D picture (--png: points as spheres coloured by type, red
unstable and blue stable separatrices and surfaces, the grid's outline; --size and the camera
flags below set it).

Input:
  -a, --array ARRAY       vector array (2 or 3 components; the in-plane components are used)
  --slice SLICE           x=I|y=J|z=K, x@X|y@Y|z@Z or plane:ox,oy,oz,nx,ny,nz (docs/slices.md;
                          a 3D array without it is analysed in 3D)
  --mask ARRAY            nonzero = fluid; the file's vtkValidPointMask, NaN/inf and
                          zero-velocity solids are masked without it (no critical points in cells of masked nodes)
  --crop x0,x1,y0,y1      region of interest in world coordinates of the 2D field
  --set key=value         topology parameter (repeatable), e.g. --set cluster_radius=4;
                          keys, units and ranges: filters/topology/TopologyParams.h
  --no-separatrices       do not trace separatrices (nor, in 3D, separating surfaces)
)";

const char* kTopologyHelpTail = R"(Outputs (nothing is written unless everything succeeds):
  -o, --output POINTS.vtp critical points as vertices with point arrays type (string),
                          type_code, index, morse, det, trace, normalized_det, hyperbolic,
                          elliptic, parabolic, index_measured, cluster_size
  --separatrices SEP.vtp  separatrices as polylines (cell arrays origin, outgoing, end,
                          end_point); default: POINTS_separatrices.vtp next to POINTS.vtp
  --surfaces SURF.vtp     3D only: separating surfaces as triangles (cell arrays surface,
                          origin, outgoing; field data surface_end); default:
                          POINTS_surfaces.vtp next to POINTS.vtp
  --csv POINTS.csv        one row per point:
                          x,y,z,type,index,morse,det,trace,hyperbolic,elliptic,parabolic
                          (3D: x,y,z,type,index,morse,det,trace,index_measured,cluster_size,
                          then the real and imaginary parts of the three eigenvalues)
  --png OUT.png           glyphs (one shape and colour per type, legend below) and
                          separatrices over a LIC picture of the flow coloured by speed
                          (in-plane speed |v_xy| for a z layer of a 3D field)
                          3D: spheres, lines and translucent surfaces in a 3D view
Picture:
  --underlay lic|speed    LIC texture over the speed colours (default) or colours only
  --background white|dark the backdrop and text colours (default white)
  --width PX              LIC texture / picture width, [64, 4096] (default 800)
  --title TEXT            title above the picture
  --axes                  x and y axes with round ticks in world coordinates
  --glyph-size PX         glyph diameter, [4, 100] (default 16)
3D picture (a 3D array without --slice; --background, --title, --glyph-size as above):
)";

const char* kTopologyHelpErrors = R"(
Errors (exit code 2): missing file or array (the arrays present are listed), a scalar array,
--crop, --width, --underlay or --axes for a 3D field without --slice, a 3D picture flag or
--surfaces for a planar analysis, a --slice or --crop outside the grid, parameters outside
their range. NaN or infinite values are masked.
)";

struct TopologyArgs {
  fs::path field, vtp, separatricesVtp, surfacesVtp, csv, png;
  bool surfacesGiven = false;  ///< --surfaces was given (an error for a planar analysis)
  View3DParams view;           ///< the 3D picture's size, camera and background
  std::vector<std::string> view3DFlags;        ///< given flags only the 3D picture reads
  std::vector<std::string> planarPictureFlags; ///< given flags only the planar picture reads
  std::string array, slice, mask, crop;
  bool fileArrays = true;  ///< not --ignore-file-arrays
  bool separatrices = true;
  topo::TopologyParams params;
  TopologyPictureParams picture;
  std::optional<std::string> units;  ///< --units; nullopt: the file's or m
  ImageSampling sampling;            ///< --spacing
};

// --set key=value pairs read through TopologyParams' own declaration (ranges, messages).
topo::TopologyParams readTopologySettings(const std::vector<std::string>& settings) {
  scene::json j = scene::json::object();
  topo::TopologyParams params;
  try {
    for (const std::string& s : settings) scene::applyOverride(j, s, "--set");
    scene::readParams(j, params, "");
    topo::validateTopologyParams(params);
  } catch (const scene::SceneError& e) {
    throw UsageError(e.what());
  } catch (const ParamError& e) {
    throw UsageError("--set: key '" + e.key() + "' " + e.what());
  }
  return params;
}

// Picture flags read through TopologyPictureParams' declaration (ranges and messages).
TopologyPictureParams readPictureFlags(const ParsedArgs& a) {
  TopologyPictureParams p;
  scene::json j = scene::json::object();
  refuseUnderlayAsBackground(a, "glyphs");
  if (a.has("--underlay")) j["underlay"] = a.value("--underlay");
  if (a.has("--background")) j["picture"]["background"] = a.value("--background");
  if (a.has("--title")) j["picture"]["title"] = a.value("--title");
  if (a.has("--axes")) j["picture"]["axes"] = true;
  if (a.has("--width")) j["lic"]["width"] = parseNumbers("--width", a.value("--width"), 1)[0];
  if (a.has("--glyph-size"))
    j["glyph_size"] = parseNumbers("--glyph-size", a.value("--glyph-size"), 1)[0];
  try {
    scene::readParams(j, p, "");
  } catch (const ParamError& e) {
    const std::string flag = e.key() == "lic.width"    ? "--width"
                             : e.key() == "glyph_size" ? "--glyph-size"
                             : e.key() == "underlay" ? "--underlay"
                             : e.key() == "picture.background" ? "--background"
                                                       : e.key();
    throw UsageError(flag + " " + e.what());
  }
  if (p.lic.width < 64 || p.lic.width > 4096)
    throw UsageError("--width is " + std::to_string(p.lic.width) + " px; allowed [64, 4096]");
  p.picture.width = p.picture.height = p.lic.width;  // background speed: a square picture
  return p;
}

fs::path besidePoints(const fs::path& vtp, const std::string& suffix) {
  fs::path p = vtp;
  p.replace_filename(vtp.stem().string() + suffix);
  return p;
}

TopologyArgs parseTopologyArgs(std::vector<std::string> args) {
  TopologyArgs r;
  const std::vector<std::string> settings = takeRepeatedOption(args, "--set");
  std::set<std::string> valued = {"--array", "--output", "--slice", "--separatrices", "--surfaces",
                                   "--csv", "--png", "--underlay", "--background", "--width",
                                   "--title", "--glyph-size", "--units", "--mask", "--crop",
                                   "--spacing"};
  std::set<std::string> switches = {"--help", "--no-separatrices", "--axes", kIgnoreFileArraysFlag};
  valued.merge(view3DValuedOptions());
  switches.merge(view3DSwitches());
  const ParsedArgs a = parseArgs(args, valued, switches,
                                 {{"-a", "--array"}, {"-o", "--output"}, {"-h", "--help"}});
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
  if (r.vtp.empty()) throw UsageError("needs -o POINTS.vtp");
  if (r.vtp.extension() != ".vtp") throw UsageError("-o is '" + r.vtp.string() + "'; expected a .vtp file");
  r.separatrices = !a.has("--no-separatrices");
  r.separatricesVtp = a.has("--separatrices") ? fs::path(a.value("--separatrices"))
                                              : besidePoints(r.vtp, "_separatrices.vtp");
  r.surfacesGiven = a.has("--surfaces");
  r.surfacesVtp = r.surfacesGiven ? fs::path(a.value("--surfaces"))
                                  : besidePoints(r.vtp, "_surfaces.vtp");
  r.csv = a.value("--csv");
  r.png = a.value("--png");
  r.units = unitsOption(a);
  r.sampling = samplingOption(a);
  r.params = readTopologySettings(settings);
  r.picture = readPictureFlags(a);
  r.picture.separatrices = r.separatrices;
  r.view = readView3DFlags(a);
  for (const std::string& flag : view3DValuedOptions())
    if (flag != "--background" && a.has(flag)) r.view3DFlags.push_back(flag);
  for (const std::string& flag : view3DSwitches())
    if (a.has(flag)) r.view3DFlags.push_back(flag);
  for (const std::string& flag : {"--width", "--underlay", "--axes"})
    if (a.has(flag)) r.planarPictureFlags.push_back(flag);
  if (r.array.empty()) throwMissingArrayOption(r.field);
  return r;
}

// Every output folder is checked before anything is computed or written.
std::vector<fs::path> outputsOf(const TopologyArgs& r, bool volume) {
  std::vector<fs::path> files{r.vtp};
  if (r.separatrices) files.push_back(r.separatricesVtp);
  if (r.separatrices && volume) files.push_back(r.surfacesVtp);
  if (!r.csv.empty()) files.push_back(r.csv);
  if (!r.png.empty()) files.push_back(r.png);
  for (std::size_t i = 0; i < files.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (fs::weakly_canonical(files[i]) == fs::weakly_canonical(files[k]))
        throw UsageError("output " + files[i].string() + " is given twice");
  return files;
}

template <class Point>
std::string summary(const std::vector<Point>& points,
                    const std::vector<std::pair<std::string, int>>& counts) {
  std::string s = std::to_string(points.size()) + " critical points";
  int indexSum = 0;
  for (const auto& p : points) indexSum += p.index;
  std::string types;
  for (const auto& [name, count] : counts)
    types += (types.empty() ? "" : ", ") + name + " " + std::to_string(count);
  return s + (types.empty() ? "" : " (" + types + ")") + ", index sum " + std::to_string(indexSum);
}

}  // namespace

std::vector<std::string> takeRepeatedOption(std::vector<std::string>& args,
                                            const std::string& option) {
  std::vector<std::string> values, rest;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (i > 0 && args[i] == option) {
      if (i + 1 >= args.size()) throw UsageError(option + " needs a value");
      values.push_back(args[++i]);
    } else if (i > 0 && args[i].rfind(option + "=", 0) == 0) {
      values.push_back(args[i].substr(option.size() + 1));
    } else {
      rest.push_back(args[i]);
    }
  }
  args = rest;
  return values;
}

namespace {

// A 3D array without --slice: the critical points of the 3D field and the 1D separatrices of its
// saddles, .vtp and CSV. Masked nodes are NaN: their tetrahedra hold no zero, lines end there.
int volumeTopology(const TopologyArgs& r, const FlowInput& in, std::ostream& out) {
  const std::string why = in.source + " array '" + r.array + "' is 3D (" +
                          in.velocity.grid.describe() + ") and no --slice was given";
  if (r.view.turntable_frames > 0)
    throw UsageError("--turntable: the topology picture is one view (its legend is drawn below "
                     "it); render turns in ParaView from the .vtp files");
  if (!r.planarPictureFlags.empty())
    throw UsageError(r.planarPictureFlags.front() + ": " + why +
                     "; it is drawn in 3D (--size WxH and the camera flags set the picture)");
  for (const fs::path& f : outputsOf(r, true)) requireWritableFolder(f);

  const VectorField field = in.maskedVelocity();
  const std::vector<topo::CriticalPoint3D> points = topo::findCriticalPoints3D(field, r.params);
  std::vector<topo::Separatrix3D> separatrices;
  std::vector<topo::SeparatingSurface> surfaces;
  if (r.separatrices) {
    separatrices = topo::computeSeparatrices3D(field, points, r.params);
    surfaces = topo::computeSeparatingSurfaces(field, points, r.params);
  }
  RgbaImage image;  // rendered before anything is written: its errors stop everything
  if (!r.png.empty()) {
    Topology3DPictureParams picture;
    picture.view = r.view;
    picture.glyph_size = r.picture.glyph_size;
    picture.title = r.picture.picture.title.empty()
                        ? "Topology of " + r.array + " (" + r.field.filename().string() + ")"
                        : r.picture.picture.title;
    image = renderTopology3DPicture(field.grid, points, separatrices, surfaces, picture);
  }
  out << r.field.string() << ": " << summary(points, countTypes3D(points)) << " (3D)\n";
  writeVtp(topo::criticalPoints3DToPolyData(points), r.vtp);
  out << "wrote " << r.vtp.string() << "\n";
  if (r.separatrices) {
    writeVtp(topo::separatrices3DToPolyData(separatrices), r.separatricesVtp);
    out << "wrote " << r.separatricesVtp.string() << " (" << separatrices.size()
        << " separatrices)\n";
    std::size_t triangles = 0;
    for (const topo::SeparatingSurface& s : surfaces) triangles += s.triangles.size();
    writeVtp(topo::separatingSurfacesToPolyData(surfaces), r.surfacesVtp);
    out << "wrote " << r.surfacesVtp.string() << " (" << surfaces.size()
        << " separating surfaces, " << triangles << " triangles)\n";
  }
  if (!r.csv.empty()) {
    writeTextOutput(r.csv, criticalPoints3DCsv(points));
    out << "wrote " << r.csv.string() << "\n";
  }
  if (!r.png.empty()) {
    writePicture(image, r.png);
    out << "wrote " << r.png.string() << "\n";
  }
  return kSuccess;
}

}  // namespace

int topologyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&,
                    bool) {
  for (const std::string& a : args)
    if (a == "-h" || a == "--help") {
      out << kTopologyHelp << ignoreFileArraysHelpLine() << unitsHelpLine() << spacingHelpLine()
          << kTopologyHelpTail << kView3DHelp << kTopologyHelpErrors;
      return kSuccess;
    }
  const TopologyArgs r = parseTopologyArgs(args);
  const FlowInput in = readFlowInput({r.field, r.array, r.slice, r.units, r.sampling, r.mask,
                                      r.crop, r.slice.empty(), r.fileArrays});
  if (!in.velocity.grid.is2D()) return volumeTopology(r, in, out);
  if (!r.view3DFlags.empty())
    throw UsageError(r.view3DFlags.front() + ": the 3D topology picture's flag, but " +
                     r.field.string() + " array '" + r.array + "' is analysed in a plane");
  if (r.surfacesGiven)
    throw UsageError("--surfaces: separating surfaces exist for 3D fields only; " +
                     r.field.string() + " array '" + r.array + "' is analysed in a plane");
  for (const fs::path& f : outputsOf(r, false)) requireWritableFolder(f);

  // Everything is computed before the first file is written.
  const VectorField field = in.topologyVelocity();
  const std::vector<topo::CriticalPoint> points =
      topo::findCriticalPointsInFluid(field, in.mask, r.params, in.restingWalls());
  std::vector<topo::Separatrix> separatrices;
  if (r.separatrices) separatrices = topo::computeSeparatrices(field, points, r.params);
  TopologyPictureParams picture = r.picture;
  if (picture.picture.title.empty())
    picture.picture.title = "Topology of " + r.array + " (" + r.field.filename().string() + ")";
  RgbaImage image;
  if (!r.png.empty()) {
    if (picture.picture.scalar_bar_title.empty())
      picture.picture.scalar_bar_title = colourScalar(in, picture.blend.color_by).legendTitle;
    picture.picture.axes_unit = in.units;
    // Coloured by the speed the flow has in the plane (defect 7 of issue 15), as its LIC.
    image = renderTopologyPicture(inPlaneVelocity(withMaskedValue(in.velocity, in.mask,
                                                                  Vec3::Zero())),
                                  points, separatrices, picture,
                                  maskedCells(in.velocity.grid, in.mask));
  }

  out << r.field.string() << ": " << summary(points, countTypes(points)) << "\n";
  writeVtp(topo::criticalPointsToPolyData(points), r.vtp);
  out << "wrote " << r.vtp.string() << "\n";
  if (r.separatrices) {
    writeVtp(topo::separatricesToPolyData(separatrices), r.separatricesVtp);
    out << "wrote " << r.separatricesVtp.string() << " (" << separatrices.size()
        << " separatrices)\n";
  }
  if (!r.csv.empty()) {
    writeTextOutput(r.csv, criticalPointsCsv(points));
    out << "wrote " << r.csv.string() << "\n";
  }
  if (!r.png.empty()) {
    writePicture(image, r.png);
    out << "wrote " << r.png.string() << " (" << image.width << " x " << image.height
        << " px, underlay " << choiceName(picture.underlay) << ")\n";
  }
  return kSuccess;
}

}  // namespace fluidviz::app
