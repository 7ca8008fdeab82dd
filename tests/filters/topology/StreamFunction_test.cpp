// Stream function of incompressible planar flows and agreement of the two topological views.
// Reference: cellular flow psi = sin(pi x) sin(pi y), u = dpsi/dy, v = -dpsi/dx, on
// [-0.313, 2.271]^2 (so that the boundary values are not trivial and no critical point sits on a
// node). psi is known up to a constant: compared after matching psi at the grid origin.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "filters/topology/ScalarCriticalPoints.h"
#include "filters/topology/StreamFunction.h"
#include "filters/topology/TopologyAgreement.h"
#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

constexpr double kLo = -0.313, kHi = 2.271;

double cellularPsi(double x, double y) { return std::sin(std::numbers::pi * x) * std::sin(std::numbers::pi * y); }
Vec2 cellularVelocity(double x, double y) {
  return {std::numbers::pi * std::sin(std::numbers::pi * x) * std::cos(std::numbers::pi * y), -std::numbers::pi * std::cos(std::numbers::pi * x) * std::sin(std::numbers::pi * y)};
}

double maxPsiError(int n) {
  const Grid g = squareGrid(n, kLo, kHi);
  const StreamFunctionResult r = computeStreamFunction(sampleField(g, cellularVelocity), {});
  const double offset = cellularPsi(kLo, kLo) - r.psi.values[0];
  double err = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3 p = g.position(i, j);
      err = std::max(err, std::abs(r.psi.values[g.index(i, j)] + offset - cellularPsi(p.x(), p.y())));
    }
  return err;
}

}  // namespace

// Second order: the max error falls 4x per halving of the spacing (measured 4.013, 3.988, 4.001
// from 17 to 129 nodes; 2.27e-3 at 65 and 5.67e-4 at 129 nodes, max |psi| = 1).
TEST(StreamFunction, CellularFlowIsRecoveredToSecondOrder) {
  const double e33 = maxPsiError(33), e65 = maxPsiError(65), e129 = maxPsiError(129);
  EXPECT_NEAR(e33 / e65, 4.0, 0.3);
  EXPECT_NEAR(e65 / e129, 4.0, 0.3);
  EXPECT_LT(e129, 7e-4);
}

TEST(StreamFunction, BoundaryFluxMismatchIsTheNetOutflow) {
  const Grid g = squareGrid(21, 0.0, 1.0);
  // Incompressible: the boundary integral closes (trapezoidal rule on a smooth periodic-like
  // field: round-off only).
  EXPECT_LT(std::abs(computeStreamFunction(sampleField(g, cellularVelocity), {})
                         .boundary_flux_mismatch),
            1e-12);
  // v = (x, y): div v = 2, net outflow through the unit square = 2 (trapezoid exact for linear).
  const auto r = computeStreamFunction(
      sampleField(g, [](double x, double y) { return Vec2(x, y); }), {});
  EXPECT_NEAR(r.boundary_flux_mismatch, 2.0, 1e-12);
}

TEST(StreamFunction, DirectAndConjugateGradientSolversAgree) {
  const VectorField f = sampleField(squareGrid(65, kLo, kHi), cellularVelocity);
  TopologyParams direct, cg;
  direct.stream_function_solver = fluidviz::topology::StreamFunctionSolver::direct;
  cg.stream_function_solver = fluidviz::topology::StreamFunctionSolver::cg;
  cg.stream_function_tolerance = 1e-12;
  const auto a = computeStreamFunction(f, direct);
  const auto b = computeStreamFunction(f, cg);
  EXPECT_GT(b.iterations, 0);
  EXPECT_LT(a.relative_residual, 1e-12);
  EXPECT_LT(b.relative_residual, 1e-10);
  double diff = 0.0;
  for (std::size_t k = 0; k < a.psi.values.size(); ++k)
    diff = std::max(diff, std::abs(a.psi.values[k] - b.psi.values[k]));
  EXPECT_LT(diff, 1e-8);
}

// Both views of the cellular flow: 9 saddles (integer points) and 4 centres (half-integer
// points) of the velocity; 9 saddles, 2 maxima (psi = +1) and 2 minima (psi = -1) of psi, at the
// same places (analytic positions within 0.01 cell in both views).
TEST(StreamFunction, CriticalPointsOfPsiAgreeWithThoseOfTheVelocity) {
  const Grid g = squareGrid(65, kLo, kHi);
  const VectorField f = sampleField(g, cellularVelocity);
  const auto velocity = findCriticalPoints(f, {});
  const auto psi = findScalarCriticalPoints(computeStreamFunction(f, {}).psi, {});
  ASSERT_EQ(velocity.size(), 13u);
  ASSERT_EQ(psi.size(), 13u);
  const double h = g.spacing[0];
  auto nearestInteger2 = [](const Vec3& p) {  // analytic points lie on the half-integer lattice
    return Vec2(std::round(2 * p.x()) / 2, std::round(2 * p.y()) / 2);
  };
  int saddles = 0, centres = 0, maxima = 0, minima = 0;
  for (const auto& p : velocity) {
    const Vec2 a = nearestInteger2(p.position);
    EXPECT_LT((Vec2(p.position.x(), p.position.y()) - a).norm() / h, 0.01);
    const bool integer = std::abs(a.x() - std::round(a.x())) < 1e-9;
    EXPECT_EQ(p.type, integer ? CriticalPointType::Saddle : CriticalPointType::Centre);
    saddles += p.type == CriticalPointType::Saddle;
    centres += p.type == CriticalPointType::Centre;
  }
  for (const auto& s : psi) {
    const Vec2 a = nearestInteger2(s.position);
    EXPECT_LT((Vec2(s.position.x(), s.position.y()) - a).norm() / h, 0.01);
    const double value = cellularPsi(a.x(), a.y());
    const ScalarCriticalType expected = std::abs(value) < 0.5 ? ScalarCriticalType::Saddle
                                        : value > 0           ? ScalarCriticalType::Maximum
                                                              : ScalarCriticalType::Minimum;
    EXPECT_EQ(s.type, expected) << toString(s.type) << " at " << a.transpose();
    maxima += s.type == ScalarCriticalType::Maximum;
    minima += s.type == ScalarCriticalType::Minimum;
  }
  EXPECT_EQ(saddles, 9);
  EXPECT_EQ(centres, 4);
  EXPECT_EQ(maxima, 2);
  EXPECT_EQ(minima, 2);
  const TopologyAgreement agreement = compareVelocityAndStreamFunction(velocity, psi, g);
  EXPECT_TRUE(agreement.agree());
  EXPECT_EQ(agreement.matches.size(), 13u);
  for (const ViewMatch& m : agreement.matches) EXPECT_LT(m.distance, 0.02);
}

