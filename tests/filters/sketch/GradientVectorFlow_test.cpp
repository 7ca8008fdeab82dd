// Gradient Vector Flow (Xu & Prince 1998): the explicit scheme against the direct sparse solve,
// the energy it descends, and its stability limits.
#include "filters/sketch/gvf/GradientVectorFlow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "filters/sketch/grid/ProjectStrokes.h"
#include "tests/filters/sketch/SketchTestFields.h"

namespace fluidviz::sketch {
namespace {

using testing::circleStroke;
using testing::latticeGrid;
using testing::lineStroke;

/// v0 of an arc and a crossing line on a 28 x 24 grid (lattice units): the drawn velocity
/// times the coverage, fading off the strokes.
VectorField smallSketch(SketchBoundary bx = SketchBoundary::zero_flux) {
  const Grid grid = latticeGrid(28, 24);
  const PlaneGrid g = PlaneGrid::of(grid, bx, SketchBoundary::zero_flux);
  std::vector<Stroke> strokes = {circleStroke({13, 12, 0}, 7, 40, 0.08),
                                 lineStroke({2, 3, 0}, {25, 20, 0}, 0.05)};
  for (Stroke& s : strokes) s = resampleStroke(s, 0.25);
  ProjectedStrokes p = projectStrokes(strokes, grid, g, 1.0);
  for (std::size_t n = 0; n < p.coverage.size(); ++n) p.velocity.values[n] *= p.coverage[n];
  return p.velocity;
}

double maxDifference(const VectorField& a, const VectorField& b) {
  double d = 0.0;
  for (std::size_t n = 0; n < a.values.size(); ++n)
    d = std::max(d, (a.values[n] - b.values[n]).lpNorm<Eigen::Infinity>());
  return d;
}

double maxComponent(const VectorField& a) {
  double s = 0.0;
  for (const Vec3& v : a.values) s = std::max(s, v.lpNorm<Eigen::Infinity>());
  return s;
}

// The explicit scheme converges to the steady state the direct solve computes: relative L-inf
// difference <= 1e-6 (issue 20), both for zero-flux and periodic sides.
TEST(GradientVectorFlow, ExplicitConvergesToDirectSolve) {
  for (SketchBoundary bx : {SketchBoundary::zero_flux, SketchBoundary::periodic}) {
    const VectorField v0 = smallSketch(bx);
    GvfParams p;
    p.mu = 2.0;
    p.boundary_x = bx;
    p.tolerance = 1e-11;
    p.solver = GvfSolver::direct;
    const GvfResult direct = gradientVectorFlow(v0, p);
    p.solver = GvfSolver::explicit_euler;
    const GvfResult expl = gradientVectorFlow(v0, p);
    const double relative = maxDifference(expl.field, direct.field) / maxComponent(direct.field);
    EXPECT_LE(relative, 1e-6) << choiceName(bx);
    EXPECT_LE(direct.residual, 1e-14);
    EXPECT_GT(expl.iterations, 100);  // it did march
    RecordProperty("relative_difference_" + std::string(choiceName(bx)), formatNumber(relative, 3));
    RecordProperty("explicit_iterations_" + std::string(choiceName(bx)),
                   std::to_string(expl.iterations));
  }
}

// The explicit step is gradient descent on E = integral mu |grad v|^2 + b |v - v0|^2, so E never
// rises between iterations, even at the largest step allowed (the combined limit). v0 with
// node-to-node noise puts energy into the checkerboard mode, the first to go unstable.
TEST(GradientVectorFlow, EnergyNeverIncreasesBetweenIterations) {
  const Grid grid = latticeGrid(20, 16);
  VectorField v0{"v0", grid, std::vector<Vec3>(grid.nodeCount(), Vec3::Zero())};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  for (int j = 4; j < 12; ++j)
    for (int i = 3; i < 15; ++i) v0.values[grid.index(i, j)] = Vec3(noise(rng), noise(rng), 0.0);
  for (double mu : {0.05, 1.0}) {
    GvfParams p;
    p.mu = mu;
    const GvfIteration probe(v0, p);
    p.time_step = probe.limits().stable();  // exactly at the limit
    GvfIteration it(v0, p);
    double previous = it.energy();
    const double start = previous;
    int rises = 0;
    for (int k = 0; k < 400; ++k) {
      it.step();
      const double e = it.energy();
      if (e > previous * (1.0 + 1e-14)) ++rises;
      previous = e;
    }
    EXPECT_EQ(rises, 0) << "mu = " << mu;
    EXPECT_LT(previous, 0.9 * start) << "mu = " << mu;  // and it does descend
    // The energy of the field matches the stand-alone evaluation.
    EXPECT_NEAR(gvfEnergy(it.field(), v0, p), previous, 1e-12 * previous);
  }
}

// A step beyond each limit is refused with the limit named; each configuration makes that
// limit the binding one.
TEST(GradientVectorFlow, UnstableExplicitStepIsRefusedNamingTheLimit) {
  const VectorField v0 = smallSketch();
  struct Case {
    double mu;
    std::string rule;
    double GvfStepLimits::*limit;
  };
  // h = 1: diffusion limit 1 / (4 mu), reaction 1, combined 2 / (8 mu + 1).
  const Case cases[] = {
      {1.0, "mu dt sum(1/h^2) <= 1/2", &GvfStepLimits::diffusion},
      {0.01, "dt max|v0|^2 <= 1", &GvfStepLimits::reaction},
      {1.0, "dt (4 mu sum(1/h^2) + max|v0|^2) <= 2", &GvfStepLimits::combined},
  };
  for (const Case& c : cases) {
    GvfParams p;
    p.mu = c.mu;
    p.solver = GvfSolver::explicit_euler;
    const GvfStepLimits limits = GvfIteration(v0, p).limits();
    // Just above the named limit; for the combined rule, below the diffusion limit.
    p.time_step = c.limit == &GvfStepLimits::combined ? 0.5 * (limits.combined + limits.diffusion)
                                                      : 1.01 * limits.*c.limit;
    try {
      gradientVectorFlow(v0, p);
      ADD_FAILURE() << "time_step " << *p.time_step << " accepted; rule " << c.rule;
    } catch (const ParamError& e) {
      EXPECT_EQ(e.key(), "time_step");
      EXPECT_NE(std::string(e.what()).find(c.rule), std::string::npos) << e.what();
    }
  }
  // Square grid, mu = 1: 1/(4 mu) = 0.25 and 2/9 are the limits the header derives.
  GvfParams p;
  p.mu = 1.0;
  const GvfStepLimits l = GvfIteration(v0, p).limits();
  EXPECT_DOUBLE_EQ(l.diffusion, 0.25);
  EXPECT_DOUBLE_EQ(l.reaction, 1.0);
  EXPECT_DOUBLE_EQ(l.combined, 2.0 / 9.0);
}

TEST(GradientVectorFlow, ExplicitSolverOutOfIterationsNamesTheKey) {
  GvfParams p;
  p.solver = GvfSolver::explicit_euler;
  p.max_iterations = 50;
  try {
    gradientVectorFlow(smallSketch(), p);
    ADD_FAILURE() << "50 iterations reached the tolerance";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "max_iterations");
    EXPECT_NE(std::string(e.what()).find("explicit GVF stopped there at residual"),
              std::string::npos)
        << e.what();
  }
}

TEST(GradientVectorFlow, EmptySketchIsRefused) {
  const Grid grid = latticeGrid(8, 8);
  const VectorField zero{"v0", grid, std::vector<Vec3>(grid.nodeCount(), Vec3::Zero())};
  EXPECT_THROW(gradientVectorFlow(zero, GvfParams{}), std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz::sketch
