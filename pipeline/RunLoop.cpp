#include "pipeline/RunLoop.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>

#include "fieldviz/core/InstabilityError.h"
#include "fieldviz/core/Params.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "pipeline/Checkpoint.h"
#include "pipeline/PictureSeries.h"
#include "pipeline/Probes.h"
#include "pipeline/Progress.h"
#include "pipeline/RunRecord.h"
#include "pipeline/StopSignals.h"
#include "pipeline/TimeSeries.h"

namespace fluidviz {

namespace fs = std::filesystem;

SnapshotSeries::SnapshotSeries(fs::path dir, std::string name,
                               std::vector<PvdSeries::Entry> earlier)
    : dir_(std::move(dir)), name_(std::move(name)), path_(dir_ / (name_ + ".pvd")) {
  if (!earlier.empty()) series_.emplace(path_, std::move(earlier));
}

const std::vector<PvdSeries::Entry>& SnapshotSeries::entries() const {
  static const std::vector<PvdSeries::Entry> none;
  return series_ ? series_->entries() : none;
}

namespace {
std::string numbered(const std::string& stem, int index, const std::string& extension) {
  char number[16];
  std::snprintf(number, sizeof number, "_%04d", index);
  return stem + number + extension;
}
}  // namespace

fs::path SnapshotSeries::file(int index, const std::string& extension) const {
  fs::create_directories(dir_ / name_);
  return fs::path(name_) / numbered(name_, index, extension);
}

fs::path SnapshotSeries::frameFile(int index, const std::string& pictureFile) const {
  fs::create_directories(dir_ / name_);
  const fs::path picture(pictureFile);
  return fs::path(name_) / numbered(picture.stem().string(), index, picture.extension().string());
}

void SnapshotSeries::add(double time, const fs::path& relative, std::vector<fs::path>& written) {
  if (!series_) series_.emplace(path_);
  series_->add(time, relative.string());
  written.push_back(dir_ / relative);
}

namespace {

// The provenance every snapshot file carries as field data (the date is left to the run record:
// a resumed run's snapshots stay byte-identical to an uninterrupted run's).
std::vector<std::pair<std::string, std::string>> snapshotProvenance(
    const Solver& solver, const SceneParams& scene, const scene::json& effectiveScene) {
  const Provenance p = Provenance::now();
  return {{"fluidviz_version", p.version},
          {"fluidviz_commit", p.commit + (p.modified ? " (modified)" : "")},
          {"scene_name", scene.name},
          {"solver", solver.description()},
          {"scene", effectiveScene.dump()}};
}

// <name>_scene.json and <name>_run.json of a run that ended with `outcome` (RunRecord.h),
// appended to `files`.
void recordRun(const Solver& solver, const SceneParams& scene, const scene::json& effectiveScene,
               const RunOptions& options, const SnapshotSeries& series, RunOutcome outcome,
               const std::string& message, std::vector<fs::path>& files) {
  if (!series.entries().empty() &&
      std::find(files.begin(), files.end(), series.path()) == files.end())
    files.push_back(series.path());
  RunRecord record{Provenance::now(), options.sceneFile, solver.description(), outcome, message,
                   solver.stepCount(), solver.time(), files};
  writeRunRecord(options.outputDir, scene.name, effectiveScene, record);
  files.push_back(options.outputDir / (scene.name + "_scene.json"));
  files.push_back(runRecordPath(options.outputDir, scene.name));
}

// The loop's own state in a checkpoint, before the solver's.
void saveRunState(StateWriter& w, int written, const Solver& solver) {
  w.put<std::int32_t>(written);
  solver.saveState(w);
}

// Restores solver and snapshot count from a checkpoint that openCheckpointForResume accepted.
int restoreRunState(LoadedCheckpoint& ckpt, const fs::path& file, Solver& solver) {
  try {
    if (ckpt.header.solver != solver.name())
      throw StateFormatError("it was written by solver " + ckpt.header.solver + ", the scene runs " +
                             solver.name());
    const int written = ckpt.state.get<std::int32_t>();
    if (written < 0 || static_cast<std::size_t>(written) != ckpt.header.snapshots.size())
      throw StateFormatError("it counts " + std::to_string(written) + " snapshots but lists " +
                             std::to_string(ckpt.header.snapshots.size()));
    solver.restoreState(ckpt.state);
    if (ckpt.state.remaining() != 0) throw StateFormatError("bytes are left over after the state");
    return written;
  } catch (const StateFormatError& e) {
    throw FileError(file, "checkpoint " + file.string() + " does not fit this scene's solver: " +
                              e.what() + "; start the run again without --resume");
  }
}

}  // namespace

RunSummary runLoop(Solver& solver, SolverOutputs& outputs, const SceneParams& scene,
                   const scene::json& effectiveScene, const RunOptions& options) {
  std::ostream& log = options.log ? *options.log : std::cerr;
  log << scene.name << ": " << solver.description() << "\n";
  const std::string sceneJson = checkpointSceneJson(effectiveScene);
  RunSummary summary;
  std::optional<LoadedCheckpoint> resumed;
  if (options.resume) resumed = openCheckpointForResume(scene, sceneJson, options);
  if (!resumed) claimOutputFolder(options.outputDir, scene.name, options.replace);
  fs::create_directories(options.outputDir);
  if (!resumed) prepareFreshOutput(scene, options);
  const int snapshots = scene.output.snapshots;
  SnapshotSeries series(options.outputDir, scene.name,
                        resumed ? resumed->header.snapshots : std::vector<PvdSeries::Entry>{});
  for (const PvdSeries::Entry& e : series.entries())
    summary.files.push_back(options.outputDir / e.file);
  series.setProvenance(snapshotProvenance(solver, scene, effectiveScene));

  outputs.begin(series, resumed.has_value(), summary.files);  // before the state moves on

  RunCheckpointer checkpoints(scene, options);
  int written = 0;  // snapshots, t = 0 included: snapshot k of n targets is file k
  TimeSeries timeSeries(scene, options.sceneFile);
  if (resumed) {
    written = restoreRunState(*resumed, checkpoints.path(), solver);
    log << scene.name << ": resuming from " << checkpoints.path().string() << " at "
        << solver.position() << " (" << written << " snapshots written)\n";
    timeSeries.resume(options.outputDir, solver.time());
  }
  // Saved at every sample, so that a resume from any checkpoint continues the series.
  auto sample = [&] {
    if (timeSeries.sampleIfDue(solver.time(), outputs)) timeSeries.writeCsv(options.outputDir);
  };
  sample();

  auto header = [&] {
    return CheckpointHeader{solver.name(), sceneJson, solver.stepCount(), solver.time(),
                            series.entries()};
  };
  auto state = [&](StateWriter& w) { saveRunState(w, written, solver); };
  auto pollStop = [&] {
    if (const int signal = checkpoints.stopSignal(solver.stepCount()))
      checkpoints.stop(signal, header(), state);
  };
  ProgressReporter progress(log, options.interactive, scene.name);
  auto report = [&](const SolverProgress& p) { progress.update(p.fraction, p.detail); };
  auto showWarnings = [&](const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings) log << scene.name << ": warning: " << w << "\n";
  };

