#include "pipeline/RunScene.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/PvdSeries.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/Checkpoint.h"
#include "pipeline/FlowFields.h"
#include "pipeline/FlowOutputs.h"
#include "pipeline/Progress.h"
#include "pipeline/RunSphScene.h"
#include "pipeline/SphGridOutputs.h"
#include "fieldviz/scene/SceneFile.h"
#include "filters/topology/StreamFunction.h"
#include "solvers/lbm/LbmSolver.h"
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
    const std::string file = img.file.empty() ? scene.name + "_" + choiceName(img.field) + ".png" : img.file;
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
  validateFlowOutputs(scene);  // output.lic and output.streamlines
  validateSphGridOutputs(scene);  // output.grids, free_surface, views (solver sph only)
}

namespace {
std::string describeUnits(const lbm::LatticeUnits& u);

// A picture of a 3D LBM scene is one z layer: output.images[].slice_index in [0, nz - 1].
void checkLbmImageSlices(const SceneParams& scene, const lbm::LatticeUnits& units) {
  const int nz = lbm::is3D(scene.lbm) ? units.nz : 1;
  for (std::size_t i = 0; i < scene.output.images.size(); ++i) {
    const int k = scene.output.images[i].slice_index;
    if (nz > 1 && (k < 0 || k >= nz))
      throw ParamError("output.images[" + std::to_string(i) + "].slice_index",
                       "is " + std::to_string(k) + "; a 3D scene (lattice D3Q19, " +
                           std::to_string(nz) + " nodes along z) draws one z layer: give slice_index "
                           "in [0, " + std::to_string(nz - 1) + "]");
  }
}
}  // namespace

std::string checkScene(const SceneParams& scene, const std::string& sceneFile) {
  if (scene.solver == SolverKind::sph) return checkSphScene(scene, sceneFile);
  std::string prefix;
  try {
    validateScene(scene);
    prefix = "lbm.";
    const lbm::LatticeUnits units = lbm::computeLatticeUnits(scene.lbm);
    prefix.clear();
    checkLbmImageSlices(scene, units);  // 3D scenes draw z slices
    return describeUnits(units);
  } catch (const ParamError& e) {
    throw scene::SceneError(sceneFile, prefix + e.key(), e.what());
  }
}

namespace {

// The effective scene of an LBM run without the other solver's defaults, so that it reads back.
scene::json lbmOnly(scene::json effective) {
  effective.erase("sph");
  return effective;
}

std::string imageFileName(const SceneParams& scene, const ImageOutput& img) {
  return img.file.empty() ? scene.name + "_" + choiceName(img.field) + ".png" : img.file;
}

ScalarField fieldForImage(const FieldSet& fields, const std::string& name) {
  if (const ScalarField* s = fields.findScalar(name)) return *s;
  const VectorField* velocity = fields.findVector("velocity");
  const int component = name == "velocity_x" ? 0 : (name == "velocity_z" ? 2 : 1);
  ScalarField s{name, velocity->grid, std::vector<double>(velocity->values.size())};
  for (std::size_t n = 0; n < s.values.size(); ++n) s.values[n] = velocity->values[n][component];
  return s;
}

// Fields an LBM picture may ask for, computed only then: vorticity and stream function (of the
// 2D field, or of the picture's z layer of a 3D field; the result is 2D, so the picture's
// slice_index is cleared), else fieldForImage.
ScalarField lbmImageField(const FieldSet& fields, const std::string& name, FieldImageParams& picture) {
  if (name != "vorticity" && name != "stream_function") return fieldForImage(fields, name);
  const VectorField& velocity = *fields.findVector("velocity");
  const int k = velocity.grid.is2D() ? 0 : picture.slice_index;
  picture.slice_index = -1;
  if (name == "vorticity") {
    ScalarField w = vorticity(velocity.grid.is2D() ? velocity : sliceZ(velocity, k));
    useSymmetricRange(w, picture);
    return w;
  }
  topology::TopologyParams params;
  params.slice_index = k;
  ScalarField psi = topology::computeStreamFunction(velocity, params).psi;
  psi.name = "stream_function";
  return psi;
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
  s << "lattice " << u.nx << " x " << u.ny << (u.nz > 1 ? " x " + std::to_string(u.nz) : "")
    << " nodes, dx = " << u.dx << " m, dt = " << u.dt << " s\n"
    << "tau = " << u.tau << (u.tauMinus != u.tau ? " (TRT tau- = " + std::to_string(u.tauMinus) + ")" : "")
    << ", lattice velocity = " << u.latticeVelocity << ", Mach = " << u.mach
    << ", lattice viscosity = " << u.latticeViscosity << ", Reynolds = " << u.reynolds;
  return s.str();
}

class SnapshotWriter {
 public:
  /// `earlier`: the snapshots of a resumed run (listed again, and in the summary).
  SnapshotWriter(const fs::path& dir, const std::string& name, RunSummary& summary,
                 std::vector<PvdSeries::Entry> earlier = {})
      : dir_(dir), name_(name), series_(dir / (name + ".pvd"), std::move(earlier)),
        summary_(summary) {
    for (const PvdSeries::Entry& e : series_.entries()) summary_.files.push_back(dir_ / e.file);
  }
  const std::vector<PvdSeries::Entry>& entries() const { return series_.entries(); }

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

// The run loop's own variables, saved in checkpoints next to the solver's state.
struct LbmLoopState {
  int written = 0;        ///< snapshots written
  long sinceCheck = 0;    ///< steps since the last stability/steady check
  double change = NAN;    ///< last relative velocity change (progress lines)
  bool steady = false;
  std::vector<Vec3> lastVelocity;  ///< velocity at the last check (steady_tolerance > 0)

