// What LBM accuracy costs: error against wall time for the knobs a scene has (resolution,
// collision BGK/TRT, precision double/float, staircase/interpolated curved walls), on three
// references measured in this run:
//   Taylor-Green  decaying vortex, periodic box, exact solution (Taylor & Green 1937); diffusive
//                 scaling (tau = 0.8, lattice speed ~ 1/N), relative L2 velocity error at t = 1 /
//                 (2 nu k^2); N = 16 ... 256.
//   cavity        lid-driven square cavity, Re 100, against Ghia, Ghia & Shin 1982 (Tables I,
//                 II: centreline velocities, RMS error over the 15 interior points of each
//                 table); lattice lid speed 0.1, run to steady state; N = 32 ... 256.
//   curved wall   circular Couette flow between a rotating inner and a fixed outer cylinder
//                 (exact u_theta = A r + B / r), staircase against Bouzidi interpolated
//                 bounce-back, TRT, diffusive scaling; N = 32 ... 128 across the box.
//   cavity 3D     lid-driven cube, Re 100, D3Q19 TRT: change of the centreline profile between
//                 successive resolutions 12, 24, 48 (no published reference used).
// Wall time = construction + run, 1 thread (OMP_NUM_THREADS is set to 1 for comparability).
// Writes lbm_tradeoff.csv and lbm_tradeoff.png (log-log error vs time, rendered off-screen) into
// the output folder. docs/accuracy.md explains how to read them.
//
// Usage: lbm_tradeoff [output_dir=.] [--quick]   (full run ~3 minutes; --quick: fewer
// resolutions, a few seconds)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fieldviz/core/Sampling.h"
#include "TradeoffPlot.h"
#include "solvers/lbm/LbmSolver.h"
#include "solvers/lbm/validation/CavityGhia1982.h"
#include "solvers/lbm/validation/TaylorGreenVortex.h"
#include "tests/support/LbmScenes.h"

namespace {

namespace fs = std::filesystem;
namespace lbm = fluidviz::lbm;
using fluidviz::FieldSet;
using fluidviz::Vec3;
using fluidviz::VectorField;
using Clock = std::chrono::steady_clock;

using Point = fluidviz::bench::TradeoffPoint;
using Panel = fluidviz::bench::TradeoffPanel;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// ---- Taylor-Green -----------------------------------------------------------------------------

Point taylorGreen(int n, const std::string& collision, const std::string& precision) {
  const auto t0 = Clock::now();
  const double nu = 1e-3, k = 2 * M_PI, uLattice = 0.08 * 16.0 / n;
  lbm::LbmParams p;
  p.resolution = n;
  p.viscosity = nu;
  p.collision = fluidviz::choiceNamed<fluidviz::lbm::Collision>(collision);
  p.precision = fluidviz::choiceNamed<fluidviz::lbm::Precision>(precision);
  for (auto* w : {&p.walls.x_min, &p.walls.x_max, &p.walls.y_min, &p.walls.y_max})
    w->type = fluidviz::lbm::WallType::periodic;
  p.initial_flow = fluidviz::lbm::InitialFlow::taylor_green;
  const double dx = 1.0 / n, dt = 0.1 * dx * dx / nu;  // tau = 0.8
  p.initial_speed = uLattice * dx / dt;
  p.lattice_velocity = uLattice;
  p.end_time = 1e9;
  auto solver = lbm::createLbmSolver(p);
  const double tEnd = 1.0 / (2 * nu * k * k);
  solver->step(static_cast<int>(std::lround(tEnd / solver->units().dt)));
  const FieldSet f = solver->fields();
  const double seconds = since(t0);
  const double error = lbm::TaylorGreenVortex{k, k, p.initial_speed, nu}.relativeL2Error(
      *f.findVector("velocity"), solver->time());
  return {"Taylor-Green", collision + " " + precision, n, error, seconds,
          solver->stepCount()};
}

// ---- Cavity vs Ghia 1982 ----------------------------------------------------------------------

Point cavity(int n, const std::string& collision, const std::string& precision) {
  static const std::string data = FLUIDVIZ_EXAMPLE_DATA_DIR;
  static const auto uTable = lbm::readGhiaCentreline(data + "/ghia1982_u_vertical_centerline.csv");
  static const auto vTable = lbm::readGhiaCentreline(data + "/ghia1982_v_horizontal_centerline.csv");
  const auto t0 = Clock::now();
  lbm::LbmParams p = lbm::test::lidDrivenCavity(n, 100, 0.1);
  p.collision = fluidviz::choiceNamed<fluidviz::lbm::Collision>(collision);
  p.precision = fluidviz::choiceNamed<fluidviz::lbm::Precision>(precision);
  p.end_time = 100;
  p.steady_tolerance = precision == "float" ? 1e-5 : 1e-6;
  p.check_interval = 1000;
  auto solver = lbm::createLbmSolver(p);
  solver->run();
  const FieldSet f = solver->fields();
  const double seconds = since(t0);
  const double error = lbm::compareWithGhia(*f.findVector("velocity"), 1.0, uTable, vTable).rms;
  return {"cavity Re 100 vs Ghia", collision + " " + precision, n, error, seconds,
          solver->stepCount()};
}

// ---- Circular Couette, staircase vs Bouzidi -----------------------------------------------------

Point couette(int n, const std::string& boundary) {
  const double r1 = 0.2, r2 = 0.45, omega = 1.0, cx = 0.5, cy = 0.5;
  const auto t0 = Clock::now();
  lbm::LbmParams p;
  p.resolution = n;
  p.rollers.push_back({{cx, cy}, r1, omega});
  p.rollers[0].boundary = fluidviz::choiceNamed<fluidviz::lbm::RollerBoundary>(boundary);
  p.reynolds = 5;
  p.reference_length = r2 - r1;
  p.lattice_velocity = 0.05 * 32.0 / n;
  p.collision = fluidviz::lbm::Collision::trt;
  p.end_time = 1000.0;
  p.steady_tolerance = 1e-8;
  p.check_interval = 1000;
  lbm::SolidBody outer{"outer cylinder",
                       [=](const lbm::Vec2& x) { return std::hypot(x.x() - cx, x.y() - cy) >= r2; },
                       [](const lbm::Vec2&) { return lbm::Vec2(0.0, 0.0); },
                       boundary == "interpolated"};
  auto solver = lbm::createLbmSolver(p, {outer});
  solver->run();
  const FieldSet f = solver->fields();
  const double seconds = since(t0);
  const VectorField& u = *f.findVector("velocity");
  const double a = -omega * r1 * r1 / (r2 * r2 - r1 * r1);
  const double b = omega * r1 * r1 * r2 * r2 / (r2 * r2 - r1 * r1);
  double err2 = 0, ref2 = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (solver->isSolid(i, j)) continue;
      const Vec3 x = u.grid.position(i, j);
      const double dx = x.x() - cx, dy = x.y() - cy, r = std::hypot(dx, dy);
      const Vec3& v = u.values[u.grid.index(i, j)];
      const double ut = (-v.x() * dy + v.y() * dx) / r, exact = a * r + b / r;
      err2 += (ut - exact) * (ut - exact);
      ref2 += exact * exact;
    }
  return {"curved wall (Couette)", boundary + " trt", n, std::sqrt(err2 / ref2), seconds,
          solver->stepCount()};
}

