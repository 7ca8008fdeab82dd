// What SPH accuracy costs: error against wall time on the 2D dam break (Martin & Moyce 1952),
// for the knobs a scene has:
//   particle spacing  a / dx = 10, 20, 40 (column a = 0.5 m wide, 2a high, tank 4a long);
//   model and kernel  B (weakly compressible, alpha = 0.1, delta-SPH 0.1) with the cubic spline
//                     or Wendland C2 (h = 1.3 dx); A (Mueller 2003: poly6 / spiky / viscosity
//                     kernels, h = 1.5 dx, max_density_error 0.2, as in DamBreak_test).
// Error = max |Z_sim - Z_MM| of the surge front over Martin & Moyce's points with T <= 2.5
// (solvers/sph/SurgeFrontMartinMoyce.h, the code of the validation test); a run that stops
// with an InstabilityError is listed as unstable. Wall time = construction + run to T = 2.5,
// 1 thread (the particle counts are below the solver's threading threshold anyway).
// Writes sph_tradeoff.csv and sph_tradeoff.png (log-log error vs time, off-screen) into the
// output folder. docs/accuracy.md "SPH" explains how to read them.
//
// Usage: sph_tradeoff [output_dir=.] [--quick]   (full run ~5-10 minutes on a shared 2-core
// machine; --quick: a / dx = 10 and 20 only)

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "TradeoffPlot.h"
#include "fieldviz/io/OutputPath.h"
#include "solvers/sph/InstabilityError.h"
#include "solvers/sph/SphSolver.h"
#include "solvers/sph/SurgeFrontMartinMoyce.h"
#include "tests/support/SphScenes.h"

namespace {

namespace fs = std::filesystem;
namespace sph = fluidviz::sph;
using Point = fluidviz::bench::TradeoffPoint;
using Clock = std::chrono::steady_clock;

constexpr double kA = 0.5;
const char* kReference = "dam break vs Martin & Moyce";

struct Variant {
  std::string name, model, kernel;
};

// The scene of tests/solvers/sph/DamBreak_test.cpp (tests/support/SphScenes.h), with its
// per-model settings.
sph::SphParams damBreak(const Variant& v, int particlesAcross) {
  sph::SphParams p = sph::test::damBreak2D(v.model, kA, particlesAcross);
  p.kernel = fluidviz::choiceNamed<fluidviz::sph::SphKernel>(v.kernel);
  if (v.model == "B") p.alpha = 0.1;
  if (v.model == "A") {
    p.smoothing_length_ratio = 1.5;
    p.max_density_error = 0.2;
  }
  return p;
}

struct Run {
  Point point;
  bool stable = true;
  std::string note;
};

Run run(const Variant& v, int n, const std::vector<sph::SurgeFrontPoint>& data) {
  Run r;
  r.point = {kReference, v.name, n, std::numeric_limits<double>::quiet_NaN(), 0.0, 0};
  const auto t0 = Clock::now();
  try {
    sph::SphSolver solver(damBreak(v, n));
    const sph::SurgeFrontComparison c = sph::compareSurgeFront(solver, kA, sph::test::kGravity, data);
    r.point.error = c.maxError;
    r.point.steps = solver.stepCount();
    if (c.maxRitterExcess >= 0.0) r.note = "passes Ritter's bound";
  } catch (const sph::InstabilityError& e) {
    r.stable = false;
    r.note = std::string("unstable: ") + e.reason();
  }
  r.point.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const fluidviz::bench::TradeoffArgs args = fluidviz::bench::parseTradeoffArgs(argc, argv);
  const fs::path& outDir = args.outDir;
  const bool quick = args.quick;
  const std::vector<sph::SurgeFrontPoint> data =
      sph::readMartinMoyce(std::string(FLUIDVIZ_EXAMPLE_DATA_DIR) + "/martin_moyce_1952_surge_front.csv");
  const std::vector<Variant> variants{{"B cubic spline", "B", "cubic_spline"},
                                      {"B Wendland C2", "B", "wendland_c2"},
                                      {"A Mueller kernels", "A", "cubic_spline"}};
  const std::vector<int> spacings = quick ? std::vector<int>{10, 20} : std::vector<int>{10, 20, 40};
  std::vector<Point> points;
  std::ostringstream csv;
  csv << "variant,model,kernel,particles_per_a,fluid_particles,max_front_error,seconds,steps,note\n";
  std::printf("%-20s %6s %8s %12s %10s %8s  %s\n", "variant", "a/dx", "fluid", "max |dZ|",
              "seconds", "steps", "note");
  for (const Variant& v : variants) {
    for (int n : spacings) {
      const Run r = run(v, n, data);
      const int fluid = 2 * n * n;
      std::printf("%-20s %6d %8d %12.4f %10.2f %8lld  %s\n", v.name.c_str(), n, fluid,
                  r.point.error, r.point.seconds, r.point.steps, r.note.c_str());
      std::fflush(stdout);
      csv << '"' << v.name << "\"," << v.model << ',' << (v.model == "A" ? "mueller2003" : v.kernel)
          << ',' << n << ',' << fluid << ',' << r.point.error << ',' << r.point.seconds << ','
          << r.point.steps << ",\"" << r.note << "\"\n";
      if (r.stable) points.push_back(r.point);
    }
  }
  const fs::path csvFile = outDir / "sph_tradeoff.csv", png = outDir / "sph_tradeoff.png";
  fluidviz::writeTextOutput(csvFile, csv.str());
  std::vector<fluidviz::bench::TradeoffPanel> panels{{kReference, {}}};
  for (const Variant& v : variants) panels[0].variants.push_back(v.name);
  fluidviz::bench::writeTradeoffPlot(
      points, panels, "SPH dam break: front error against wall time (1 thread)",
      "error = max |Z - Z_MM| for T <= 2.5; labels: particles across the column (a / dx)", png);
  std::printf("\nwrote %s and %s\n", csvFile.string().c_str(), png.string().c_str());
  return 0;
}
