#include "apps/fluidviz/Commands.h"

#include <omp.h>
#include <vtkVersion.h>

#include <iostream>
#include <map>

#include "apps/fluidviz/FlowCommands.h"
#include "apps/fluidviz/ParticleCommands.h"
#include "apps/fluidviz/PlotCommand.h"
#include "apps/fluidviz/SketchCommand.h"
#include "apps/fluidviz/TopologyCommands.h"
#include "fieldviz/core/BuildInfo.h"
#include "fieldviz/core/InstabilityError.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "pipeline/RunScene.h"
#include "pipeline/SceneReading.h"
#include "pipeline/StopSignals.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "pipeline/SceneDocs.h"
#include "fieldviz/scene/SceneFile.h"
#include "solvers/lbm/LbmSolverD2Q9.h"

namespace fluidviz::app {

namespace {

namespace fs = std::filesystem;

const char* kMainHelp = R"(fluidviz - simulate fluids and visualise their fields

Usage:
  fluidviz run SCENE.json [-o DIR] [--replace] [--set key.path=value]... [--threads N] [--resume DIR]
  fluidviz check SCENE.json [--set key.path=value]...   validate, print units and run time
  fluidviz docs [KEY]      print the scene-file key reference (docs/scenes.md), or of KEY
  fluidviz lic FIELD.vti -a ARRAY -o OUT.png [options]   LIC picture of a vector array
  fluidviz streamlines FIELD.vti -a ARRAY -o OUT.vtp [--png OUT.png] [options]   streamlines
  fluidviz topology FIELD.vti -a ARRAY -o POINTS.vtp [--csv F] [--png F]   critical points
  fluidviz sweep SCENE.json --param PATH --from A --to B --steps N [-o DIR]   bifurcations
  fluidviz resample PARTICLES.vtp -o GRID.vti [--spacing D] [--kernel K] [--h H]   particles to grid
  fluidviz isosurface GRID.vti -a ARRAY --value V -o OUT.vtp [--png OUT.png]   surfaces/isolines
  fluidviz plot FILE.csv [--x COL] [--y COL[,COL]] [--reference REF.csv] -o PLOT.png   line plot
  fluidviz sketch STROKES.csv -o FIELD.vti [--png OUT.png] [options]   strokes to a flow (GVF)
  fluidviz --help | COMMAND --help | --version

Exit codes: 0 success, 2 bad input, 3 numerical instability, 1 anything else;
run: 130 / 143 stopped by SIGINT / SIGTERM after writing a checkpoint.
)";

const char* kRunHelp = R"(fluidviz run SCENE.json [options]

Runs a scene file: the solver, .vti snapshots listed in DIR/<name>.pvd (open it in ParaView),
and PNG pictures of the final state.

Options:
  -o, --output DIR       output folder (default: out). A folder that holds an earlier run of
                         the same scene (its <name>.pvd, <name>/ snapshots, <name>_run.json) is
                         refused: the two runs' snapshots would form one ParaView series
  --replace              remove the earlier run's files (those its <name>_run.json lists, its
                         series, scene copy and checkpoint) before the run starts
  --set key.path=value   override any scene key, e.g. --set lbm.reynolds=400
                         or --set lbm.rollers.0.angular_velocity=-2 (repeatable)
  --threads N            OpenMP threads (default: all cores)
  --resume DIR           continue an interrupted run from DIR/<name>.checkpoint, writing into
                         DIR; give the same scene and --set options (docs/checkpoints.md)
  -h, --help             this text

Checkpoints (the whole solver state) are written with every snapshot and every
checkpoint.interval seconds. SIGINT (Ctrl-C) or SIGTERM stops the run after writing one, with
exit code 130 or 143; a second signal stops at once. With the same thread count a resumed run
ends with the same files, bit for bit, as an uninterrupted one.

Besides the pictures and files the scene asks for, every run writes <name>_scene.json (the
effective scene, re-runnable, with version, date and outcome in comment lines) and <name>_run.json
(fluidviz version and commit, date, threads, derived units, outcome, steps, the files written).

Every key is documented in docs/scenes.md (or: fluidviz docs).
)";

struct RunArgs {
  std::string scene;
  std::string output = "out";
  std::vector<std::string> overrides;
  int threads = 0;
  std::string resume;  ///< folder of the interrupted run; empty: a fresh run
  bool outputGiven = false;
  bool replace = false;  ///< remove an earlier run's files from the output folder first
  bool estimate = true;  ///< check: measure the run time
  bool help = false;
};

