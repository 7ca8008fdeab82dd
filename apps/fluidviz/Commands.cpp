#include "apps/fluidviz/Commands.h"

#include <omp.h>

#include <iostream>
#include <map>

#include "apps/fluidviz/FlowCommands.h"
#include "apps/fluidviz/ParticleCommands.h"
#include "apps/fluidviz/TopologyCommands.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/pipeline/RunScene.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "fieldviz/pipeline/SceneDocs.h"
#include "fieldviz/scene/SceneFile.h"
#include "solvers/lbm/LbmSolverD2Q9.h"
#include "solvers/sph/InstabilityError.h"

namespace fluidviz::app {

namespace {

const char* kMainHelp = R"(fluidviz - simulate fluids and visualise their fields

Usage:
  fluidviz run SCENE.json [-o DIR] [--set key.path=value]... [--threads N]
  fluidviz check SCENE.json [--set key.path=value]...   validate only, print lattice units
  fluidviz docs            print the scene-file key reference (docs/scenes.md)
  fluidviz lic FIELD.vti -a ARRAY -o OUT.png [options]   LIC picture of a vector array
  fluidviz streamlines FIELD.vti -a ARRAY -o OUT.vtp [--png OUT.png] [options]   streamlines
  fluidviz topology FIELD.vti -a ARRAY -o POINTS.vtp [--csv F] [--png F]   critical points
  fluidviz sweep SCENE.json --param PATH --from A --to B --steps N [-o DIR]   bifurcations
  fluidviz resample PARTICLES.vtp -o GRID.vti [--spacing D] [--kernel K] [--h H]   particles to grid
  fluidviz isosurface GRID.vti -a ARRAY --value V -o OUT.vtp [--png OUT.png]   surfaces/isolines
  fluidviz --help | COMMAND --help

Exit codes: 0 success, 2 bad input, 3 numerical instability, 1 anything else.
)";

const char* kRunHelp = R"(fluidviz run SCENE.json [options]

Runs a scene file: the solver, .vti snapshots listed in DIR/<name>.pvd (open it in ParaView),
and PNG pictures of the final state.

Options:
  -o, --output DIR       output folder (default: out)
  --set key.path=value   override any scene key, e.g. --set lbm.reynolds=400
                         or --set lbm.rollers.0.angular_velocity=-2 (repeatable)
  --threads N            OpenMP threads (default: all cores)
  -h, --help             this text

Every key is documented in docs/scenes.md (or: fluidviz docs).
)";

struct RunArgs {
  std::string scene;
  std::string output = "out";
  std::vector<std::string> overrides;
  int threads = 0;
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
  if (!r.help && r.scene.empty()) throw UsageError("fluidviz run needs a scene file");
  return r;
}

SceneParams loadScene(const RunArgs& r) {
  scene::json j = scene::readSceneFile(r.scene);
  for (const std::string& o : r.overrides) scene::applyOverride(j, o, r.scene);
  return scene::readScene<SceneParams>(j, r.scene);
}

int checkCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&, bool) {
  const RunArgs r = parseRunArgs(args);
  if (r.help) {
    out << "fluidviz check SCENE.json [--set key.path=value]...\n\nValidates a scene without "
           "running it and prints the lattice units the run would use.\n";
    return kSuccess;
  }
  out << r.scene << ": valid\n" << checkScene(loadScene(r), r.scene) << "\n";
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
  if (r.threads > 0) omp_set_num_threads(r.threads);
  RunOptions options;
  options.outputDir = r.output;
  options.sceneFile = r.scene;
  options.log = &err;
  options.interactive = interactive;
  runScene(params, options);
  return kSuccess;
}

int docsCommand(const std::vector<std::string>&, std::ostream& out, std::ostream&, bool) {
  out << sceneDocsMarkdown();
  return kSuccess;
}

}  // namespace

int dispatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             bool interactive) {
  try {
    if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
      (args.empty() ? err : out) << kMainHelp;
      return args.empty() ? kBadInput : kSuccess;
    }
    const std::vector<std::pair<std::string, CommandFunction>> commands = {
        {"run", runCommand},
        {"check", checkCommand},
        {"docs", docsCommand},
        {"lic", licCommand},
        {"streamlines", streamlinesCommand},
        {"topology", topologyCommand},
        {"sweep", sweepCommand},
        {"resample", resampleCommand},
        {"isosurface", isosurfaceCommand},
    };
    for (const auto& [name, command] : commands)
      if (args[0] == name) return command(args, out, err, interactive);
    throw UsageError("unknown command '" + args[0] + "' (see fluidviz --help)");
  } catch (const UsageError& e) {
    err << "fluidviz: " << e.what() << "\n";
    return kBadInput;
  } catch (const scene::SceneError& e) {
    err << "fluidviz: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const FileError& e) {
    err << "fluidviz: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const DataArrayError& e) {
    err << "fluidviz: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const lbm::InstabilityError& e) {
    err << "fluidviz: unstable: " << e.what() << "\n";
    return kUnstable;
  } catch (const sph::InstabilityError& e) {
    err << "fluidviz: unstable: " << e.what() << "\n";
    return kUnstable;
  } catch (const std::exception& e) {
    err << "fluidviz: " << e.what() << "\n";
    return kFailure;
  }
}

}  // namespace fluidviz::app
