// fvStreamlineFilter in a VTK pipeline and the .vtp layout of streamlines (StreamlinePolyData.h):
// arrays, reason codes with their legend, seeds from a source or from SeedingParams, errors.
#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <cmath>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"
#include "filters/streamlines/vtk/fvStreamlineFilter.h"
#include "tests/support/AnalyticFields.h"

namespace fluidviz::streamlines {
namespace {

vtkSmartPointer<vtkImageData> imageOf(const VectorField& v) {
  FieldSet set;
  set.grid = v.grid;
  set.add(v);
  return toImageData(set);
}

vtkSmartPointer<vtkPolyData> points(const std::vector<Vec3>& ps) {
  vtkNew<vtkPoints> pts;
  for (const Vec3& p : ps) pts->InsertNextPoint(p.data());
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pts);
  return data;
}

int cellValue(vtkPolyData* d, const char* array, vtkIdType cell) {
  auto* a = vtkIntArray::SafeDownCast(d->GetCellData()->GetArray(array));
  EXPECT_NE(a, nullptr) << array;
  return a ? a->GetValue(cell) : -1;
}

class StreamlineFilterErrors : public ::testing::Test {  // VTK reports these errors too: keep it quiet
 protected:
  void SetUp() override { vtkObject::GlobalWarningDisplayOff(); }
  void TearDown() override { vtkObject::GlobalWarningDisplayOn(); }
};

// Rigid rotation v = (-y, x) (reproduced exactly by bilinear interpolation): circles of period
// 2 pi on which |v| = r.
TEST(StreamlineFilter, SeedSourceGivesClosedCirclesWithSpeedTimeAndReasonArrays) {
  vtkNew<fvStreamlineFilter> filter;
  filter->SetInputData(imageOf(testing::rotationField(testing::squareGrid(41, -1.0, 1.0))));
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  filter->SetSourceData(points({{0.5, 0.0, 0.0}, {0.0, -0.8, 0.0}}));
  StreamlineParams p;
  p.step = 0.05;
  p.direction = fluidviz::streamlines::TraceDirection::forward;
  filter->SetIntegration(p);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  EXPECT_EQ(filter->GetLastError(), "");
  ASSERT_EQ(out->GetNumberOfLines(), 2);
  auto* names = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("reason_names"));
  ASSERT_NE(names, nullptr);
  const double radius[2] = {0.5, 0.8};
  vtkNew<vtkIdList> ids;
  out->GetLines()->InitTraversal();
  for (vtkIdType c = 0; c < 2; ++c) {
    EXPECT_EQ(names->GetValue(cellValue(out, "reason", c)), "closed_loop");
    EXPECT_EQ(cellValue(out, "reason", c), static_cast<int>(TerminationReason::closed_loop));
    EXPECT_EQ(cellValue(out, "seed_id", c), c);
    out->GetLines()->GetNextCell(ids);
    auto* speed = out->GetPointData()->GetArray("speed");
    auto* time = out->GetPointData()->GetArray("integration_time");
    double worstSpeed = 0;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      double q[3];
      out->GetPoint(ids->GetId(k), q);
      // On the circle, at speed r (RK4 at step 0.05 cells: radius drift far below 1e-6).
      EXPECT_NEAR(std::hypot(q[0], q[1]), radius[c], 1e-6);
      worstSpeed = std::max(worstSpeed, std::abs(speed->GetTuple1(ids->GetId(k)) - radius[c]));
    }
    EXPECT_LT(worstSpeed, 1e-6);
    EXPECT_EQ(time->GetTuple1(ids->GetId(0)), 0.0);
    // One turn takes 2 pi s; the loop closes within closing_distance (0.1 cell = 0.005 m) of the
    // seed, i.e. within 0.005 / r rad of a full turn.
    EXPECT_NEAR(time->GetTuple1(ids->GetId(ids->GetNumberOfIds() - 1)), 2 * M_PI,
                0.005 / radius[c] + 1e-3);
  }
}

TEST(StreamlineFilter, WithoutSourceTheSeedingParamsPlaceTheSeedsAndActiveVectorsAreUsed) {
  vtkNew<fvStreamlineFilter> filter;
  filter->SetInputData(imageOf(testing::uniformField(testing::squareGrid(11, 0.0, 1.0), {1, 0, 0})));
  SeedingParams s;
  s.strategy = fluidviz::streamlines::SeedStrategy::line;
  s.line_start = {0.5, 0.1, 0};
  s.line_end = {0.5, 0.9, 0};
  s.line_count = 5;
  filter->SetSeeding(s);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  ASSERT_EQ(out->GetNumberOfLines(), 5);
  vtkNew<vtkIdList> ids;
  out->GetLines()->InitTraversal();
  for (vtkIdType c = 0; c < 5; ++c) {
    out->GetLines()->GetNextCell(ids);
    // Both directions to the walls x = 0 and x = 1: the line runs across the whole box.
    double first[3], last[3];
    out->GetPoint(ids->GetId(0), first);
    out->GetPoint(ids->GetId(ids->GetNumberOfIds() - 1), last);
    EXPECT_NEAR(first[0], 0.0, 1e-9);
    EXPECT_NEAR(last[0], 1.0, 1e-9);
    EXPECT_NEAR(first[1], 0.1 + 0.2 * c, 1e-12);
    EXPECT_EQ(cellValue(out, "reason", c), static_cast<int>(TerminationReason::domain_exit));
    EXPECT_EQ(cellValue(out, "reason_backward", c),
              static_cast<int>(TerminationReason::domain_exit));
  }
}

