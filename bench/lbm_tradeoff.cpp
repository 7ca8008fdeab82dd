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
#include <omp.h>
#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

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
#include "fieldviz/render/OffscreenRenderer.h"
#include "solvers/lbm/LbmSolver.h"

namespace {

namespace fs = std::filesystem;
namespace lbm = fluidviz::lbm;
using fluidviz::FieldSet;
using fluidviz::Vec3;
using fluidviz::VectorField;
using Clock = std::chrono::steady_clock;

struct Point {
  std::string reference, variant;
  int n;
  double error, seconds;
  long long steps;
};

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
  p.collision = collision;
  p.precision = precision;
  for (auto* w : {&p.walls.x_min, &p.walls.x_max, &p.walls.y_min, &p.walls.y_max})
    w->type = "periodic";
  p.initial_flow = "taylor_green";
  const double dx = 1.0 / n, dt = 0.1 * dx * dx / nu;  // tau = 0.8
  p.initial_speed = uLattice * dx / dt;
  p.lattice_velocity = uLattice;
  p.end_time = 1e9;
  auto solver = lbm::createLbmSolver(p);
  const double tEnd = 1.0 / (2 * nu * k * k);
  solver->step(static_cast<int>(std::lround(tEnd / solver->units().dt)));
  const FieldSet f = solver->fields();
  const double seconds = since(t0);
  const double decay = std::exp(-2 * nu * k * k * solver->time()), u0 = p.initial_speed;
  const VectorField& u = *f.findVector("velocity");
  double err2 = 0, ref2 = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3 x = u.grid.position(i, j);
      const Vec3 exact = u0 * decay *
                         Vec3(std::sin(k * x.x()) * std::cos(k * x.y()),
                              -std::cos(k * x.x()) * std::sin(k * x.y()), 0.0);
      err2 += (u.values[u.grid.index(i, j)] - exact).squaredNorm();
      ref2 += exact.squaredNorm();
    }
  return {"Taylor-Green", collision + " " + precision, n, std::sqrt(err2 / ref2), seconds,
          solver->stepCount()};
}

// ---- Cavity vs Ghia 1982 ----------------------------------------------------------------------

std::vector<std::pair<double, double>> readGhia(const std::string& file) {
  std::ifstream in(std::string(FLUIDVIZ_SHARED_DATA_DIR) + "/" + file);
  if (!in) throw std::runtime_error("cannot open " + file + " in " FLUIDVIZ_SHARED_DATA_DIR);
  std::vector<std::pair<double, double>> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::istringstream s(line);
    double a, b;
    char comma;
    s >> a >> comma >> b;
    if (a > 0.0 && a < 1.0) rows.push_back({a, b});  // wall rows are boundary values
  }
  return rows;
}

Point cavity(int n, const std::string& collision, const std::string& precision) {
  static const auto uTable = readGhia("ghia1982_u_vertical_centerline.csv");
  static const auto vTable = readGhia("ghia1982_v_horizontal_centerline.csv");
  const auto t0 = Clock::now();
  lbm::LbmParams p;
  p.resolution = n;
  p.reynolds = 100;
  p.lattice_velocity = 0.1;
  p.collision = collision;
  p.precision = precision;
  p.walls.y_max.type = "moving_wall";
  p.walls.y_max.velocity = {1.0, 0.0};
  p.end_time = 100;
  p.steady_tolerance = precision == "float" ? 1e-5 : 1e-6;
  p.check_interval = 1000;
  auto solver = lbm::createLbmSolver(p);
  solver->run();
  const FieldSet f = solver->fields();
  const double seconds = since(t0);
  const VectorField& u = *f.findVector("velocity");
  double e2 = 0;
  int count = 0;
  for (const auto& [y, ref] : uTable) {
    const double d = fluidviz::sample(u, Vec3(0.5, y, 0.0))->x() - ref;
    e2 += d * d;
    ++count;
  }
  for (const auto& [x, ref] : vTable) {
    const double d = fluidviz::sample(u, Vec3(x, 0.5, 0.0))->y() - ref;
    e2 += d * d;
    ++count;
  }
  return {"cavity Re 100 vs Ghia", collision + " " + precision, n, std::sqrt(e2 / count), seconds,
          solver->stepCount()};
}

