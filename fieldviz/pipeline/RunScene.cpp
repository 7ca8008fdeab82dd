#include "fieldviz/pipeline/RunScene.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/PvdSeries.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "fieldviz/pipeline/Progress.h"
#include "fieldviz/scene/SceneFile.h"
#include "solvers/lbm/LbmSolverD2Q9.h"

namespace fluidviz {

namespace fs = std::filesystem;

void validateScene(const SceneParams& scene) {
  if (scene.name.empty() ||
      scene.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") !=
          std::string::npos)
    throw ParamError("name", "is \"" + scene.name +
                                 "\"; allowed: letters, digits, '_' and '-' (it prefixes file names)");
  std::vector<std::string> files;
  for (std::size_t i = 0; i < scene.output.images.size(); ++i) {
    const auto& img = scene.output.images[i];
    const std::string file = img.file.empty() ? scene.name + "_" + img.field + ".png" : img.file;
    if (file.find('/') != std::string::npos || fs::path(file).extension() != ".png")
      throw ParamError("output.images[" + std::to_string(i) + "].file",
                       "is \"" + file + "\"; allowed: a plain file name ending in .png");
    if (std::find(files.begin(), files.end(), file) != files.end())
      throw ParamError("output.images[" + std::to_string(i) + "].file",
                       "\"" + file + "\" is written by an earlier image too; give each a file name");
    files.push_back(file);
    try {
      validateFieldImageParams(img);
    } catch (const ParamError& e) {
      throw ParamError("output.images[" + std::to_string(i) + "]." + e.key(), e.what());
    }
  }
}

namespace {
std::string describeUnits(const lbm::LatticeUnits& u);
}  // namespace

std::string checkScene(const SceneParams& scene, const std::string& sceneFile) {
  std::string prefix;
  try {
    validateScene(scene);
    prefix = "lbm.";
    return describeUnits(lbm::computeLatticeUnits(scene.lbm));
  } catch (const ParamError& e) {
    throw scene::SceneError(sceneFile, prefix + e.key(), e.what());
  }
}

namespace {

std::string imageFileName(const SceneParams& scene, const ImageOutput& img) {
  return img.file.empty() ? scene.name + "_" + img.field + ".png" : img.file;
}

ScalarField fieldForImage(const FieldSet& fields, const std::string& name) {
  if (const ScalarField* s = fields.findScalar(name)) return *s;
  const VectorField* velocity = fields.findVector("velocity");
  const int component = name == "velocity_x" ? 0 : 1;
  ScalarField s{name, velocity->grid, std::vector<double>(velocity->values.size())};
  for (std::size_t n = 0; n < s.values.size(); ++n) s.values[n] = velocity->values[n][component];
  return s;
}

// Largest change of the velocity between two checks, relative to the largest speed.
double relativeVelocityChange(const std::vector<Vec3>& before, const std::vector<Vec3>& after) {
  double change = 0.0, scale = 0.0;
  for (std::size_t n = 0; n < after.size(); ++n) {
    change = std::max(change, (after[n] - before[n]).norm());
    scale = std::max(scale, after[n].norm());
  }
  return scale > 0 ? change / scale : change;
}

std::string describeUnits(const lbm::LatticeUnits& u) {
  std::ostringstream s;
  s.precision(4);
  s << "lattice " << u.nx << " x " << u.ny << " nodes, dx = " << u.dx << " m, dt = " << u.dt
    << " s\n"
    << "tau = " << u.tau << ", lattice velocity = " << u.latticeVelocity << ", Mach = " << u.mach
    << ", lattice viscosity = " << u.latticeViscosity << ", Reynolds = " << u.reynolds;
  return s.str();
}

class SnapshotWriter {
 public:
  SnapshotWriter(const fs::path& dir, const std::string& name, RunSummary& summary)
      : dir_(dir), name_(name), series_(dir / (name + ".pvd")), summary_(summary) {}

  void write(const FieldSet& fields, double time, int index) {
    fs::create_directories(dir_ / name_);
    char file[64];
    std::snprintf(file, sizeof file, "%s_%04d.vti", name_.c_str(), index);
    const fs::path relative = fs::path(name_) / file;
    writeVti(fields, dir_ / relative);
    series_.add(time, relative.string());
    summary_.files.push_back(dir_ / relative);
  }

 private:
  fs::path dir_;
  std::string name_;
  PvdSeries series_;
  RunSummary& summary_;
};

}  // namespace

RunSummary runScene(const SceneParams& scene, const RunOptions& options) {
  std::ostream& log = options.log ? *options.log : std::cerr;
  // Everything that can be checked is checked before the first file is written.
  log << scene.name << ": " << checkScene(scene, options.sceneFile) << "\n";
  lbm::LbmSolverD2Q9 solver(scene.lbm);
  const lbm::LatticeUnits& units = solver.units();

  const long totalSteps = std::min<long>(scene.lbm.max_steps,
                                         std::lround(std::ceil(scene.lbm.end_time / units.dt - 1e-9)));
  const int snapshots = scene.output.snapshots;
  RunSummary summary;
  fs::create_directories(options.outputDir);
  SnapshotWriter writer(options.outputDir, scene.name, summary);

  ProgressReporter progress(log, options.interactive, scene.name);
  std::vector<Vec3> lastVelocity = solver.fields().findVector("velocity")->values;
  int written = 0;
  long step = 0, sinceCheck = 0;
  double change = NAN;
  while (step < totalSteps && !summary.steady) {
    const long nextSnapshot =
        snapshots > 0 ? (totalSteps * (written + 1) + snapshots - 1) / snapshots : totalSteps;
    const long chunk = std::min<long>(
        {scene.lbm.check_interval - sinceCheck, nextSnapshot - step, totalSteps - step});
    solver.step(static_cast<int>(chunk));
    step += chunk;
    sinceCheck += chunk;
    solver.checkStability();
    if (sinceCheck >= scene.lbm.check_interval) sinceCheck = 0;
    if (scene.lbm.steady_tolerance > 0 && sinceCheck == 0) {
      const FieldSet now = solver.fields();
      change = relativeVelocityChange(lastVelocity, now.findVector("velocity")->values);
      lastVelocity = now.findVector("velocity")->values;
      summary.steady = change < scene.lbm.steady_tolerance;
    }
    const bool snapshotDue = snapshots > 0 && (step >= nextSnapshot || summary.steady || step == totalSteps);
    if (snapshotDue) writer.write(solver.fields(), solver.time(), ++written);
    std::ostringstream detail;
    detail.precision(4);
    detail << "t = " << solver.time() << " s, step " << step;
    if (std::isfinite(change)) detail << ", change " << change;
    progress.update(static_cast<double>(step) / totalSteps, detail.str());
  }
  summary.steps = step;
  summary.time = solver.time();
  std::ostringstream end;
  end.precision(5);
  end << (summary.steady ? "steady state reached at t = " : "reached t = ") << summary.time
      << " s after " << step << " steps";
  progress.finish(end.str());

  const FieldSet final = solver.fields();
  for (const ImageOutput& img : scene.output.images) {
    const fs::path png = options.outputDir / imageFileName(scene, img);
    FieldImageParams params = img;
    if (params.title.empty()) params.title = scene.name + ": " + img.field;
    writeFieldImagePng(fieldForImage(final, img.field), params, png);
    summary.files.push_back(png);
  }
  writeTextOutput(options.outputDir / (scene.name + "_scene.json"),
                      scene::writeParams(scene).dump(2) + "\n");
  for (const auto& f : summary.files) log << "wrote " << f.string() << "\n";
  return summary;
}

}  // namespace fluidviz