// The velocity field of psi = x^3 - 3xy^2 has a monkey saddle; psi computed from it has a
// degenerate saddle of index -2 at the same place (within one cell), not two saddles.
TEST(StreamFunction, MonkeySaddleOfTheVelocityIsADegenerateSaddleOfPsi) {
  const Grid g = squareGrid(41, -1.0, 1.0);
  const double h = g.spacing[0];
  for (const Vec2& x0 : {Vec2(0, 0), Vec2(0.37 * h, -0.23 * h)}) {
    const VectorField f = sampleField(g, [&](double x, double y) {
      x -= x0.x();
      y -= x0.y();
      return Vec2(-6 * x * y, 3 * y * y - 3 * x * x);
    });
    const auto velocity = findCriticalPoints(f, {});
    const auto psi = findScalarCriticalPoints(computeStreamFunction(f, {}).psi, {});
    ASSERT_EQ(velocity.size(), 1u);
    ASSERT_EQ(psi.size(), 1u);
    EXPECT_EQ(velocity[0].type, CriticalPointType::MonkeySaddle);
    EXPECT_EQ(psi[0].type, ScalarCriticalType::DegenerateSaddle);
    EXPECT_EQ(psi[0].index, -2);
    EXPECT_FALSE(psi[0].morse);
    EXPECT_LT((Vec2(psi[0].position.x(), psi[0].position.y()) - x0).norm() / h, 1.0);
    const TopologyAgreement agreement = compareVelocityAndStreamFunction(velocity, psi, g);
    EXPECT_TRUE(agreement.agree());
    ASSERT_EQ(agreement.matches.size(), 1u);
  }
}

// A mismatching pair is reported: a centre whose partner is a saddle does not agree.
TEST(StreamFunction, AgreementDetectsTypeMismatches) {
  CriticalPoint centre;
  centre.type = CriticalPointType::Centre;
  centre.morse = true;
  centre.index = 1;
  centre.jacobian << 0, -1, 1, 0;  // counter-clockwise: must pair with a maximum
  ScalarCriticalPoint maximum, minimum, saddle;
  maximum.type = ScalarCriticalType::Maximum;
  maximum.index = 1;
  maximum.morse = true;
  minimum = maximum;
  minimum.type = ScalarCriticalType::Minimum;
  saddle.type = ScalarCriticalType::Saddle;
  saddle.index = -1;
  saddle.morse = true;
  EXPECT_TRUE(correspondingTypes(centre, maximum));
  EXPECT_FALSE(correspondingTypes(centre, minimum));
  EXPECT_FALSE(correspondingTypes(centre, saddle));
  const Grid g = squareGrid(11, 0, 1);
  centre.position = {0.5, 0.5, 0};
  saddle.position = {0.52, 0.5, 0};
  EXPECT_FALSE(compareVelocityAndStreamFunction({centre}, {saddle}, g).agree());
  // The minimum is far from the centre: both unmatched. (The maximum, left at the grid's corner,
  // is within the boundary margin and not compared.)
  minimum.position = {0.9, 0.1, 0};
  const auto r = compareVelocityAndStreamFunction({centre}, {maximum, minimum}, g, 1.0, 0.5);
  EXPECT_EQ(r.unmatched_velocity.size(), 1u);
  EXPECT_EQ(r.unmatched_stream_function.size(), 1u);
  EXPECT_FALSE(r.agree());
}

// A 3D field: psi of the requested slice is the 2D stream function of that slice.
TEST(StreamFunction, ZSliceOfA3DField) {
  const Grid g2 = squareGrid(33, kLo, kHi);
  Grid g3 = g2;
  g3.dims[2] = 2;
  g3.spacing[2] = 0.5;
  VectorField f3{"v", g3, {}};
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 33; ++j)
      for (int i = 0; i < 33; ++i) {
        const Vec3 p = g3.position(i, j, k);
        const Vec2 w = cellularVelocity(p.x(), p.y()) * (k == 1 ? 2.0 : 1.0);
        f3.values.emplace_back(w.x(), w.y(), 1.0);
      }
  TopologyParams params;
  params.slice_index = 1;
  const auto r3 = computeStreamFunction(f3, params);
  const auto r2 = computeStreamFunction(sampleField(g2, cellularVelocity), {});
  ASSERT_EQ(r3.psi.values.size(), r2.psi.values.size());
  EXPECT_EQ(r3.psi.grid.dims[2], 1);
  EXPECT_DOUBLE_EQ(r3.psi.grid.origin[2], 0.5);
  for (std::size_t k = 0; k < r2.psi.values.size(); ++k)
    EXPECT_NEAR(r3.psi.values[k], 2.0 * r2.psi.values[k], 1e-12);
}
