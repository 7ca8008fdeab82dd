#include "pipeline/RunSphScene.h"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <vtkPolyData.h>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/PvdSeries.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/Checkpoint.h"
#include "pipeline/Progress.h"
#include "pipeline/SphDerivedArrays.h"
#include "pipeline/SphGridOutputs.h"
#include "fieldviz/render/ParticleImage.h"
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "fieldviz/scene/SceneFile.h"
#include "solvers/sph/SphSolver.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

std::string num(double x) { return formatNumber(x, 4); }

// Scene rules that need no solver; ParamError keys are scene paths.
void validateSphOutputs(const SceneParams& scene) {
  if (!scene.output.lic.empty())
    throw ParamError("output.lic", "is not available for solver sph (LIC needs a grid); resample "
                                   "the particles with `fluidviz resample` and run `fluidviz "
                                   "lic` on the grid, or remove output.lic");
  if (!scene.output.streamlines.empty())
    throw ParamError("output.streamlines",
                     "is not available for solver sph (streamlines need a grid); resample the "
                     "particles with `fluidviz resample` first, or remove output.streamlines");
  // Particle pictures colour particles by a particle array; derived grid fields do not exist here.
  const std::vector<std::string> particleFields = {"speed", "density", "velocity_x", "velocity_y"};
  for (std::size_t i = 0; i < scene.output.images.size(); ++i) {
    const std::string field = choiceName(scene.output.images[i].field);
    if (std::find(particleFields.begin(), particleFields.end(), field) == particleFields.end())
      throw ParamError("output.images[" + std::to_string(i) + "].field",
                       "is \"" + field + "\", not available for solver sph; allowed one of "
                       "{speed, density, velocity_x, velocity_y}");
  }
  validateScene(scene);
}

std::string describeSolver(sph::SphSolver& s) {
  const sph::SphParams& p = s.params();
  const sph::TimeStepLimits limits = s.timeStepLimits();
  std::ostringstream d;
  d << "SPH " << p.dimension << "D model " << choiceName(p.model)
    << (p.model == sph::SphModel::weakly_compressible ? " (" + choiceName(p.kernel) + ")"
                                                       : std::string())
    << ", " << s.fluidCount()
    << " fluid + " << s.boundaryParticles().size() << " boundary particles, dx = "
    << num(p.particle_spacing) << " m, h = " << num(s.smoothingLength())
    << " m, mass = " << num(s.particleMass()) << " kg\n"
    << "c0 = " << num(p.speed_of_sound) << " m/s, stable dt at t = 0: " << num(limits.stable())
    << " s (" << limits.binding() << "), "
    << (p.time_step ? "fixed time_step = " + num(*p.time_step) + " s" : std::string("automatic"))
    << ", end_time = " << num(p.end_time) << " s";
  return d.str();
}

// Validates everything and builds the solver; every ParamError becomes a SceneError.
std::unique_ptr<sph::SphSolver> makeCheckedSolver(const SceneParams& scene,
                                                  const std::string& sceneFile) {
  std::string prefix;
  try {
    validateSphOutputs(scene);
    prefix = "sph.";
    auto solver = std::make_unique<sph::SphSolver>(scene.sph);
    prefix.clear();
    checkSphGridOutputs(scene, *solver);  // output.grids, free_surface, views
    return solver;
  } catch (const ParamError& e) {
    throw scene::SceneError(sceneFile, prefix + e.key(), e.what());
  } catch (const std::invalid_argument& e) {  // layout problems the validation cannot see
    throw scene::SceneError(sceneFile, "sph", e.what());
  }
}

// The solver stops on NaN before a state is kept; this guards the files all the same.
void requireFinite(const particles::ParticleSet& s, double time) {
  auto bad = [&](double x) {
    if (!std::isfinite(x))
      throw std::runtime_error("SPH state at t = " + num(time) +
                               " s has a non-finite value; no snapshot written");
  };
  for (const Vec3& x : s.positions)
    for (int a = 0; a < 3; ++a) bad(x[a]);
  for (const auto& sc : s.scalars)
    for (double x : sc.values) bad(x);
  for (const auto& v : s.vectors)
    for (const Vec3& x : v.values)
      for (int a = 0; a < 3; ++a) bad(x[a]);
}

