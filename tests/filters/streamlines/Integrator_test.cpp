// Accuracy of the shared streamline integrator against analytic streamlines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "filters/streamlines/Streamline.h"
#include "tests/support/AnalyticFields.h"

using namespace fluidviz;
using namespace fluidviz::streamlines;
using namespace fluidviz::testing;

namespace {

// [-5, 5]^2 with spacing 0.1: radius 2 (m) is 20 cells.
Grid rotationGrid() { return squareGrid(101, -5.0, 5.0); }

StreamlineParams oneTurnParams(const std::string& integrator, double step, double radiusCells) {
  StreamlineParams p;
  p.integrator = fluidviz::choiceNamed<fluidviz::streamlines::Integrator>(integrator);
  p.step = step;
  p.direction = fluidviz::streamlines::TraceDirection::forward;
  p.loop_detection = false;
  p.max_length = 2 * std::numbers::pi * radiusCells;
  p.max_steps = 10'000'000;
  return p;
}

// Largest distance (m) between the traced points and the exact solution x(t) = R(t) x0 of the
// rotation, taken at the recorded integration times.
double maxErrorAgainstRotation(const Streamline& line) {
  const Vec3 x0 = line.points[line.seed_index];
  double err = 0.0;
  for (std::size_t i = 0; i < line.points.size(); ++i) {
    const double t = line.times[i];
    const Vec3 exact(std::cos(t) * x0.x() - std::sin(t) * x0.y(),
                     std::sin(t) * x0.x() + std::cos(t) * x0.y(), 0.0);
    err = std::max(err, (line.points[i] - exact).norm());
  }
  return err;
}

double maxRadialDrift(const Streamline& line, double r0) {
  double drift = 0.0;
  for (const Vec3& p : line.points) drift = std::max(drift, std::abs(p.norm() - r0));
  return drift;
}

}  // namespace

// Bilinear interpolation of the linear field (-y, x) is exact, so the drift is RK4's own:
// ~ 2 pi theta^5 / 72 r per turn with theta = step / r = 0.005 rad, i.e. ~1e-13 m.
TEST(Integrator, Rk4RotationClosesWithRadialDriftBelow1e6CellsPerTurn) {
  const VectorField v = rotationField(rotationGrid());
  const Streamline line = traceStreamline(v, Vec3(2.0, 0.0, 0.0), oneTurnParams("rk4", 0.1, 20.0));
  ASSERT_EQ(line.reason(), TerminationReason::max_length);
  const double driftCells = maxRadialDrift(line, 2.0) / 0.1;
  RecordProperty("radial_drift_cells", std::to_string(driftCells));
  EXPECT_LT(driftCells, 1e-6);
  // Position error against x(t) = R(t) x0 at every point (phase and radius), in cells.
  const double errorCells = maxErrorAgainstRotation(line) / 0.1;
  RecordProperty("position_error_cells", std::to_string(errorCells));
  std::printf("rk4 step 0.1 cell, r = 20 cells: radial drift %.2e cells, position error %.2e "
              "cells after one turn\n", driftCells, errorCells);
  EXPECT_LT(errorCells, 1e-6);
  // max_length measures the polyline (sum of chords), a factor 1 + theta^2 / 24 shorter than
  // the arc, so the line needs that much more than the period 2 pi.
  const double theta = 0.1 / 20.0;
  EXPECT_NEAR(line.times.back(), 2 * std::numbers::pi * (1 + theta * theta / 24), 1e-8);
}

// Global error after one turn ~ step^p: halving the step divides it by 2^p.
TEST(Integrator, ConvergenceOrderOfRk2AndRk4OnTheRotation) {
  const VectorField v = rotationField(rotationGrid());
  auto error = [&](const std::string& method, double step) {
    return maxErrorAgainstRotation(
        traceStreamline(v, Vec3(1.0, 0.0, 0.0), oneTurnParams(method, step, 10.0)));
  };
  const double rk2Ratio = error("rk2", 0.4) / error("rk2", 0.2);
  const double rk4Ratio = error("rk4", 1.0) / error("rk4", 0.5);
  RecordProperty("rk2_ratio", std::to_string(rk2Ratio));
  RecordProperty("rk4_ratio", std::to_string(rk4Ratio));
  std::printf("rk2 error %.3e -> %.3e ratio %.3f; rk4 error %.3e -> %.3e ratio %.3f\n",
              error("rk2", 0.4), error("rk2", 0.2), rk2Ratio, error("rk4", 1.0),
              error("rk4", 0.5), rk4Ratio);
  EXPECT_NEAR(rk2Ratio, 4.0, 0.2);
  EXPECT_NEAR(rk4Ratio, 16.0, 0.8);
}

