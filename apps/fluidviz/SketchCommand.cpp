// fluidviz sketch: strokes drawn by a user (CSV) become a velocity field on a grid (issue 20;
// filters/sketch: projection, Gaussian smoothing, Gradient Vector Flow), written as .vti, with
// an optional LIC picture with the field's critical points, which are listed too.
#include "apps/fluidviz/SketchCommand.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/KeyOptions.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/PictureText.h"
#include "pipeline/TopologyOutputs.h"
#include "filters/sketch/SketchedFlow.h"
#include "filters/sketch/vtk/StrokeFiles.h"
#include "filters/topology/VectorFieldTopology.h"

namespace fluidviz::app {

namespace {

namespace fs = std::filesystem;

const char* kSketchAbout = R"(fluidviz sketch STROKES.csv|.vtp|.svg -o FIELD.vti [--png PICTURE.png] [options]

Sketched flows (Judice & Giraldi 2012): every stroke is read as a streamline of the flow, with a
speed. The strokes are resampled and smoothed, their velocities (tangent x speed) projected onto
the grid and smoothed by a Gaussian, and Gradient Vector Flow (Xu & Prince 1998) extends them over
the whole grid; optionally the result is made divergence-free.

STROKES.csv: '#' comment lines, a header naming the columns stroke, x, y, speed (any order, other
columns ignored), then one point per line: the stroke's number (a whole number; the points of a
stroke on consecutive lines, in drawing order), the point (m) and the stroke's speed (m/s; the
same on every line of a stroke; negative reverses the flow).

STROKES.vtp: polylines, e.g. drawn in ParaView: every line cell is one stroke, its points in
drawing order (z ignored). Its speed (m/s) is the cell-data array "speed", else the point-data
array "speed" (the same at every point of a line), else 1 m/s.

STROKES.svg: every <path>'s d attribute; each subpath (M) is a stroke. Commands M, L, H, V, C
(cubic Beziers, flattened into 16 segments) and Z, absolute and relative; others and transform
attributes are refused. 1 user unit = 1 m; y is flipped within the <svg> viewBox (required).
Speed (m/s): the path's data-speed attribute, else 1 m/s.

FIELD.vti holds velocity, speed, projected_velocity (the strokes' velocity on the grid) and
gvf_weight. The critical points of the field are listed (type, position) and drawn as
glyphs on the picture.

Errors (exit code 2): a file that is not a readable .csv, .vtp or .svg, a missing column or array, a
value that is not a finite number, a stroke number that is not whole or comes back after another
stroke, a speed that changes within a stroke, a stroke without two distinct points, options
outside their range; nothing is written then.)";

// The direct GVF solve factorises one sparse matrix of NX x NY unknowns: 1024^2 needs ~1 GB.
constexpr int kMaxNodesPerSide = 1024;

struct SketchArgs {
  std::vector<std::string> inputs;
  fs::path vti, png;
  std::string nodes, domain;
  sketch::SketchParams params;
};

struct SketchCommandLine {
  CLI::App app{kSketchAbout, "fluidviz sketch"};
  SketchArgs r;
  KeyOptions keys;

  SketchCommandLine() {
    app.add_option("STROKES", r.inputs, "the strokes (.csv, .vtp or .svg)")->group("Input");
    app.add_option("--nodes", r.nodes,
                   "grid nodes along x and y (default 128 along the longer side of the domain, "
                   "square cells); at most " +
                       std::to_string(kMaxNodesPerSide) + " each")
        ->type_name("NX,NY")
        ->group("Grid");
    app.add_option("--domain", r.domain,
                   "the grid's extent (m); default: the strokes' bounding box grown by 10 % of "
                   "its longer side on every side. A periodic axis spans [min, max) (the node "
                   "at max would be the one at min)")
        ->type_name("XMIN,XMAX,YMIN,YMAX")
        ->group("Grid");
    keys.add<sketch::SketchParams>(app,
                                   {{"resample_spacing"},
                                    {"stroke_smoothing"},
                                    {"sigma"},
                                    {"weight"},
                                    {"divergence_free"},
                                    {"gvf.solver", "--solver"},
                                    {"gvf.mu", "--mu"},
                                    {"gvf.time_step", "--time-step"},
                                    {"gvf.max_iterations", "--max-iterations"},
                                    {"gvf.tolerance", "--tolerance"},
                                    {"gvf.boundary_x", "--boundary-x"},
                                    {"gvf.boundary_y", "--boundary-y"}},
                                   "Sketch");
    app.add_option("-o,--output", r.vti, "the field (.vti, written atomically)")->group("Outputs");
    app.add_option("--png", r.png,
                   "also a LIC picture of the field coloured by speed, with its critical "
                   "points as glyphs")
        ->group("Outputs");
  }

  SketchArgs read() {
    if (r.inputs.size() != 1)
      throw UsageError("needs exactly one strokes file (.csv, .vtp or .svg), got " +
                       std::to_string(r.inputs.size()));
    if (r.vti.empty()) throw UsageError("needs -o FIELD.vti");
    if (r.vti.extension() != ".vti")
      throw UsageError("-o " + r.vti.string() + ": must end in .vti");
    keys.read(r.params);
    keys.checkWithFlagNames([&] { sketch::validateSketchParams(r.params); });
    return r;
  }
};

struct Box {
  double x0, x1, y0, y1;
};