std::array<double, 6> domainBox(const sph::SphParams& p) {
  const bool d3 = p.dimension == 3;
  return {p.domain_lower[0], p.domain_upper[0], p.domain_lower[1], p.domain_upper[1],
          d3 ? p.domain_lower[2] : 0.0, d3 ? p.domain_upper[2] : 0.0};
}

std::string imageFile(const SceneParams& scene, const ImageOutput& img) {
  return img.file.empty() ? scene.name + "_" + choiceName(img.field) + ".png" : img.file;
}

// The run loop's own variables, saved in checkpoints next to the solver's state.
struct SphLoopState {
  int written = 0;                             ///< snapshots written
  std::string stopReason = "end_time reached";  ///< else why the loop stopped early

  void save(StateWriter& w) const {
    w.put<std::int32_t>(written);
    w.putString(stopReason);
  }
  void restore(StateReader& r) {
    written = r.get<std::int32_t>();
    stopReason = r.getString();
  }
};

// Restores loop and solver from a checkpoint that openCheckpointForResume accepted.
void restoreSphRun(LoadedCheckpoint& ckpt, const fs::path& file, SphLoopState& loop,
                   sph::SphSolver& solver) {
  try {
    loop.restore(ckpt.state);
    solver.restoreState(ckpt.state);
    if (ckpt.state.remaining() != 0) throw StateFormatError("bytes are left over after the state");
  } catch (const StateFormatError& e) {
    throw FileError(file, "checkpoint " + file.string() + " does not fit this scene's solver: " +
                              e.what() + "; start the run again without --resume");
  }
}

}  // namespace

std::string checkSphScene(const SceneParams& scene, const std::string& sceneFile) {
  return describeSolver(*makeCheckedSolver(scene, sceneFile));
}