std::string valueAfter(const std::vector<std::string>& args, std::size_t& i) {
  if (i + 1 >= args.size()) throw UsageError(args[i] + " needs a value");
  return args[++i];
}

RunArgs parseRunArgs(const std::vector<std::string>& args) {
  RunArgs r;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-h" || a == "--help") {
      r.help = true;
    } else if (a == "-o" || a == "--output") {
      r.output = valueAfter(args, i);
      r.outputGiven = true;
    } else if (a == "--no-estimate" && args[0] == "check") {
      r.estimate = false;
    } else if (a == "--replace") {
      r.replace = true;
    } else if (a == "--resume") {
      r.resume = valueAfter(args, i);
    } else if (a == "--set") {
      r.overrides.push_back(valueAfter(args, i));
    } else if (a.rfind("--set=", 0) == 0) {
      r.overrides.push_back(a.substr(6));
    } else if (a == "--threads") {
      const std::string v = valueAfter(args, i);
      try {
        std::size_t used = 0;
        r.threads = std::stoi(v, &used);
        if (used != v.size()) throw std::invalid_argument(v);
      } catch (const std::exception&) {
        throw UsageError("--threads is '" + v + "'; allowed: a whole number from 1 to 1024");
      }
      if (r.threads < 1 || r.threads > 1024)
        throw UsageError("--threads is " + v + "; allowed: 1 to 1024");
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError("unknown option '" + a + "' (see fluidviz run --help)");
    } else if (r.scene.empty()) {
      r.scene = a;
    } else {
      throw UsageError("unexpected argument '" + a + "': give one scene file");
    }
  }
  if (!r.help && r.scene.empty()) throw UsageError("needs a scene file");
  if (!r.resume.empty()) {
    if (r.outputGiven && fs::path(r.output).lexically_normal() != fs::path(r.resume).lexically_normal())
      throw UsageError("--resume " + r.resume + " and -o " + r.output + " differ: a resumed run "
                       "writes into the folder it resumes (leave out -o)");
    if (r.replace)
      throw UsageError("--replace and --resume exclude each other: a resumed run continues the "
                       "files in its folder");
    r.output = r.resume;
  }
  return r;
}

// A word for a shell command line: quoted unless it is plainly safe.
std::string shellWord(const std::string& word) {
  if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                              "0123456789_-./=:,+@%") == std::string::npos)
    return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The command that continues an interrupted run: same scene, overrides and thread count.
std::string resumeCommandLine(const RunArgs& r) {
  std::string line = "fluidviz run " + shellWord(r.scene);
  for (const std::string& o : r.overrides) line += " --set " + shellWord(o);
  if (r.threads > 0) line += " --threads " + std::to_string(r.threads);
  return line + " --resume " + shellWord(r.output);
}

SceneParams loadScene(const RunArgs& r) {
  scene::json j = scene::readSceneFile(r.scene);
  for (const std::string& o : r.overrides) scene::applyOverride(j, o, r.scene);
  return readSceneParams(j, r.scene);
}

int checkCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&, bool) {
  const RunArgs r = parseRunArgs(args);
  if (r.help) {
    out << "fluidviz check SCENE.json [--set key.path=value]... [--threads N] [--no-estimate]\n\n"
           "Validates a scene without running it and prints what the run would use (LBM: "
           "lattice units, Mach and Reynolds numbers, steps; SPH: particle counts, time-step "
           "limits) and an estimate of the run time, measured by stepping the solver for half a "
           "second (--no-estimate: validation only).\n";
    return kSuccess;
  }
  const SceneParams scene = loadScene(r);
  const std::string units = checkScene(scene, r.scene);  // "valid" only once it is
  if (r.threads > 0) omp_set_num_threads(r.threads);
  out << r.scene << ": valid\n" << units << "\n";
  if (r.estimate) out << estimateRunTime(scene, 0.5) << "\n";
  return kSuccess;
}

int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
               bool interactive) {
  const RunArgs r = parseRunArgs(args);
  if (r.help) {
    out << kRunHelp;
    return kSuccess;
  }
  const SceneParams params = loadScene(r);
  requireCreatableFolder(r.output);
  if (r.threads > 0) omp_set_num_threads(r.threads);
  RunOptions options;
  options.outputDir = r.output;
  options.sceneFile = r.scene;
  options.log = &err;
  options.interactive = interactive;
  options.resume = !r.resume.empty();
  options.replace = r.replace;
  try {
    runScene(params, options);
  } catch (const RunInterrupted& e) {
    err << "\nfluidviz: " << e.what() << "; continue with: " << resumeCommandLine(r) << "\n";
    return kSignalBase + e.signal();
  }
  return kSuccess;
}