// ---- Circular Couette, staircase vs Bouzidi -----------------------------------------------------

Point couette(int n, const std::string& boundary) {
  const double r1 = 0.2, r2 = 0.45, omega = 1.0, cx = 0.5, cy = 0.5;
  const auto t0 = Clock::now();
  lbm::LbmParams p;
  p.resolution = n;
  p.rollers.push_back({{cx, cy}, r1, omega});
  p.rollers[0].boundary = boundary;
  p.reynolds = 5;
  p.reference_length = r2 - r1;
  p.lattice_velocity = 0.05 * 32.0 / n;
  p.collision = "trt";
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
  lbm::LbmParams p;
  p.lattice = "D3Q19";
  p.collision = "trt";
  p.domain_depth = 1.0;
  p.resolution = n;
  p.reynolds = 100;
  p.lattice_velocity = 0.1;
  p.walls.y_max.type = "moving_wall";
  p.walls.y_max.velocity = {1.0, 0.0};
  p.end_time = 60;
  p.steady_tolerance = 1e-5;
  p.check_interval = 200;
  auto solver = lbm::createLbmSolver(p);
  solver->run();
  const FieldSet f = solver->fields();
  seconds = since(t0);
  steps = solver->stepCount();
  std::vector<double> profile;
  for (int k = 1; k <= 9; ++k)
    profile.push_back(fluidviz::sample(*f.findVector("velocity"), Vec3(0.5, 0.1 * k, 0.5))->x());
  return profile;
}

// ---- Plot: log-log error vs time, one panel per reference, drawn with plain 2D actors --------

struct Panel {
  std::string title;
  std::vector<std::string> variants;  // series in legend order
};