RunSummary runSphScene(const SceneParams& scene, const RunOptions& options) {
  std::ostream& log = options.log ? *options.log : std::cerr;
  // Everything that can be checked is checked before the first file is written.
  std::unique_ptr<sph::SphSolver> solverPtr = makeCheckedSolver(scene, options.sceneFile);
  sph::SphSolver& solver = *solverPtr;
  log << scene.name << ": " << describeSolver(solver) << "\n";

  const sph::SphParams& p = scene.sph;
  RunSummary summary;
  const fs::path& dir = options.outputDir;
  std::optional<LoadedCheckpoint> resumed;
  if (options.resume) resumed = openCheckpointForResume(scene, options);
  fs::create_directories(dir);
  if (!resumed) prepareFreshOutput(scene, options);
  PvdSeries series(dir / (scene.name + ".pvd"),
                   resumed ? resumed->header.snapshots : std::vector<PvdSeries::Entry>{});
  for (const PvdSeries::Entry& e : series.entries()) summary.files.push_back(dir / e.file);
  const particles::ParticleSet boundary = solver.boundary();  // at t = 0, also when resuming
  if (boundary.size() > 0) {
    const fs::path file = dir / (scene.name + "_boundary.vtp");
    writeVtp(resample::toPolyData(boundary), file);
    summary.files.push_back(file);
  }

  const int snapshots = scene.output.snapshots;
  SphLoopState loop;
  int& written = loop.written;
  std::string& stopReason = loop.stopReason;
  RunCheckpointer checkpoints(scene, options);
  if (resumed) {
    restoreSphRun(*resumed, checkpoints.path(), loop, solver);
    log << scene.name << ": resuming from " << checkpoints.path().string() << " at t = "
        << num(solver.time()) << " s, step " << solver.stepCount() << " (" << written
        << " snapshots written)\n";
  }
  const std::string sceneJson = checkpointSceneJson(scene);
  auto header = [&] {
    return CheckpointHeader{"sph", sceneJson, solver.stepCount(), solver.time(), series.entries()};
  };
  auto saveState = [&](StateWriter& w) {
    loop.save(w);
    solver.saveState(w);
  };
  SphGridOutputs gridOutputs(scene, dir, log, resumed.has_value(), series.entries());
  summary.files.insert(summary.files.end(), gridOutputs.earlierFiles().begin(),
                       gridOutputs.earlierFiles().end());
  auto writeSnapshot = [&] {
    const particles::ParticleSet fluid = withDerived(solver.fluid());
    requireFinite(fluid, solver.time());
    fs::create_directories(dir / scene.name);
    char file[96];
    std::snprintf(file, sizeof file, "%s_%04d.vtp", scene.name.c_str(), ++written);
    const fs::path relative = fs::path(scene.name) / file;
    writeVtp(resample::toPolyData(fluid), dir / relative);  // the file first, then the index
    series.add(solver.time(), relative.string());
    summary.files.push_back(dir / relative);
    gridOutputs.snapshot(solver, written, summary.files);  // output.grids etc., every_snapshot
  };

  ProgressReporter progress(log, options.interactive, scene.name);
  std::size_t warningsShown = solver.warnings().size();  // a resumed run showed them before
  try {
    const int targets = std::max(snapshots, 1);
    for (int k = written + 1; k <= targets && stopReason == "end_time reached"; ++k) {
      const double target = k == targets ? p.end_time : p.end_time * k / targets;
      while (solver.time() < target * (1.0 - 1e-12)) {
        if (solver.stepCount() >= p.max_steps) {
          stopReason = "max_steps (" + std::to_string(p.max_steps) + ") reached";
          break;
        }
        solver.step(target - solver.time());
        for (; warningsShown < solver.warnings().size(); ++warningsShown)
          log << scene.name << ": warning: " << solver.warnings()[warningsShown] << "\n";
        if (solver.stepCount() % 20 == 0)
          progress.update(solver.time() / p.end_time,
                          "t = " + num(solver.time()) + " s, step " +
                              std::to_string(solver.stepCount()) + ", dt = " +
                              num(solver.lastTimeStep()) + " s");
        if (const int signal = checkpoints.stopSignal(solver.stepCount()))
          checkpoints.stop(signal, header(), saveState);
        if (checkpoints.intervalDue()) checkpoints.write(header(), saveState);
      }
      if (snapshots > 0) writeSnapshot();
      if (snapshots > 0 && checkpoints.atSnapshots()) checkpoints.write(header(), saveState);
      progress.update(solver.time() / p.end_time, "t = " + num(solver.time()) + " s, step " +
                                                      std::to_string(solver.stepCount()));
    }
  } catch (const sph::InstabilityError&) {
    progress.finish("stopped: unstable at t = " + num(solver.time()) + " s");
    log << scene.name << ": kept " << written << " complete snapshot(s) in "
        << series.path().string() << "\n";
    throw;
  }
  summary.steps = static_cast<long>(solver.stepCount());
  summary.time = solver.time();
  if (solver.stableLimitExceeded())
    log << scene.name << ": warning: " << solver.stepsPastStableLimit()
        << " steps exceeded the stable time-step limit\n";
  progress.finish(stopReason + ": t = " + num(summary.time) + " s after " +
                  std::to_string(summary.steps) + " steps");

  if (!scene.output.images.empty()) {
    const particles::ParticleSet fluid = withDerived(solver.fluid(), true);
    const auto fluidPoly = resample::toPolyData(fluid);
    const auto boundaryPoly = resample::toPolyData(solver.boundary());
    for (const ImageOutput& img : scene.output.images) {
      ParticlePictureParams pp;
      pp.picture = img;
      const std::string field = choiceName(img.field);
      if (pp.picture.title.empty())
        pp.picture.title = scene.name + ": " + field + ", t = " + num(summary.time) + " s";
      if (pp.picture.scalar_bar_title.empty())
        pp.picture.scalar_bar_title =
            img.field == ImageField::density ? "density (kg/m^3)" : field + " (m/s)";
      pp.color_by = field;
      pp.radius = 0.5 * p.particle_spacing;
      pp.dimension = p.dimension;
      pp.domain = domainBox(p);
      const fs::path png = dir / imageFile(scene, img);
      writePng(renderParticlePicture(fluidPoly, boundaryPoly, pp), png);
      summary.files.push_back(png);
    }
  }
  gridOutputs.finalState(solver, summary.files);  // output.grids, free_surface, views
  scene::json effective = scene::writeParams(scene);
  effective.erase("lbm");  // the other solver's defaults would not read back
  writeTextOutput(dir / (scene.name + "_scene.json"), effective.dump(2) + "\n");
  summary.files.push_back(dir / (scene.name + "_scene.json"));
  summary.files.push_back(series.path());
  checkpoints.finish();
  for (const auto& f : summary.files) log << "wrote " << f.string() << "\n";
  return summary;
}

}  // namespace fluidviz
