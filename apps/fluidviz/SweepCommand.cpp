// fluidviz sweep: a scene run over evenly spaced values of one parameter, the topology of each
// final velocity field, and the bifurcation diagram of the critical points.
#include <omp.h>

#include <cmath>
#include <ostream>

#include "apps/fluidviz/FlowCommandSupport.h"
#include "apps/fluidviz/TopologyCommands.h"
#include "fieldviz/io/OutputPath.h"
#include "pipeline/Sweep.h"
#include "fieldviz/scene/SceneFile.h"

namespace fluidviz::app {

namespace {

namespace fs = std::filesystem;

const char* kSweepHelp = R"(fluidviz sweep SCENE.json --param PATH --from A --to B --steps N [options]

Runs the scene N times with the key PATH set to N evenly spaced values from A to B (the --set
mechanism: list elements by index, e.g. lbm.rollers.0.angular_velocity or lbm.rollers.0.center.1),
finds the critical points of each final velocity field (critical points inside rollers are left
out: roller nodes carry the roller's rigid rotation) and writes the bifurcation diagram.
Every step's scene is checked before the first run starts.

Options:
  -o, --output DIR        output folder (default: out):
                            step_KK/                      each run's files (one snapshot)
                            step_KK/NAME_critical_points.vtp/.csv
                            NAME_step_KK_topology.png     glyphs + separatrices over LIC
                            NAME_bifurcation.csv          step,parameter,x,y,z,type,index,morse,
                                                          det,trace,hyperbolic,elliptic,parabolic
                            NAME_bifurcation.png          x and y of each point vs the parameter
  --set key.path=value    scene override for every run (repeatable)
  --topology key=value    topology parameter (repeatable), e.g. --topology cluster_radius=5
  --region X0,Y0,X1,Y1    only points inside this box (m) are drawn in the diagram
  --underlay lic|speed    under the per-step glyphs (default lic)
  --no-pictures           no per-step topology pictures (faster)
  --threads N             OpenMP threads (default: all cores)

Progress of every run goes to stderr. Exit codes as for run: 2 bad input (nothing written),
3 numerical instability.
)";

double parseNumber(const std::string& flag, const std::string& text) {
  return parseNumbers(flag, text, 1)[0];
}

int parseSteps(const std::string& text) {
  const double n = parseNumber("--steps", text);
  if (n != std::floor(n) || n < 1 || n > 1000)
    throw UsageError("--steps is " + text + "; allowed: a whole number from 1 to 1000");
  return static_cast<int>(n);
}

topology::TopologyParams readTopologySettings(const std::vector<std::string>& settings) {
  scene::json j = scene::json::object();
  topology::TopologyParams params;
  try {
    for (const std::string& s : settings) scene::applyOverride(j, s, "--topology");
    scene::readParams(j, params, "");
    topology::validateTopologyParams(params);
  } catch (const scene::SceneError& e) {
    throw UsageError(e.what());
  } catch (const ParamError& e) {
    throw UsageError("--topology: key '" + e.key() + "' " + e.what());
  }
  return params;
}

struct SweepArgs {
  std::string scene;
  fs::path output = "out";
  SweepParams params;
  int threads = 0;
};

SweepArgs parseSweepArgs(std::vector<std::string> args) {
  SweepArgs r;
  r.params.overrides = takeRepeatedOption(args, "--set");
  const std::vector<std::string> topologySettings = takeRepeatedOption(args, "--topology");
  const ParsedArgs a = parseArgs(
      args, {"--param", "--from", "--to", "--steps", "--output", "--region", "--underlay", "--background",
             "--threads"},
      {"--help", "--no-pictures"}, {{"-o", "--output"}, {"-h", "--help"}});
  if (a.positional.size() != 1)
    throw UsageError("needs exactly one scene file, got " +
                     std::to_string(a.positional.size()));
  r.scene = a.positional[0];
  for (const char* required : {"--param", "--from", "--to", "--steps"})
    if (!a.has(required))
      throw UsageError(std::string("needs ") + required + " (see --help)");
  r.params.parameter = a.value("--param");
  r.params.from = parseNumber("--from", a.value("--from"));
  r.params.to = parseNumber("--to", a.value("--to"));
  r.params.steps = parseSteps(a.value("--steps"));
  r.output = a.value("--output", "out");
  if (a.has("--region")) {
    const auto g = parseNumbers("--region", a.value("--region"), 4);
    if (!(g[0] < g[2] && g[1] < g[3]))
      throw UsageError("--region is '" + a.value("--region") + "'; expected X0,Y0,X1,Y1 with "
                       "X0 < X1 and Y0 < Y1");
    r.params.region = std::array<double, 4>{g[0], g[1], g[2], g[3]};
  }
  refuseUnderlayAsBackground(a, "glyphs");
  const std::string underlay = a.value("--underlay", "lic");
  const auto chosen = choiceFromName<TopologyUnderlay>(underlay);
  if (!chosen) throw UsageError("--underlay is '" + underlay + "'; allowed: lic, speed");
  r.params.picture.underlay = *chosen;
  if (a.has("--background")) {
    const auto backdrop = choiceFromName<Background>(a.value("--background"));
    if (!backdrop)
      throw UsageError("--background is '" + a.value("--background") + "'; allowed: white, dark");
    r.params.picture.picture.background = *backdrop;
  }
  r.params.pictures = !a.has("--no-pictures");
  r.params.topology = readTopologySettings(topologySettings);
  if (a.has("--threads")) {
    const double t = parseNumber("--threads", a.value("--threads"));
    if (t != std::floor(t) || t < 1 || t > 1024)
      throw UsageError("--threads is " + a.value("--threads") + "; allowed: 1 to 1024");
    r.threads = static_cast<int>(t);
  }
  return r;
}

}  // namespace

int sweepCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                 bool interactive) {
  for (const std::string& a : args)
    if (a == "-h" || a == "--help") {
      out << kSweepHelp;
      return kSuccess;
    }
  const SweepArgs r = parseSweepArgs(args);
  const scene::json sceneJson = scene::readSceneFile(r.scene);
  requireCreatableFolder(r.output);
  if (r.threads > 0) omp_set_num_threads(r.threads);
  SweepResult result;
  try {
    result = runSweep(sceneJson, r.scene, r.params, r.output, err, interactive);
  } catch (const ParamError& e) {
    throw UsageError("--" + e.key() + " " + e.what());
  }
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    const SweepStep& s = result.steps[k];
    out << "step " << k << ": " << r.params.parameter << " = " << s.value << ": "
        << s.points.size() << " critical points\n";
  }
  for (const fs::path& f : result.files) out << "wrote " << f.string() << "\n";
  return kSuccess;
}

}  // namespace fluidviz::app
