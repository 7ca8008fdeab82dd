#include "pipeline/Sweep.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <cstdio>
#include <ostream>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/RunScene.h"
#include "pipeline/SceneReading.h"
#include "fieldviz/render/BifurcationDiagram.h"
#include "fieldviz/scene/SceneFile.h"
#include "filters/topology/Separatrices.h"
#include "filters/topology/VectorFieldTopology.h"
#include "filters/topology/vtk/TopologyPolyData.h"

namespace fluidviz {

namespace fs = std::filesystem;
namespace topo = fluidviz::topology;

double sweepValue(const SweepParams& p, int k) {
  if (p.steps <= 1) return p.from;
  return p.from + (p.to - p.from) * k / (p.steps - 1);
}

namespace {

std::string formatValue(double v) {
  char s[40];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

std::string shortValue(double v) {
  char s[40];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

std::string stepName(int k) {
  char s[16];
  std::snprintf(s, sizeof s, "step_%02d", k);
  return s;
}

void validateSweep(const SweepParams& p) {
  if (p.parameter.empty()) throw ParamError("param", "is empty; give the key path to sweep");
  if (p.steps < 1 || p.steps > 1000)
    throw ParamError("steps", "is " + std::to_string(p.steps) + "; allowed [1, 1000]");
  if (!std::isfinite(p.from) || !std::isfinite(p.to))
    throw ParamError("from", "and --to must be finite numbers");
  topo::validateTopologyParams(p.topology);
  validateTopologyPictureParams(p.picture);
}

// Rollers are solid discs; their nodes carry the rigid rotation.
bool insideRoller(const SceneParams& scene, const Vec3& q) {
  for (const auto& r : scene.lbm.rollers)
    if (std::hypot(q.x() - r.center[0], q.y() - r.center[1]) < r.radius) return true;
  return false;
}

std::string describePoints(const std::vector<topo::CriticalPoint>& points) {
  std::string s;
  for (const auto& [name, count] : countTypes(points))
    s += (s.empty() ? "" : ", ") + std::to_string(count) + " " + name;
  return s.empty() ? "no critical points" : s;
}

// Points, their table and their picture of one finished run.
SweepStep analyzeStep(const SceneParams& scene, const SweepParams& p, int k, double value,
                      const RunSummary& run, const fs::path& stepDir, const fs::path& dir,
                      SweepResult& result) {
  SweepStep step{value, {}, stepDir};
  // As `fluidviz topology` analyses the snapshot: its solid mask, its resting walls.
  const fs::path snapshot = finalSnapshot(run.files);
  const bool withSeparatrices = p.pictures && p.picture.separatrices;
  const topo::TopologyResult analysed = topo::computeTopology(
      readImageData(snapshot), "velocity", p.topology, withSeparatrices, "file " + snapshot.string());
  const VectorField& velocity = analysed.field;
  step.points = analysed.points;
  const fs::path vtp = stepDir / (scene.name + "_critical_points.vtp");
  writeVtp(topo::criticalPointsToPolyData(step.points), vtp);
  writeTextOutput(stepDir / (scene.name + "_critical_points.csv"), criticalPointsCsv(step.points));
  result.files.insert(result.files.end(),
                      {vtp, stepDir / (scene.name + "_critical_points.csv")});
  if (!p.pictures) return step;
  const std::vector<topo::Separatrix>& separatrices = analysed.separatrices;
  TopologyPictureParams picture = p.picture;
  if (picture.picture.title.empty())
    picture.picture.title = scene.name + ": " + p.parameter + " = " + shortValue(value);
  const fs::path png = dir / (scene.name + "_" + stepName(k) + "_topology.png");
  writePicture(renderTopologyPicture(velocity, step.points, separatrices, picture,
                                 [&](const Vec3& q) { return insideRoller(scene, q); }),
           png);
  result.files.push_back(png);
  return step;
}

void writeDiagram(const SweepResult& r, const SweepParams& p, const fs::path& png) {
  std::vector<DiagramPoint> points;
  BifurcationDiagramParams d;
  for (const SweepStep& s : r.steps) {
    d.steps.push_back(s.value);
    for (const topo::CriticalPoint& c : s.points) {
      const auto& g = p.region;
      if (g && (c.position.x() < (*g)[0] || c.position.y() < (*g)[1] ||
                c.position.x() > (*g)[2] || c.position.y() > (*g)[3]))
        continue;
      points.push_back({s.value, c.position.x(), c.position.y(), c.typeName()});
    }
  }
  d.title = r.sceneName + ": critical points against " + p.parameter;
  d.parameter_label = p.parameter;
  d.background = p.picture.picture.background;
  writePicture(renderBifurcationDiagram(points, d), png);
}

}  // namespace

SceneParams sweepScene(const scene::json& sceneJson, const std::string& sceneFile,
                       const SweepParams& p, int k) {
  scene::json j = sceneJson;
  for (const std::string& o : p.overrides) scene::applyOverride(j, o, sceneFile);
  scene::applyOverride(j, p.parameter + "=" + formatValue(sweepValue(p, k)), sceneFile);
  // The sweep analyses the final state only: one snapshot per run.
  scene::applyOverride(j, "output.snapshots=1", sceneFile);
  const SceneParams scene = readSceneParams(j, sceneFile);
  checkScene(scene, sceneFile);
  return scene;
}

fs::path finalSnapshot(const std::vector<fs::path>& runFiles) {
  for (auto it = runFiles.rbegin(); it != runFiles.rend(); ++it)
    if (it->extension() == ".vti") return *it;
  throw FileError("", "the run wrote no snapshot to read its final velocity from");
}

VectorField finalVelocity(const std::vector<fs::path>& runFiles) {
  return readVectorField(finalSnapshot(runFiles), "velocity");
}

std::string bifurcationCsv(const SweepResult& r) {
  std::string csv = std::string("step,parameter,") + kCriticalPointsCsvHeader + "\n";
  for (std::size_t k = 0; k < r.steps.size(); ++k)
    for (const topo::CriticalPoint& c : r.steps[k].points)
      csv += std::to_string(k) + "," + formatValue(r.steps[k].value) + "," + criticalPointCsvRow(c);
  return csv;
}

SweepResult runSweep(const scene::json& sceneJson, const std::string& sceneFile,
                     const SweepParams& p, const fs::path& dir, std::ostream& log,
                     bool interactive) {
  validateSweep(p);
  std::vector<SceneParams> scenes;
  for (int k = 0; k < p.steps; ++k) scenes.push_back(sweepScene(sceneJson, sceneFile, p, k));
  fs::create_directories(dir);
  requireWritableFolder(dir / "probe");
  SweepResult result;
  result.sceneName = scenes.front().name;
  for (int k = 0; k < p.steps; ++k) {
    const double value = sweepValue(p, k);
    const std::string label = "sweep " + std::to_string(k + 1) + "/" + std::to_string(p.steps) +
                              ": " + p.parameter + " = " + shortValue(value);
    log << label << ": running " << scenes[k].name << "\n";
    RunOptions options;
    options.outputDir = dir / stepName(k);
    options.sceneFile = sceneFile;
    options.log = &log;
    options.interactive = interactive;
    // The step folders belong to the sweep: a sweep run again replaces its steps' runs whole
    // (never mixes them), as it rewrites its bifurcation table.
    options.replace = true;
    const RunSummary run = runScene(scenes[k], options);
    result.steps.push_back(
        analyzeStep(scenes[k], p, k, value, run, options.outputDir, dir, result));
    log << label << ": " << describePoints(result.steps.back().points) << "\n";
  }
  const fs::path csv = dir / (result.sceneName + "_bifurcation.csv");
  writeTextOutput(csv, bifurcationCsv(result));
  const fs::path png = dir / (result.sceneName + "_bifurcation.png");
  writeDiagram(result, p, png);
  result.files.insert(result.files.end(), {csv, png});
  return result;
}

}  // namespace fluidviz