Box domainOf(const std::vector<sketch::Stroke>& strokes, const std::string& option) {
  if (!option.empty()) {
    const std::vector<double> d = parseNumbers("--domain", option, 4);
    if (!(d[1] > d[0]) || !(d[3] > d[2]))
      throw UsageError("--domain " + option + ": needs XMIN < XMAX and YMIN < YMAX");
    return {d[0], d[1], d[2], d[3]};
  }
  Box b{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const sketch::Stroke& s : strokes)
    for (const Vec3& p : s.points) {
      b.x0 = std::min(b.x0, p[0]), b.x1 = std::max(b.x1, p[0]);
      b.y0 = std::min(b.y0, p[1]), b.y1 = std::max(b.y1, p[1]);
    }
  const double pad = 0.1 * std::max(b.x1 - b.x0, b.y1 - b.y0);
  if (!(pad > 0.0)) throw UsageError("the strokes are a single point; give --domain");
  return {b.x0 - pad, b.x1 + pad, b.y0 - pad, b.y1 + pad};
}

Grid gridOf(const Box& box, const std::string& nodes, const sketch::GvfParams& gvf) {
  const double lx = box.x1 - box.x0, ly = box.y1 - box.y0;
  int nx, ny;
  if (!nodes.empty()) {
    const std::vector<double> n = parseNumbers("--nodes", nodes, 2);
    for (double v : n)
      if (v != std::floor(v) || v < 3 || v > kMaxNodesPerSide)
        throw UsageError("--nodes " + nodes + ": each must be a whole number from 3 to " +
                         std::to_string(kMaxNodesPerSide));
    nx = static_cast<int>(n[0]), ny = static_cast<int>(n[1]);
  } else {
    const double h = std::max(lx, ly) / 127.0;
    nx = std::clamp(static_cast<int>(std::lround(lx / h)) + 1, 3, kMaxNodesPerSide);
    ny = std::clamp(static_cast<int>(std::lround(ly / h)) + 1, 3, kMaxNodesPerSide);
  }
  // A periodic axis has no node at its max: that node is the one at min.
  auto spacing = [](double length, int n, sketch::SketchBoundary b) {
    return length / (b == sketch::SketchBoundary::periodic ? n : n - 1);
  };
  Grid g;
  g.dims = {nx, ny, 1};
  g.origin = {box.x0, box.y0, 0.0};
  g.spacing = {spacing(lx, nx, gvf.boundary_x), spacing(ly, ny, gvf.boundary_y), 1.0};
  return g;
}

void writeField(const sketch::SketchedFlow& f, const fs::path& vti) {
  FieldSet set;
  set.grid = f.velocity.grid;
  set.add(f.velocity);
  set.add(magnitude(f.velocity, "speed"));
  set.add(f.projected);
  set.add(ScalarField{"gvf_weight", set.grid, f.weight});
  writeVti(set, vti);
}

/// The LIC picture coloured by speed with the critical points as glyphs (legend below), as
/// fluidviz topology draws them.
void writeTopologyPicture(const sketch::SketchedFlow& f, std::size_t strokeCount,
                          const std::vector<topology::CriticalPoint>& points,
                          const fs::path& png) {
  TopologyPictureParams params;
  params.separatrices = false;
  params.lic.width = std::clamp(4 * f.velocity.grid.dims[0], 400, 1200);
  params.picture.title = "Sketched flow: " + std::to_string(strokeCount) + " stroke" +
                         (strokeCount == 1 ? "" : "s") + ", GVF";
  params.picture.scalar_bar_title = legendTitleOf("speed");  // "speed (m/s)"
  writePicture(renderTopologyPicture(f.velocity, points, {}, params), png);
}

}  // namespace

int sketchCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&, bool) {
  SketchCommandLine commandLine;
  if (!parseCommandLine(commandLine.app, args, out)) return kSuccess;
  const SketchArgs r = commandLine.read();
  const fs::path file = r.inputs[0];
  if (!r.png.empty()) requirePictureFile(r.png);
  requireWritableFolder(r.vti);
  if (!r.png.empty()) requireWritableFolder(r.png);
  const std::vector<sketch::Stroke> strokes = sketch::readStrokeFile(file);
  const Grid grid = gridOf(domainOf(strokes, r.domain), r.nodes, r.params.gvf);
  sketch::SketchedFlow f;
  try {
    f = sketch::sketchFlow(strokes, grid, r.params);
  } catch (const ParamError& e) {  // the GVF step limits and iteration budget (gvf.*)
    throw UsageError(commandLine.keys.flagForKey("gvf." + e.key()) + " " + e.what());
  } catch (const std::invalid_argument& e) {
    throw FileError(file, file.string() + ": " + e.what());
  }
  writeField(f, r.vti);
  out << "wrote " << r.vti.string() << " (" << grid.dims[0] << " x " << grid.dims[1]
      << " nodes, spacing " << formatNumber(grid.spacing[0]) << " x "
      << formatNumber(grid.spacing[1]) << " m; " << strokes.size() << " strokes; GVF "
      << choiceName(r.params.gvf.solver) << ", residual " << formatNumber(f.gvfResidual, 3);
  if (f.gvfIterations > 0) out << " after " << f.gvfIterations << " iterations";
  if (r.params.divergence_free)
    out << "; max |div| " << formatNumber(f.divergenceBefore, 3) << " -> "
        << formatNumber(f.divergenceAfter, 3) << " 1/s";
  out << ")\n";
  const std::vector<topology::CriticalPoint> points =
      topology::findCriticalPoints(f.velocity, topology::TopologyParams{});
  if (!r.png.empty()) {
    writeTopologyPicture(f, strokes.size(), points, r.png);
    out << "wrote " << r.png.string() << "\n";
  }
  for (const topology::CriticalPoint& p : points)
    out << "critical point: " << p.typeName() << " at (" << formatNumber(p.position[0]) << ", "
        << formatNumber(p.position[1]) << "), index " << p.index << "\n";
  return kSuccess;
}

}  // namespace fluidviz::app