// The controller keeps the local error per cell of arc below `tolerance`, so the global error
// per cell of arc length travelled stays below it too; a tighter tolerance takes more steps.
TEST(Integrator, Rk45MeetsItsToleranceAndAdaptsTheStep) {
  const VectorField v = rotationField(rotationGrid());
  std::size_t previousPoints = 0;
  for (double tol : {1e-4, 1e-6, 1e-8}) {
    StreamlineParams p = oneTurnParams("rk45", 1.0, 20.0);
    p.tolerance = tol;
    p.max_step = 10.0;
    p.max_length *= 3;  // three turns
    const Streamline line = traceStreamline(v, Vec3(2.0, 0.0, 0.0), p);
    ASSERT_EQ(line.reason(), TerminationReason::max_length);
    const double errorPerCell = maxErrorAgainstRotation(line) / 0.1 / p.max_length;
    std::printf("rk45 tol %.0e: %zu points, error per cell of arc %.3e\n", tol,
                line.points.size(), errorPerCell);
    EXPECT_LT(errorPerCell, tol);
    EXPECT_GT(line.points.size(), previousPoints);
    previousPoints = line.points.size();
  }
}

TEST(Integrator, LoopDetectionReportsClosedLoop) {
  const VectorField v = rotationField(rotationGrid());
  StreamlineParams p;
  p.step = 0.1;
  const Streamline line = traceStreamline(v, Vec3(0.0, 3.0, 0.0), p);
  ASSERT_GT(line.points.size(), 100u);
  EXPECT_EQ(line.forward_end, TerminationReason::closed_loop);
  EXPECT_EQ(line.backward_end, TerminationReason::closed_loop);  // skipped: loop complete
  EXPECT_EQ(line.seed_index, 0u);
  EXPECT_LT((line.points.back() - line.points.front()).norm() / 0.1, p.closing_distance);
  // The closing step ends within closing_distance + step (cells) of the seed: radius 30 cells.
  EXPECT_NEAR(line.times.back(), 2 * std::numbers::pi, (p.closing_distance + p.step) / 30.0);
}

// Saddle v = (x, -y): x(t) = x0 e^t, y(t) = y0 e^-t, so x y is constant along every line.
TEST(Integrator, SaddleLinesFollowHyperbolaeUpToTheBoundary) {
  const VectorField v = saddleField(squareGrid(201, -1.0, 1.0));
  for (const std::string method : {"rk2", "rk4", "rk45"}) {
    StreamlineParams p;
    p.integrator = fluidviz::choiceNamed<fluidviz::streamlines::Integrator>(method);
    for (const Vec3& seed : {Vec3(0.05, 0.9, 0), Vec3(-0.3, -0.2, 0), Vec3(0.6, -0.01, 0)}) {
      const Streamline line = traceStreamline(v, seed, p);
      const double c = seed.x() * seed.y();
      double dev = 0.0;
      for (const Vec3& q : line.points) dev = std::max(dev, std::abs(q.x() * q.y() - c));
      EXPECT_LT(dev, 1e-4) << method;
      EXPECT_EQ(line.forward_end, TerminationReason::domain_exit);
      EXPECT_EQ(line.backward_end, TerminationReason::domain_exit);
      // Forward leaves through x = +-1, backward through y = +-1.
      EXPECT_NEAR(std::abs(line.points.back().x()), 1.0, 1e-12) << method;
      EXPECT_NEAR(std::abs(line.points.front().y()), 1.0, 1e-12) << method;
      if (method == "rk4") std::printf("saddle rk4 seed (%g, %g): max |xy - c| = %.2e\n",
                                       seed.x(), seed.y(), dev);
    }
  }
}