constexpr const char* kDocsHelp = R"(usage: fluidviz docs [KEY | --keys]

  fluidviz docs          the whole scene-file key reference (Markdown, as docs/scenes.md)
  fluidviz docs KEY      the keys KEY names: the key itself (lbm.reynolds), the keys below it
                         (lbm.walls, output.images[]), or every key ending in it (reynolds, title)
  fluidviz docs --keys   every key, one a line (for shell completion of --set KEY=)
)";

int docsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&, bool) {
  if (args.size() == 1) {
    out << sceneDocsMarkdown();
    return kSuccess;
  }
  if (args.size() > 2) throw UsageError("takes at most one KEY (see fluidviz docs --help)");
  const std::string& a = args[1];
  if (a == "-h" || a == "--help") {
    out << kDocsHelp;
  } else if (a == "--keys") {
    for (const std::string& k : sceneKeys()) out << k << "\n";
  } else if (a.starts_with("-")) {
    throw UsageError("unknown option '" + a + "' (see fluidviz docs --help)");
  } else {
    const std::string text = sceneKeyDocs(a);
    if (text.empty()) {
      std::string similar;
      for (const std::string& k : similarSceneKeys(a)) similar += "\n  " + k;
      throw UsageError("no scene key '" + a + "'" +
                       (similar.empty() ? std::string("; fluidviz docs --keys lists them all")
                                        : "; keys containing it:" + similar));
    }
    out << text;
  }
  return kSuccess;
}

}  // namespace

// Every error and warning of a command starts with "fluidviz <command>: " ("fluidviz: " before a
// command is known), then "error: " for errors, so that scripts and users find it the same way.
std::string messagePrefix(const std::vector<std::string>& args) {
  return args.empty() ? "fluidviz: " : "fluidviz " + args[0] + ": ";
}

namespace {

// The command `args` names, or nullptr.
CommandFunction findCommand(const std::vector<std::string>& args) {
  static const std::vector<std::pair<std::string, CommandFunction>> commands = {
      {"run", runCommand},
      {"check", checkCommand},
      {"docs", docsCommand},
      {"lic", licCommand},
      {"streamlines", streamlinesCommand},
      {"topology", topologyCommand},
      {"sweep", sweepCommand},
      {"resample", resampleCommand},
      {"isosurface", isosurfaceCommand},
      {"plot", plotCommand},
      {"sketch", sketchCommand},
  };
  for (const auto& [name, command] : commands)
    if (!args.empty() && args[0] == name) return command;
  return nullptr;
}

// What a bug report needs: fluidviz's version and commit, the libraries and the thread count.
void printVersion(std::ostream& out) {
  out << "fluidviz " << buildInfo().describe() << "\n"
      << "VTK " << vtkVersion::GetVTKVersion() << ", OpenMP threads " << omp_get_max_threads()
      << "\n";
}

}  // namespace

int dispatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             bool interactive) {
  const CommandFunction command = findCommand(args);
  const std::string error = (command ? messagePrefix(args) : "fluidviz: ") + "error: ";
  try {
    if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
      (args.empty() ? err : out) << kMainHelp;
      return args.empty() ? kBadInput : kSuccess;
    }
    if (args[0] == "--version" || args[0] == "version") {
      printVersion(out);
      return kSuccess;
    }
    if (!command) throw UsageError("unknown command '" + args[0] + "' (see fluidviz --help)");
    return command(args, out, err, interactive);
  } catch (const UsageError& e) {
    err << error << e.what() << "\n";
    return kBadInput;
  } catch (const scene::SceneError& e) {
    err << error << e.what() << "\n";
    return kBadInput;
  } catch (const FileError& e) {
    err << error << e.what() << "\n";
    return kBadInput;
  } catch (const DataArrayError& e) {
    err << error << e.what() << "\n";
    return kBadInput;
  } catch (const InstabilityError& e) {  // any solver's (fieldviz/core/InstabilityError.h)
    err << error << "unstable: " << e.what() << "\n";
    return kUnstable;
  } catch (const std::exception& e) {
    err << error << e.what() << "\n";
    return kFailure;
  }
}

}  // namespace fluidviz::app