void addPolyline(fluidviz::OffscreenRenderer& r, const std::vector<std::array<double, 2>>& pts,
                 const std::array<double, 3>& color, double width, bool closed = false) {
  vtkNew<vtkPoints> points;
  for (const auto& p : pts) points->InsertNextPoint(p[0], p[1], 0.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType count = static_cast<vtkIdType>(pts.size()) + (closed ? 1 : 0);
  lines->InsertNextCell(count);
  for (vtkIdType i = 0; i < count; ++i) lines->InsertCellPoint(i % static_cast<vtkIdType>(pts.size()));
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkActor2D> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  r.addProp(actor);
}

void addText(fluidviz::OffscreenRenderer& r, const std::string& text, double x, double y, int size,
             int hJustify, int vJustify, const std::array<double, 3>& color = {0, 0, 0},
             bool bold = false) {
  vtkNew<vtkTextActor> t;
  t->SetInput(text.c_str());
  t->SetDisplayPosition(static_cast<int>(x), static_cast<int>(y));
  vtkTextProperty* p = t->GetTextProperty();
  p->SetFontSize(size);
  p->SetColor(color[0], color[1], color[2]);
  p->SetBold(bold);
  p->SetJustification(hJustify);       // 0 left, 1 centred, 2 right
  p->SetVerticalJustification(vJustify);  // 0 bottom, 1 centred, 2 top
  r.addProp(t);
}

void writePlot(const std::vector<Point>& points, const std::vector<Panel>& panels,
               const fs::path& png) {
  const int panelW = 440, panelH = 470, width = panelW * static_cast<int>(panels.size()), height = 560;
  fluidviz::OffscreenRenderer r(width, height);
  const std::vector<std::array<double, 3>> palette{{0.12, 0.47, 0.71}, {0.84, 0.15, 0.16},
                                                   {0.17, 0.63, 0.17}, {1.00, 0.50, 0.05},
                                                   {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29}};
  addText(r, "LBM: error against wall time (1 thread) -- log-log; labels: nodes per side",
          width / 2.0, height - 12, 20, 1, 2, {0, 0, 0}, true);
  addText(r, "3D cavity: error = RMS change of the centreline profile from the next coarser "
          "resolution (no reference)", width / 2.0, 2, 13, 1, 0);
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const Panel& panel = panels[p];
    std::vector<const Point*> mine;
    for (const Point& pt : points)
      if (pt.reference == panel.title) mine.push_back(&pt);
    if (mine.empty()) continue;
    double tMin = 1e300, tMax = 0, eMin = 1e300, eMax = 0;
    for (const Point* pt : mine) {
      tMin = std::min(tMin, pt->seconds);
      tMax = std::max(tMax, pt->seconds);
      eMin = std::min(eMin, pt->error);
      eMax = std::max(eMax, pt->error);
    }
    const double lt0 = std::floor(std::log10(std::max(tMin, 1e-4))), lt1 = std::ceil(std::log10(tMax));
    const double le0 = std::floor(std::log10(eMin)), le1 = std::ceil(std::log10(eMax));
    const double x0 = p * panelW + 80, x1 = (p + 1) * panelW - 25, y0 = 70, y1 = y0 + panelH - 60;
    auto X = [&](double t) { return x0 + (std::log10(std::max(t, 1e-4)) - lt0) / std::max(lt1 - lt0, 1.0) * (x1 - x0); };
    auto Y = [&](double e) { return y0 + (std::log10(e) - le0) / std::max(le1 - le0, 1.0) * (y1 - y0); };
    // Grid and decade labels.
    for (double d = lt0; d <= lt1 + 1e-9; d += 1) {
      addPolyline(r, {{X(std::pow(10, d)), y0}, {X(std::pow(10, d)), y1}}, {0.85, 0.85, 0.85}, 1);
      char s[32];
      std::snprintf(s, sizeof s, "%g s", std::pow(10, d));
      addText(r, s, X(std::pow(10, d)), y0 - 6, 13, 1, 2);
    }
    for (double d = le0; d <= le1 + 1e-9; d += 1) {
      addPolyline(r, {{x0, Y(std::pow(10, d))}, {x1, Y(std::pow(10, d))}}, {0.85, 0.85, 0.85}, 1);
      char s[32];
      std::snprintf(s, sizeof s, "1e%d", static_cast<int>(d));
      addText(r, s, x0 - 6, Y(std::pow(10, d)), 13, 2, 1);
    }
    addPolyline(r, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {0, 0, 0}, 1.5, true);
    addText(r, panel.title, (x0 + x1) / 2, y1 + 28, 17, 1, 1, {0, 0, 0}, true);
    addText(r, "wall time", (x0 + x1) / 2, y0 - 30, 14, 1, 2);
    addText(r, "error", x0 - 40, y1 + 28, 14, 1, 1);
    for (std::size_t v = 0; v < panel.variants.size(); ++v) {
      const auto& color = palette[v % palette.size()];
      std::vector<std::array<double, 2>> line;
      for (const Point* pt : mine)
        if (pt->variant == panel.variants[v]) line.push_back({X(pt->seconds), Y(pt->error)});
      if (line.empty()) continue;
      if (line.size() > 1) addPolyline(r, line, color, 2.5);
      for (const Point* pt : mine) {
        if (pt->variant != panel.variants[v]) continue;
        const double cx = X(pt->seconds), cy = Y(pt->error), h = 4;
        addPolyline(r, {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}},
                    color, 2, true);
        addText(r, std::to_string(pt->n), cx + 6, cy + 4, 11, 0, 0, color);
      }
      // Legend, lower left of the panel.
      const double ly = y0 + 14 + 18.0 * (panel.variants.size() - 1 - v);
      addPolyline(r, {{x0 + 12, ly}, {x0 + 36, ly}}, color, 3);
      addText(r, panel.variants[v], x0 + 42, ly, 13, 0, 1, color);
    }
  }
  r.renderToPng(png);
}

}  // namespace

int main(int argc, char** argv) {
  fs::path outDir = ".";
  bool quick = false;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--quick")
      quick = true;
    else
      outDir = arg;
  }
  fs::create_directories(outDir);
  omp_set_num_threads(1);
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
  writePlot(points, panels, png);
  std::printf("\nwrote %s and %s\n", csv.string().c_str(), png.string().c_str());
  return 0;
}
