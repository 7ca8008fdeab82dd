// The sketch examples (examples/sketch/*.csv) as the initial state of the LBM (issue 20: "the
// LBM started from each example stays stable for at least 1000 steps at Mach < 0.1"). The
// sketched field, on the LBM's own grid (64^2, the unit square, walls at rest; the parallel
// strokes periodic in x), is scaled so that its largest lattice speed is 0.05 (Mach 0.087),
// tau = 0.8; after 1000 steps the solver's stability check passes and the Mach number stays
// below 0.1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "fieldviz/io/CsvTable.h"
#include "filters/sketch/SketchedFlow.h"
#include "solvers/lbm/LbmSolver.h"
#include "tests/support/FieldStats.h"

namespace fluidviz::sketch {
namespace {

/// The strokes of an example file (stroke, x, y, speed; a stroke's points on consecutive lines).
std::vector<Stroke> exampleStrokes(const std::string& name) {
  const std::filesystem::path file =
      std::filesystem::path(FLUIDVIZ_SOURCE_DIR) / "examples/sketch" / (name + ".csv");
  const CsvTable t = readCsv(file);
  const auto &id = t.column("stroke", file), &x = t.column("x", file), &y = t.column("y", file),
             &speed = t.column("speed", file);
  std::vector<Stroke> strokes;
  for (std::size_t r = 0; r < t.rowCount(); ++r) {
    if (r == 0 || id[r] != id[r - 1]) strokes.push_back({{}, speed[r]});
    strokes.back().points.emplace_back(x[r], y[r], 0.0);
  }
  return strokes;
}

using fluidviz::testing::maxSpeed;

TEST(SketchStartsLbm, EveryExampleStaysStableFor1000StepsBelowMach01) {
  const double cs = 1.0 / std::sqrt(3.0), latticeSpeed = 0.05, tau = 0.8;
  const int n = 64;
  const double dx = 1.0 / n;
  for (const std::string name :
       {"one_stroke", "parallel_strokes", "spiral", "source", "sink", "centre", "saddle"}) {
    SketchParams sketch;
    lbm::LbmParams p;
    p.domain_size = {1.0, 1.0};
    p.resolution = n;
    if (name == "parallel_strokes") {
      p.walls.x_min.type = p.walls.x_max.type = lbm::WallType::periodic;
      sketch.gvf.boundary_x = SketchBoundary::periodic;
    }
    // The sketch on the solver's grid; then dt such that the sketch's largest speed is
    // `latticeSpeed` in lattice units, and nu for tau.
    auto solver = [&] {
      p.viscosity = 1e-3;
      p.time_step = 1e-3;
      p.end_time = 1e6;
      return lbm::createLbmSolver(p);
    }();
    const SketchedFlow f = sketchFlow(exampleStrokes(name), solver->grid(), sketch);
    const double umax = maxSpeed(f.velocity);
    p.time_step = latticeSpeed * dx / umax;
    p.viscosity = (tau - 0.5) / 3.0 * dx * dx / *p.time_step;
    solver = lbm::createLbmSolver(p);
    ASSERT_TRUE(solver->grid().sameShape(f.velocity.grid)) << name;
    solver->initialise(std::vector<double>(solver->grid().nodeCount(), solver->units().density),
                       f.velocity.values);
    solver->step(1000);
    EXPECT_NO_THROW(solver->checkStability()) << name;
    const FieldSet after = solver->fields();
    const double mach = maxSpeed(*after.findVector("velocity")) * *p.time_step / dx / cs;
    EXPECT_LT(mach, 0.1) << name;
    EXPECT_TRUE(std::isfinite(mach)) << name;
    RecordProperty(name + "_mach_after_1000", formatNumber(mach, 3));
  }
}

}  // namespace
}  // namespace fluidviz::sketch