  void save(StateWriter& w) const {
    w.put<std::int32_t>(written);
    w.put<std::int64_t>(sinceCheck);
    w.put<double>(change);
    w.put<std::uint8_t>(steady ? 1 : 0);
    w.putVec3s(lastVelocity);
  }
  void restore(StateReader& r) {
    written = r.get<std::int32_t>();
    sinceCheck = r.get<std::int64_t>();
    change = r.get<double>();
    steady = r.get<std::uint8_t>() != 0;
    r.getVec3s(lastVelocity);
  }
};

// Restores loop and solver from a checkpoint that openCheckpointForResume accepted.
void restoreLbmRun(LoadedCheckpoint& ckpt, const fs::path& file, LbmLoopState& loop,
                   lbm::LbmSolver& solver, std::size_t nodes, bool steadyCheck) {
  try {
    loop.restore(ckpt.state);
    if (loop.lastVelocity.size() != (steadyCheck ? nodes : 0))
      throw StateFormatError("the steady-state reference holds " +
                             std::to_string(loop.lastVelocity.size()) + " nodes");
    solver.restoreState(ckpt.state);
    if (ckpt.state.remaining() != 0) throw StateFormatError("bytes are left over after the state");
  } catch (const StateFormatError& e) {
    throw FileError(file, "checkpoint " + file.string() + " does not fit this scene's solver: " +
                              e.what() + "; start the run again without --resume");
  }
}

}  // namespace

RunSummary runScene(const SceneParams& scene, const RunOptions& options) {
  if (scene.solver == SolverKind::sph) return runSphScene(scene, options);
  std::ostream& log = options.log ? *options.log : std::cerr;
  // Everything that can be checked is checked before the first file is written.
  log << scene.name << ": " << checkScene(scene, options.sceneFile) << "\n";
  const std::unique_ptr<lbm::LbmSolver> lbmSolver = lbm::createLbmSolver(scene.lbm);  // lattice, precision
  lbm::LbmSolver& solver = *lbmSolver;
  const lbm::LatticeUnits& units = solver.units();

  const long totalSteps = std::min<long>(scene.lbm.max_steps,
                                         std::lround(std::ceil(scene.lbm.end_time / units.dt - 1e-9)));
  const int snapshots = scene.output.snapshots;
  const bool steadyCheck = scene.lbm.steady_tolerance > 0;
  RunSummary summary;
  std::optional<LoadedCheckpoint> resumed;
  if (options.resume) resumed = openCheckpointForResume(scene, options);
  fs::create_directories(options.outputDir);
  if (!resumed) prepareFreshOutput(scene, options);
  SnapshotWriter writer(options.outputDir, scene.name, summary,
                        resumed ? resumed->header.snapshots : std::vector<PvdSeries::Entry>{});

  LbmLoopState loop;
  auto& [written, sinceCheck, change, steady, lastVelocity] = loop;
  if (steadyCheck) lastVelocity = solver.fields().findVector("velocity")->values;
  RunCheckpointer checkpoints(scene, options);
  if (resumed) {
    restoreLbmRun(*resumed, checkpoints.path(), loop, solver, solver.grid().nodeCount(),
                  steadyCheck);
    summary.steady = steady;
    log << scene.name << ": resuming from " << checkpoints.path().string() << " at t = "
        << solver.time() << " s, step " << solver.stepCount() << " (" << written
        << " snapshots written)\n";
  }
  long step = static_cast<long>(solver.stepCount());
  const std::string sceneJson = checkpointSceneJson(scene);
  auto header = [&] {
    return CheckpointHeader{"lbm", sceneJson, step, solver.time(), writer.entries()};
  };
  auto saveState = [&](StateWriter& w) {
    loop.steady = summary.steady;  // not the binding: clang < 16 cannot capture bindings
    loop.save(w);
    solver.saveState(w);
  };
  // Steps between polls of a stop request: a few million node updates, well under a second.
  const long sliceSteps = std::max<long>(1, 4'000'000 / std::max<long>(1, solver.fluidNodeCount()));

  ProgressReporter progress(log, options.interactive, scene.name);
  while (step < totalSteps && !summary.steady) {
    const long nextSnapshot =
        snapshots > 0 ? (totalSteps * (written + 1) + snapshots - 1) / snapshots : totalSteps;
    const long chunk = std::min<long>(
        {scene.lbm.check_interval - sinceCheck, nextSnapshot - step, totalSteps - step});
    for (long done = 0; done < chunk;) {  // results do not depend on how steps are grouped
      const long n = std::min(sliceSteps, chunk - done);
      solver.step(static_cast<int>(n));
      done += n;
      step += n;
      sinceCheck += n;
      if (const int signal = done < chunk ? checkpoints.stopSignal(step) : 0)
        checkpoints.stop(signal, header(), saveState);
    }
    solver.checkStability();
    if (sinceCheck >= scene.lbm.check_interval) sinceCheck = 0;
    if (steadyCheck && sinceCheck == 0) {
      const FieldSet now = solver.fields();
      change = relativeVelocityChange(lastVelocity, now.findVector("velocity")->values);
      lastVelocity = now.findVector("velocity")->values;
      summary.steady = change < scene.lbm.steady_tolerance;
    }
    const bool snapshotDue = snapshots > 0 && (step >= nextSnapshot || summary.steady || step == totalSteps);
    if (snapshotDue) writer.write(solver.fields(), solver.time(), ++written);
    if (snapshotDue ? checkpoints.atSnapshots() : checkpoints.intervalDue())
      checkpoints.write(header(), saveState);
    std::ostringstream detail;
    detail.precision(4);
    detail << "t = " << solver.time() << " s, step " << step;
    if (std::isfinite(change)) detail << ", change " << change;
    progress.update(static_cast<double>(step) / totalSteps, detail.str());
    if (const int signal = checkpoints.stopSignal(step))
      checkpoints.stop(signal, header(), saveState);
  }
  summary.steps = step;
  summary.time = solver.time();
  std::ostringstream end;
  end.precision(5);
  end << (summary.steady ? "steady state reached at t = " : "reached t = ") << summary.time
      << " s after " << step << " steps";
  progress.finish(end.str());

  const FieldSet final = solver.fields();
  // Streamlines first: pictures may show them.
  const SceneLineOverlays lines = writeSceneStreamlines(scene, *final.findVector("velocity"),
                                                        options.outputDir, summary.files);
  for (const ImageOutput& img : scene.output.images) {
    const fs::path png = options.outputDir / imageFileName(scene, img);
    FieldImageParams params = img;
    const std::string field = choiceName(img.field);
    if (params.title.empty()) params.title = scene.name + ": " + field;
    writePng(renderFieldPicture(lbmImageField(final, field, params), params, lines.images), png);
    summary.files.push_back(png);
  }
  writeSceneLicPictures(scene, final, lines.lic, options.outputDir, summary.files);
  writeTextOutput(options.outputDir / (scene.name + "_scene.json"),
                      lbmOnly(scene::writeParams(scene)).dump(2) + "\n");
  checkpoints.finish();
  for (const auto& f : summary.files) log << "wrote " << f.string() << "\n";
  return summary;
}

}  // namespace fluidviz
