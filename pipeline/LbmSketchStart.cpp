#include "pipeline/LbmSketchStart.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fieldviz/io/FileError.h"
#include "filters/sketch/vtk/StrokeFiles.h"
#include "pipeline/SceneValidation.h"
#include "solvers/lbm/lattice/UnitConversion.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

/// Every point inside the box [0, Lx] x [0, Ly]: a stroke outside it sketches nothing the LBM
/// has, and bounds its length (kMaxSketchStrokePoints).
void requireInsideBox(const sketch::Stroke& s, const lbm::LbmParams& p, const std::string& key) {
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    const Vec3& x = s.points[k];
    if (!(x[0] >= 0.0 && x[0] <= p.domain_size[0] && x[1] >= 0.0 && x[1] <= p.domain_size[1]))
      throw ParamError(key, "point " + std::to_string(k + 1) + " (" + formatNumber(x[0]) + ", " +
                                formatNumber(x[1]) + ") m lies outside the box [0, " +
                                formatNumber(p.domain_size[0]) + "] x [0, " +
                                formatNumber(p.domain_size[1]) + "] m (lbm.domain_size)");
  }
}

/// gvf.boundary_x/y periodic exactly where the LBM's walls are: the sketch then wraps as the
/// flow does.
void requireMatchingBoundaries(const LbmSceneParams& p) {
  const auto check = [](sketch::SketchBoundary b, lbm::WallType wall, const char* axis) {
    const bool periodicWalls = wall == lbm::WallType::periodic;
    if (periodicWalls == (b == sketch::SketchBoundary::periodic)) return;
    throw ParamError(std::string("sketch.gvf.boundary_") + axis,
                     "is " + choiceName(b) + " but lbm.walls." + axis + "_min is " +
                         choiceName(wall) + ": give " + (periodicWalls ? "periodic" : "zero_flux") +
                         " (the sketch wraps where the flow does)");
  };
  check(p.sketch.gvf.boundary_x, p.walls.x_min.type, "x");
  check(p.sketch.gvf.boundary_y, p.walls.y_min.type, "y");
}

}  // namespace

Grid lbmNodeGrid(const lbm::LbmParams& p) {
  const double dx = p.domain_size[0] / p.resolution;
  const long ny = std::lround(p.domain_size[1] / p.domain_size[0] * p.resolution);
  if (ny < 4 || ny > 1'000'000)  // computeLatticeUnits says what to change
    throw ParamError("domain_size", "gives ny = round(Ly / Lx * resolution) = " +
                                        std::to_string(ny) + " nodes across y; allowed 4 to 1e6");
  Grid g;
  g.dims = {p.resolution, static_cast<int>(ny), 1};
  g.origin = {0.5 * dx, 0.5 * dx, 0.0};
  g.spacing = {dx, dx, dx};
  return g;
}

std::vector<sketch::Stroke> sceneStrokes(const SceneParams& scene) {
  const LbmSketchParams& s = scene.lbm.sketch;
  std::vector<sketch::Stroke> strokes;
  for (std::size_t i = 0; i < s.strokes.size(); ++i) {
    sketch::Stroke stroke{{}, s.strokes[i].speed};
    for (const auto& p : s.strokes[i].points) stroke.points.emplace_back(p[0], p[1], 0.0);
    requireInsideBox(stroke, scene.lbm, "sketch.strokes[" + std::to_string(i) + "].points");
    strokes.push_back(std::move(stroke));
  }
  if (!s.file.empty()) {
    const fs::path file = fs::path(s.file).is_absolute() ? fs::path(s.file) : scene.folder / s.file;
    try {
      for (sketch::Stroke& stroke : sketch::readStrokeFile(file)) {
        requireInsideBox(stroke, scene.lbm, "sketch.file");
        strokes.push_back(std::move(stroke));
      }
    } catch (const FileError& e) {
      throw ParamError("sketch.file", e.what());
    } catch (const ParamError& e) {
      throw ParamError(e.key(), file.string() + ": stroke " +
                                    std::to_string(strokes.size() - s.strokes.size() + 1) + ": " +
                                    e.what());
    }
  }
  if (strokes.empty())
    throw ParamError("sketch", "has no strokes: lbm.initial_flow is sketch; give "
                               "lbm.sketch.strokes or lbm.sketch.file");
  return strokes;
}