// ---- 3D cavity: self-convergence ------------------------------------------------------------

std::vector<double> cavity3dProfile(int n, double& seconds, long long& steps) {
  const auto t0 = Clock::now();
  auto solver = lbm::createLbmSolver(lbm::test::lidDrivenCubicCavity(n));
  solver->run();
  const FieldSet f = solver->fields();
  seconds = since(t0);
  steps = solver->stepCount();
  const std::vector<double> profile = lbm::test::cubicCavityCentreline(*f.findVector("velocity"));
  return profile;
}

}  // namespace

int main(int argc, char** argv) {
  const fluidviz::bench::TradeoffArgs args = fluidviz::bench::parseTradeoffArgs(argc, argv);
  const fs::path& outDir = args.outDir;
  const bool quick = args.quick;
  std::vector<Point> points;
  auto report = [&](const Point& p) {
    points.push_back(p);
    std::printf("%-22s %-22s %5d %12.3e %10.3f %10lld\n", p.reference.c_str(), p.variant.c_str(), p.n,
                p.error, p.seconds, p.steps);
    std::fflush(stdout);
  };
  std::printf("%-22s %-22s %5s %12s %10s %10s\n", "reference", "variant", "N", "error", "seconds",
              "steps");
  taylorGreen(32, "bgk", "double");  // warm-up: first-use costs (thread pool, page faults, clones)
  const std::vector<std::pair<std::string, std::string>> variants{
      {"bgk", "double"}, {"trt", "double"}, {"bgk", "float"}, {"trt", "float"}};
  const std::vector<int> tgN = quick ? std::vector<int>{16, 32, 64} : std::vector<int>{16, 32, 64, 128, 256};
  for (const auto& [c, prec] : variants)
    for (int n : tgN) report(taylorGreen(n, c, prec));
  const std::vector<int> cavN = quick ? std::vector<int>{32, 64} : std::vector<int>{32, 64, 128, 256};
  for (const auto& [c, prec] : variants)
    for (int n : cavN) report(cavity(n, c, prec));
  const std::vector<int> couN = quick ? std::vector<int>{32, 64} : std::vector<int>{32, 45, 64, 90, 128};
  for (const char* b : {"staircase", "interpolated"})
    for (int n : couN) report(couette(n, b));
  // 3D cavity: change against the next coarser resolution as the error estimate.
  {
    std::vector<double> previous;
    for (int n : quick ? std::vector<int>{12, 24} : std::vector<int>{12, 24, 48}) {
      double seconds;
      long long steps;
      const std::vector<double> profile = cavity3dProfile(n, seconds, steps);
      if (!previous.empty()) {
        double d = 0;
        for (std::size_t k = 0; k < profile.size(); ++k)
          d += (profile[k] - previous[k]) * (profile[k] - previous[k]) / profile.size();
        report({"3D cavity (self-conv.)", "trt double (change)", n, std::sqrt(d), seconds, steps});
      }
      previous = profile;
    }
  }

  const fs::path csv = outDir / "lbm_tradeoff.csv";
  {
    std::ofstream out(csv);
    out << "reference,variant,nodes_per_side,error,seconds,steps\n";
    for (const Point& p : points)
      out << '"' << p.reference << "\"," << p.variant << ',' << p.n << ',' << p.error << ','
          << p.seconds << ',' << p.steps << '\n';
  }
  std::vector<Panel> panels{{"Taylor-Green", {"bgk double", "trt double", "bgk float", "trt float"}},
                            {"cavity Re 100 vs Ghia", {"bgk double", "trt double", "bgk float", "trt float"}},
                            {"curved wall (Couette)", {"staircase trt", "interpolated trt"}},
                            {"3D cavity (self-conv.)", {"trt double (change)"}}};
  const fs::path png = outDir / "lbm_tradeoff.png";
  fluidviz::bench::writeTradeoffPlot(
      points, panels, "LBM: error against wall time (1 thread) -- log-log; labels: nodes per side",
      "3D cavity: error = RMS change of the centreline profile from the next coarser resolution "
      "(no reference)",
      png);
  std::printf("\nwrote %s and %s\n", csv.string().c_str(), png.string().c_str());
  return 0;
}