  const int targets = std::max(snapshots, 1);
  try {
    if (snapshots > 0 && written == 0) outputs.writeSnapshot(written++, series, summary.files);
    for (int k = snapshots > 0 ? written : 1; k <= targets && !solver.stoppedEarly(); ++k) {
      RunTarget target{k, targets};
      while (!solver.reached(target)) {
        target.sampleTime = timeSeries.nextSampleTime();
        if (const std::optional<SolverProgress> p = solver.advance(target)) report(*p);
        showWarnings(solver.takeWarnings());
        sample();
        if (solver.reached(target)) break;  // the snapshot comes before a stop
        if (checkpoints.intervalDue()) checkpoints.write(header(), state);
        pollStop();
      }
      if (snapshots > 0) {
        solver.checkStability();
        outputs.writeSnapshot(written++, series, summary.files);
      }
      if (snapshots > 0 ? checkpoints.atSnapshots() : checkpoints.intervalDue())
        checkpoints.write(header(), state);
      report(solver.progress());
      pollStop();
    }
  } catch (const InstabilityError& e) {
    progress.finish("stopped: unstable at t = " + formatNumber(solver.time(), 4) + " s");
    log << scene.name << ": kept " << written << " complete snapshot(s) in "
        << series.path().string() << "\n";
    recordRun(solver, scene, effectiveScene, options, series, RunOutcome::unstable, e.what(),
              summary.files);
    throw;
  } catch (const RunInterrupted& e) {
    recordRun(solver, scene, effectiveScene, options, series, RunOutcome::interrupted, e.what(),
              summary.files);
    throw;
  }
  if (timeSeries.sampleFinal(solver.time(), outputs)) timeSeries.writeCsv(options.outputDir);
  summary.steps = static_cast<long>(solver.stepCount());
  summary.time = solver.time();
  summary.steady = solver.steady();
  showWarnings(solver.closingWarnings());
  progress.finish(solver.summary());
  if (snapshots > 0 && written < snapshots + 1)
    log << scene.name << ": the run ended early (" << solver.summary() << "): wrote " << written
        << " of " << snapshots + 1 << " snapshots (t = 0 and " << written - 1 << " of "
        << snapshots << " targets; the last is the final state)\n";

  outputs.writeFinal(series, effectiveScene, summary.files);
  const RunOutcome outcome = summary.steady ? RunOutcome::steady_state : RunOutcome::completed;
  try {
    writeMovies(scene, series, log, options.interactive, summary.files);
  } catch (const std::exception& e) {  // ffmpeg failed: the files so far stay listed (--replace)
    recordRun(solver, scene, effectiveScene, options, series, outcome, e.what(), summary.files);
    throw;
  }
  if (!scene.output.probes.empty())
    writeProbes(scene, outputs.probeFields(), solver.time(), options.sceneFile, series.dir(), log,
                summary.files);
  timeSeries.write(series.dir(), log, summary.files);
  checkpoints.finish();
  recordRun(solver, scene, effectiveScene, options, series, outcome, "", summary.files);
  for (const auto& f : summary.files) log << "wrote " << f.string() << "\n";
  return summary;
}

}  // namespace fluidviz
