// 3D streamlines (issue 15): the shared integrator (trilinear sampling, arc-length RK4/RK45)
// against VTK's vtkStreamTracer in 3D, classical RK4 at the same fixed step in cells, forward
// from the same seeds, on the ABC flow and on a real 3D flow (the office room, read as fluidviz
// reads it). Endpoints are compared as points (as in RealDatasets_test.cpp): >= 95% within 1
// cell; no step is longer than the step (+1%). RK45 is checked against a fine RK4 reference.
#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <cstdio>
#include <string>

#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/streamlines/Seeding.h"
#include "filters/streamlines/Streamline.h"
#include "tests/support/AnalyticFields.h"
#include "tests/support/VtkStreamTracerPeer.h"

namespace fluidviz::streamlines {
namespace {

using fluidviz::testing::maxSpeed;

// Seeds filling the middle of the grid: nx^3 at the cell centres of a lattice over the domain.
std::vector<Vec3> boxSeeds(const Grid& g, int n) { return seedGrid(g, n, n, n); }

struct Agreement {
  int within = 0;
  double worst = 0, longest = 0;
};

Agreement compareWithPeer(const VectorField& field, const std::vector<Vec3>& seeds, double step,
                          double maxLength) {
  const double dx = field.grid.spacing[0];
  const StreamlineParams p = testing::peerTwinParams(step, maxLength);
  const std::vector<Streamline> ours = traceStreamlines(field, seeds, p);
  const std::vector<Vec3> theirs = testing::peerEndpoints(
      testing::peerImageOf(field), seeds, step, maxLength, p.stagnation_speed * maxSpeed(field));
  Agreement a;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    const double apart = (ours[s].points.back() - theirs[s]).norm() / dx;
    a.within += apart <= 1.0;
    a.worst = std::max(a.worst, apart);
    for (std::size_t k = 1; k < ours[s].points.size(); ++k)
      a.longest = std::max(a.longest, (ours[s].points[k] - ours[s].points[k - 1]).norm() / dx);
  }
  return a;
}

TEST(StreamTracerAgreement3D, AbcFlowRk4EndpointsAgreeWithVtkAndNoStepIsTooLong) {
  const VectorField field = testing::abcFlow(32);
  const std::vector<Vec3> seeds = boxSeeds(field.grid, 5);
  const double step = 0.25, maxLength = 40.0;
  const Agreement a = compareWithPeer(field, seeds, step, maxLength);
  std::printf("ABC 32^3: %d of %zu endpoints within 1 cell of vtkStreamTracer's (worst %.3g "
              "cells); longest step %.4f cells\n",
              a.within, seeds.size(), a.worst, a.longest);
  EXPECT_GE(a.within, 0.95 * seeds.size());
  EXPECT_LE(a.longest, 1.01 * step);
}

// RK45 (tolerance 1e-8 per cell) against classical RK4 at a 0.005-cell step on the same
// trilinear field, whose error (~h^4) is far below the tolerance checked.
TEST(StreamTracerAgreement3D, AbcFlowRk45LineMatchesFineRk4Reference) {
  const VectorField field = testing::abcFlow(32);
  const std::vector<Vec3> seeds = boxSeeds(field.grid, 3);
  StreamlineParams fine = testing::peerTwinParams(0.005, 20.0);
  StreamlineParams adaptive = fine;
  adaptive.integrator = Integrator::rk45;
  adaptive.step = 0.1;
  adaptive.min_step = 1e-4;
  adaptive.max_step = 1.0;
  adaptive.tolerance = 1e-8;
  const auto reference = traceStreamlines(field, seeds, fine);
  const auto lines = traceStreamlines(field, seeds, adaptive);
  double worst = 0, longest = 0;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    worst = std::max(worst, (lines[s].points.back() - reference[s].points.back()).norm() /
                                field.grid.spacing[0]);
    for (std::size_t k = 1; k < lines[s].points.size(); ++k)
      longest = std::max(longest, (lines[s].points[k] - lines[s].points[k - 1]).norm() /
                                      field.grid.spacing[0]);
  }
  std::printf("ABC RK45 vs fine RK4 after 20 cells: worst endpoint %.3g cells; longest step "
              "%.3f cells\n", worst, longest);
  EXPECT_LE(worst, 0.005);
  EXPECT_LE(longest, 1.01 * adaptive.max_step);
}

TEST(StreamTracerAgreement3D, OfficeRoomRk4EndpointsAgreeWithVtk) {
  const std::string path = std::string(FLUIDVIZ_TEST_DATA_DIR) + "/vtkdata/office.binary.vtk";
  VectorField field = vectorFieldFrom(readImageData(path), "vectors", path);
  field.name = "velocity";
  const auto& h = field.grid.spacing;
  ASSERT_DOUBLE_EQ(h[0], h[1]);
  ASSERT_DOUBLE_EQ(h[0], h[2]) << "the peer's step unit needs cubic cells";
  const std::vector<Vec3> seeds = boxSeeds(field.grid, 6);
  const double step = 0.25, maxLength = 200.0;
  const Agreement a = compareWithPeer(field, seeds, step, maxLength);
  std::printf("office %d x %d x %d: %d of %zu endpoints within 1 cell of vtkStreamTracer's "
              "(worst %.3g cells); longest step %.4f cells\n",
              field.grid.dims[0], field.grid.dims[1], field.grid.dims[2], a.within, seeds.size(),
              a.worst, a.longest);
  EXPECT_GE(a.within, 0.95 * seeds.size());
  EXPECT_LE(a.longest, 1.01 * step);
}

}  // namespace
}  // namespace fluidviz::streamlines