LbmStart lbmStartOf(const SceneParams& scene) {
  LbmStart start{scene.lbm, {}, {}};
  if (scene.lbm.initial_flow != lbm::InitialFlow::sketch) return start;
  lbm::validateLbmParams(scene.lbm);  // ranges and the rules of the box first
  withKeyPrefix("sketch.", [&] { sketch::validateSketchParams(scene.lbm.sketch); });
  requireMatchingBoundaries(scene.lbm);
  const Grid grid = lbmNodeGrid(scene.lbm);
  if (scene.lbm.sketch.gvf.solver == sketch::GvfSolver::direct &&
      static_cast<long long>(grid.nodeCount()) > kMaxDirectSketchNodes)
    throw ParamError("sketch.gvf.solver",
                     "is direct, which factorises one matrix of all " +
                         std::to_string(grid.nodeCount()) + " nodes; allowed up to " +
                         std::to_string(kMaxDirectSketchNodes) +
                         ": lower lbm.resolution or use solver explicit");
  const std::vector<sketch::Stroke> strokes = sceneStrokes(scene);
  start.strokeCount = strokes.size();
  double length = 0.0;
  for (const sketch::Stroke& s : strokes) length += sketch::strokeLength(s);
  const double spacing = scene.lbm.sketch.resample_spacing * grid.spacing[0];
  if (length / spacing > kMaxSketchStrokePoints)
    throw ParamError("sketch.resample_spacing",
                     "resamples strokes " + formatNumber(length) + " m long in all into " +
                         formatNumber(length / spacing, 3) + " points, more than " +
                         formatNumber(kMaxSketchStrokePoints, 3) +
                         ": draw shorter strokes or raise resample_spacing");
  try {
    start.sketched = sketch::sketchFlow(strokes, grid, scene.lbm.sketch);
  } catch (const ParamError& e) {  // the explicit GVF's step limits and iteration budget
    throw ParamError("sketch.gvf." + e.key(), e.what());
  } catch (const std::invalid_argument& e) {  // "stroke k: fewer than two distinct points"
    throw ParamError("sketch", std::string(e.what()) + " (strokes counted over lbm.sketch.strokes, "
                               "then those of lbm.sketch.file)");
  }
  std::vector<Vec3>& u = start.velocity;
  u = start.sketched.velocity.values;
  double largest = 0.0;
  for (const Vec3& v : u) largest = std::max(largest, v.norm());
  if (!(largest > 0.0) || !std::isfinite(largest))
    throw ParamError("sketch", "gives a field at rest everywhere (largest speed " +
                                   formatNumber(largest) + " m/s): give a stroke a speed");
  if (scene.lbm.initial_speed > 0.0) {
    const double scale = scene.lbm.initial_speed / largest;
    for (Vec3& v : u) v *= scale;
    start.sketched.velocity.values = u;
    largest = scene.lbm.initial_speed;
  }
  start.params.initial_speed = largest;
  return start;
}

}  // namespace fluidviz

namespace fluidviz {

std::string describeSketchStart(const LbmStart& start, const SceneParams& scene) {
  if (start.velocity.empty()) return "";
  const LbmSketchParams& p = scene.lbm.sketch;
  std::string text = "initial flow sketched: " + std::to_string(start.strokeCount) + " stroke" +
                     (start.strokeCount == 1 ? "" : "s") + ", GVF " + choiceName(p.gvf.solver) +
                     " (residual " + formatNumber(start.sketched.gvfResidual, 3);
  if (start.sketched.gvfIterations > 0)
    text += " after " + std::to_string(start.sketched.gvfIterations) + " iterations";
  text += ")";
  if (p.divergence_free)
    text += ", divergence-free: max |div u| " + formatNumber(start.sketched.divergenceBefore, 3) +
            " -> " + formatNumber(start.sketched.divergenceAfter, 3) + " 1/s";
  return text + "; largest speed " + formatNumber(start.params.initial_speed, 4) + " m/s (U_ref)";
}

}  // namespace fluidviz