// The filter masks what `fluidviz streamlines` masks (defaultFlowMask in 2D): a column of zeros
// in the image's vtkValidPointMask at x = 0.7 stops the lines of a uniform flow along x there
// (reason nan_in_field), within the cell before it: the bilinear value is NaN beyond x = 0.6.
TEST(StreamlineFilter, LinesEndAtTheImagesValidPointMaskAsTheCommandsDo) {
  const VectorField v = testing::uniformField(testing::squareGrid(11, 0.0, 1.0), {1, 0, 0});
  ScalarField valid{kValidPointMaskArray, v.grid, std::vector<double>(v.values.size(), 1.0)};
  for (int j = 0; j < 11; ++j) valid.values[v.grid.index(7, j)] = 0.0;
  FieldSet set;
  set.grid = v.grid;
  set.add(v);
  set.add(valid);
  vtkNew<fvStreamlineFilter> filter;
  filter->SetInputData(toImageData(set));
  SeedingParams s;
  s.strategy = fluidviz::streamlines::SeedStrategy::line;
  s.line_start = {0.45, 0.1, 0};
  s.line_end = {0.45, 0.9, 0};
  s.line_count = 3;
  filter->SetSeeding(s);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  ASSERT_EQ(filter->GetLastError(), "");
  ASSERT_EQ(out->GetNumberOfLines(), 3);
  vtkNew<vtkIdList> ids;
  out->GetLines()->InitTraversal();
  for (vtkIdType c = 0; c < 3; ++c) {
    out->GetLines()->GetNextCell(ids);
    double last[3];
    out->GetPoint(ids->GetId(ids->GetNumberOfIds() - 1), last);
    EXPECT_GE(last[0], 0.6 - 0.025);  // within one step (0.25 cells) of x = 0.6
    EXPECT_LE(last[0], 0.6 + 1e-12);
    EXPECT_EQ(cellValue(out, "reason", c), static_cast<int>(TerminationReason::nan_in_field));
    EXPECT_EQ(cellValue(out, "reason_backward", c),
              static_cast<int>(TerminationReason::domain_exit));
  }
}

TEST(StreamlinePolyData, ZeroFieldLinesAreTheirSeedsAndOutsideSeedsHaveNoCell) {
  const VectorField zero = testing::uniformField(testing::squareGrid(5, 0.0, 1.0), {0, 0, 0});
  const auto lines = traceStreamlines(zero, {{0.5, 0.5, 0}, {2.0, 2.0, 0}, {0.25, 0.75, 0}},
                                      StreamlineParams{});
  vtkSmartPointer<vtkPolyData> poly = streamlinesToPolyData(lines);
  ASSERT_EQ(poly->GetNumberOfLines(), 2);  // the seed outside the grid has no points
  EXPECT_EQ(poly->GetNumberOfPoints(), 4);  // each seed twice: a zero-length polyline
  poly->BuildLinks();  // VTK accepts the cells (it rejects polylines of one point)
  EXPECT_EQ(poly->GetCell(1)->GetNumberOfPoints(), 2);
  EXPECT_EQ(cellValue(poly, "reason", 0), static_cast<int>(TerminationReason::stagnation));
  EXPECT_EQ(cellValue(poly, "reason", 1), static_cast<int>(TerminationReason::stagnation));
  EXPECT_EQ(cellValue(poly, "seed_id", 0), 0);
  EXPECT_EQ(cellValue(poly, "seed_id", 1), 2);
  EXPECT_EQ(summarizeReasons(lines), "domain_exit 1, stagnation 2");
  const auto drawn = polylinePoints(poly);
  ASSERT_EQ(drawn.size(), 2u);
  EXPECT_EQ(drawn[1], std::vector<Vec3>(2, Vec3(0.25, 0.75, 0)));
}

TEST_F(StreamlineFilterErrors, MissingOrScalarArrayIsAnErrorNamingTheArraysPresent) {
  FieldSet set;
  set.grid = testing::squareGrid(5, 0.0, 1.0);
  set.add(testing::uniformField(set.grid, {1, 0, 0}));
  set.add(ScalarField{"density", set.grid, std::vector<double>(25, 1.0)});
  vtkNew<fvStreamlineFilter> filter;
  filter->SetInputData(toImageData(set));
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "vel");
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfLines(), 0);
  EXPECT_NE(filter->GetLastError().find("no point-data array 'vel'; arrays present: "
                                        "velocity(3), density(1)"),
            std::string::npos)
      << filter->GetLastError();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "density");
  filter->Update();
  EXPECT_NE(filter->GetLastError().find("array 'density' has 1 component; a vector field needs 2 or 3"),
            std::string::npos)
      << filter->GetLastError();
  StreamlineParams bad;
  bad.step = 0;
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  filter->SetIntegration(bad);
  filter->Update();
  EXPECT_NE(filter->GetLastError().find("parameter step is 0 cells, outside the allowed range (0, 100]"),
            std::string::npos)
      << filter->GetLastError();
}

}  // namespace
}  // namespace fluidviz::streamlines