// Exact exit point of a uniform flow from the centre of [0, 10]^2.
TEST(Integrator, DomainExitClipsTheLastPointToTheBoundary) {
  const VectorField v = uniformField(squareGrid(11, 0.0, 10.0), Vec3(1.0, 0.5, 0.0));
  const Streamline line = traceStreamline(v, Vec3(5.0, 5.0, 0.0), StreamlineParams{});
  EXPECT_EQ(line.forward_end, TerminationReason::domain_exit);
  EXPECT_EQ(line.backward_end, TerminationReason::domain_exit);
  EXPECT_NEAR((line.points.back() - Vec3(10.0, 7.5, 0.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((line.points.front() - Vec3(0.0, 2.5, 0.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(line.times.back(), 5.0, 1e-9);
  EXPECT_NEAR(line.times.front(), -5.0, 1e-9);
}

TEST(Integrator, MaxLengthAndMaxStepsEndTheLineWhereTheySay) {
  const VectorField v = uniformField(squareGrid(51, 0.0, 50.0), Vec3(0.6, 0.8, 0.0));
  StreamlineParams p;
  p.direction = fluidviz::streamlines::TraceDirection::forward;
  p.max_length = 7.3;
  Streamline line = traceStreamline(v, Vec3(10.0, 10.0, 0.0), p);
  EXPECT_EQ(line.reason(), TerminationReason::max_length);
  EXPECT_NEAR((line.points.back() - Vec3(10.0 + 0.6 * 7.3, 10.0 + 0.8 * 7.3, 0)).norm(), 0, 1e-9);
  p.max_length = 1000;
  p.max_steps = 5;
  line = traceStreamline(v, Vec3(10.0, 10.0, 0.0), p);
  EXPECT_EQ(line.reason(), TerminationReason::max_steps);
  EXPECT_EQ(line.points.size(), 6u);
  EXPECT_NEAR((line.points.back() - line.points.front()).norm(), 5 * p.step, 1e-12);
}

TEST(Integrator, ZeroFieldStopsAtOnceWithStagnation) {
  const VectorField v = uniformField(squareGrid(11, 0.0, 10.0), Vec3::Zero());
  const Streamline line = traceStreamline(v, Vec3(3.0, 4.0, 0.0), StreamlineParams{});
  ASSERT_EQ(line.points.size(), 1u);
  EXPECT_EQ(line.forward_end, TerminationReason::stagnation);
  EXPECT_EQ(line.backward_end, TerminationReason::stagnation);
  EXPECT_EQ(line.points[0], Vec3(3.0, 4.0, 0.0));
}

// A separatrix-like line on the stable manifold of the saddle runs into the critical point and
// stops where |v| <= stagnation_speed * max|v|.
TEST(Integrator, LineIntoASaddleStopsWithStagnationNearIt) {
  const VectorField v = saddleField(squareGrid(201, -1.0, 1.0));
  StreamlineParams p;
  p.direction = fluidviz::streamlines::TraceDirection::forward;
  p.stagnation_speed = 1e-3;
  const Streamline line = traceStreamline(v, Vec3(0.0, 0.9, 0.0), p);
  EXPECT_EQ(line.reason(), TerminationReason::stagnation);
  const double maxSpeed = std::sqrt(2.0);
  EXPECT_LE(line.speeds.back(), 1e-3 * maxSpeed);
  EXPECT_GT(line.speeds[line.speeds.size() - 2], 1e-3 * maxSpeed);
  EXPECT_NEAR(line.points.back().norm(), 1e-3 * maxSpeed, 0.25 * 0.01);  // within a step
  EXPECT_NEAR(line.points.back().x(), 0.0, 1e-12);
}

// NaN at the nodes of column i = 7 (x = 7): the forward line ends at the last finite point, in
// the cell before the NaN column's cells start influencing the interpolation (x in (6, 8)).
TEST(Integrator, NanInTheFieldEndsTheLineWithNanInField) {
  VectorField v = uniformField(squareGrid(11, 0.0, 10.0), Vec3(1.0, 0.0, 0.0));
  for (int j = 0; j < 11; ++j) v.values[v.grid.index(7, j)].x() = std::nan("");
  const Streamline line = traceStreamline(v, Vec3(2.0, 5.0, 0.0), StreamlineParams{});
  EXPECT_EQ(line.forward_end, TerminationReason::nan_in_field);
  EXPECT_EQ(line.backward_end, TerminationReason::domain_exit);
  EXPECT_LE(line.points.back().x(), 6.0);
  EXPECT_GT(line.points.back().x(), 6.0 - 1e-5);
  for (double s : line.speeds) EXPECT_TRUE(std::isfinite(s));
  const Streamline onNan = traceStreamline(v, Vec3(7.0, 5.0, 0.0), StreamlineParams{});
  EXPECT_TRUE(onNan.points.empty());
  EXPECT_EQ(onNan.reason(), TerminationReason::nan_in_field);
}

TEST(Integrator, SeedOutsideTheGridGivesAnEmptyLine) {
  const VectorField v = uniformField(squareGrid(11, 0.0, 10.0), Vec3(1.0, 0.0, 0.0));
  const Streamline line = traceStreamline(v, Vec3(-1.0, 5.0, 0.0), StreamlineParams{});
  EXPECT_TRUE(line.points.empty());
  EXPECT_EQ(line.forward_end, TerminationReason::domain_exit);
}

TEST(Integrator, BackwardOnlyEndsAtTheSeedWithDecreasingTimes) {
  const VectorField v = uniformField(squareGrid(11, 0.0, 10.0), Vec3(2.0, 0.0, 0.0));
  StreamlineParams p;
  p.direction = fluidviz::streamlines::TraceDirection::backward;
  const Streamline line = traceStreamline(v, Vec3(4.0, 5.0, 0.0), p);
  EXPECT_EQ(line.forward_end, TerminationReason::not_traced);
  EXPECT_EQ(line.backward_end, TerminationReason::domain_exit);
  EXPECT_EQ(line.reason(), TerminationReason::domain_exit);
  ASSERT_EQ(line.seed_index, line.points.size() - 1);
  EXPECT_EQ(line.points.back(), Vec3(4.0, 5.0, 0.0));
  EXPECT_NEAR(line.points.front().x(), 0.0, 1e-12);
  EXPECT_NEAR(line.times.front(), -2.0, 1e-12);  // 4 m at 2 m/s
  for (std::size_t i = 1; i < line.times.size(); ++i) EXPECT_GT(line.times[i], line.times[i - 1]);
}

// In 3D the z component is integrated; here the rotation is about z, so z stays constant.
TEST(Integrator, ThreeDimensionalRotationKeepsItsHeightAndCloses) {
  Grid g;
  g.dims = {41, 41, 5};
  g.origin = {-2, -2, 0};
  g.spacing = {0.1, 0.1, 0.25};
  const VectorField v = sampleField(g, [](const Vec3& p) { return Vec3(-p.y(), p.x(), 0.0); });
  const Streamline line = traceStreamline(v, Vec3(1.0, 0.0, 0.3), StreamlineParams{});
  EXPECT_EQ(line.reason(), TerminationReason::closed_loop);
  for (const Vec3& p : line.points) {
    EXPECT_NEAR(p.z(), 0.3, 1e-12);
    EXPECT_NEAR(p.head<2>().norm(), 1.0, 1e-8);
  }
}

// A 2D field whose values carry a z component still gives lines in its plane.
TEST(Integrator, TwoDimensionalFieldsStayInTheirPlane) {
  const VectorField v = uniformField(squareGrid(11, 0.0, 10.0), Vec3(1.0, 0.0, 3.0));
  const Streamline line = traceStreamline(v, Vec3(1.0, 5.0, 0.0), StreamlineParams{});
  EXPECT_EQ(line.forward_end, TerminationReason::domain_exit);
  for (const Vec3& p : line.points) EXPECT_EQ(p.z(), 0.0);
  EXPECT_NEAR(line.points.back().x(), 10.0, 1e-12);
}

TEST(Integrator, ParallelTracingEqualsOneByOne) {
  const VectorField v = saddleField(squareGrid(101, -1.0, 1.0));
  std::vector<Vec3> seeds;
  for (int i = 0; i < 40; ++i) seeds.emplace_back(-0.9 + 0.045 * i, 0.3 - 0.01 * i, 0.0);
  StreamlineParams p;
  p.integrator = fluidviz::streamlines::Integrator::rk45;
  const auto lines = traceStreamlines(v, seeds, p);
  ASSERT_EQ(lines.size(), seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const Streamline one = traceStreamline(v, seeds[i], p);
    EXPECT_EQ(lines[i].points, one.points);
    EXPECT_EQ(lines[i].times, one.times);
  }
}

TEST(Integrator, TerminationReasonNames) {
  EXPECT_STREQ(toString(TerminationReason::domain_exit), "domain_exit");
  EXPECT_STREQ(toString(TerminationReason::stagnation), "stagnation");
  EXPECT_STREQ(toString(TerminationReason::max_length), "max_length");
  EXPECT_STREQ(toString(TerminationReason::max_steps), "max_steps");
  EXPECT_STREQ(toString(TerminationReason::closed_loop), "closed_loop");
  EXPECT_STREQ(toString(TerminationReason::nan_in_field), "nan_in_field");
  EXPECT_STREQ(toString(TerminationReason::too_close), "too_close");
}

namespace {

// Longest segment of a line, in cells of the (isotropic) grid of spacing h.
double longestStepCells(const Streamline& line, double spacing) {
  double longest = 0.0;
  for (std::size_t i = 1; i < line.points.size(); ++i)
    longest = std::max(longest, (line.points[i] - line.points[i - 1]).norm() / spacing);
  return longest;
}

StreamlineParams withIntegrator(Integrator integrator) {
  StreamlineParams p;
  p.integrator = integrator;
  p.max_step = 0.5;
  return p;
}

}  // namespace

// Issue 15, defect 1: near a slow point one "0.25-cell" step used to jump 5-40 cells, because
// dt = h / |v(x_n)| was taken at the start and the stages then ran with the faster velocities
// further out. Seeds 0.05 to 0.5 cells from the saddle of v = (x, -y) (where separatrices start)
// and all over a slowly decaying spiral sink: no segment may exceed `step` (fixed-step methods)
// or `max_step` (rk45) by more than 1%.
TEST(Integrator, NoStepIsLongerThanTheSetStepNearSlowPoints) {
  const double spacing = 0.01;
  const VectorField saddle = saddleField(squareGrid(201, -1.0, 1.0));
  const VectorField sink = sampleField(squareGrid(201, -1.0, 1.0), [](const Vec3& p) {
    return Vec3(-0.05 * p.x() - p.y(), p.x() - 0.05 * p.y(), 0.0);
  });
  for (const Integrator integrator : {Integrator::rk2, Integrator::rk4, Integrator::rk45}) {
    const StreamlineParams p = withIntegrator(integrator);
    const double bound = 1.01 * (integrator == Integrator::rk45 ? p.max_step : p.step);
    for (const double r : {0.05, 0.1, 0.2, 0.5})
      for (int a = 0; a < 8; ++a) {
        const double angle = 0.3 + a * std::numbers::pi / 4;
        const Vec3 seed(r * spacing * std::cos(angle), r * spacing * std::sin(angle), 0.0);
        const Streamline line = traceStreamline(saddle, seed, p);
        EXPECT_LE(longestStepCells(line, spacing), bound)
            << choiceName(integrator) << " saddle, seed " << r << " cells at angle " << angle;
      }
    for (const double r : {0.3, 0.6, 0.9}) {
      const Streamline line = traceStreamline(sink, Vec3(r, 0.0, 0.0), p);
      EXPECT_LE(longestStepCells(line, spacing), bound)
          << choiceName(integrator) << " spiral sink, seed at " << r << " m";
    }
  }
}

// Issue 15, defect 2: a line that reaches a sink it cannot resolve (here the converging line
// x = 4.5 between +1 and -1 columns, where |v| rises linearly from 0, so that the steps never
// land where |v| <= stagnation_speed * max|v|) used to be written out until max_steps. It must
// end with reason stagnation, within a step of the sink, after a few steps.
TEST(Integrator, LineStuckAtASinkItCannotResolveEndsWithStagnation) {
  VectorField v = uniformField(squareGrid(11, 0.0, 10.0), Vec3(1.0, 0.0, 0.0));
  for (int j = 0; j < 11; ++j)
    for (int i = 5; i < 11; ++i) v.values[v.grid.index(i, j)] = Vec3(-1.0, 0.0, 0.0);
  for (const Integrator integrator : {Integrator::rk2, Integrator::rk4, Integrator::rk45}) {
    StreamlineParams p = withIntegrator(integrator);
    p.direction = TraceDirection::forward;
    for (const double x0 : {1.1, 1.13, 2.0}) {
      const Streamline line = traceStreamline(v, Vec3(x0, 5.0, 0.0), p);
      EXPECT_EQ(line.reason(), TerminationReason::stagnation)
          << choiceName(integrator) << " seed x = " << x0 << ": " << toString(line.reason());
      EXPECT_LT(line.points.size(), 40u) << choiceName(integrator) << " seed x = " << x0;
      EXPECT_NEAR(line.points.back().x(), 4.5, p.step) << choiceName(integrator);
    }
  }
}

// A line into a spiral sink spirals in and ends there (stagnation) within a cell of the sink,
// instead of running to max_length around it.
TEST(Integrator, LineIntoASpiralSinkEndsAtTheSink) {
  const double spacing = 0.01;
  const VectorField sink = sampleField(squareGrid(201, -1.0, 1.0), [](const Vec3& p) {
    return Vec3(-0.3 * p.x() - p.y(), p.x() - 0.3 * p.y(), 0.0);
  });
  for (const Integrator integrator : {Integrator::rk2, Integrator::rk4, Integrator::rk45}) {
    StreamlineParams p = withIntegrator(integrator);
    p.direction = TraceDirection::forward;
    const Streamline line = traceStreamline(sink, Vec3(0.5, 0.2, 0.0), p);
    EXPECT_EQ(line.reason(), TerminationReason::stagnation) << choiceName(integrator);
    EXPECT_LT(line.points.back().norm() / spacing, 1.0) << choiceName(integrator);
  }
}
