// The thin VTK layer of the topology core: poly data layout (TopologyPolyData.h) and the
// fvTopologyFilter algorithm (image in, critical points on port 0, separatrices on port 1).
// Every array value must be the core's value for the same point (exact: only copied).
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <cmath>
#include <limits>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/VectorFieldTopology.h"
#include "filters/topology/vtk/TopologyPolyData.h"
#include "filters/topology/vtk/fvTopologyFilter.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

// Cellular flow psi = sin(pi x) sin(pi y) on [-1, 1]^2 plus a weak strain: centres at
// (+-1/2, +-1/2), saddles at the origin and on the edges; separatrices connect the saddles.
Vec2 cellular(double x, double y) {
  const double k = M_PI;
  return {k * std::sin(k * x) * std::cos(k * y) + 0.05 * x,
          -k * std::cos(k * x) * std::sin(k * y) - 0.05 * y};
}

VectorField testField(int layers = 1) {
  Grid g = squareGrid(61, -1.0, 1.0);
  g.dims[2] = layers;
  g.spacing[2] = 0.5;
  VectorField v = sampleField(g, cellular);
  v.name = "velocity";
  return v;
}

vtkSmartPointer<vtkImageData> imageOf(const VectorField& v) {
  FieldSet set;
  set.grid = v.grid;
  set.add(v);
  set.add(magnitude(v, "speed"));
  return toImageData(set);
}

double value(vtkPolyData* d, const char* name, vtkIdType i) {
  vtkDataArray* a = d->GetPointData()->GetArray(name);
  return a ? a->GetTuple1(i) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

TEST(TopologyPolyData, CriticalPointArraysAreTheCoresValues) {
  const VectorField field = testField();
  const std::vector<CriticalPoint> points = findCriticalPoints(field, {});
  ASSERT_GE(points.size(), 5u);
  vtkSmartPointer<vtkPolyData> d = criticalPointsToPolyData(points);
  ASSERT_EQ(d->GetNumberOfPoints(), static_cast<vtkIdType>(points.size()));
  EXPECT_EQ(d->GetNumberOfVerts(), static_cast<vtkIdType>(points.size()));
  auto* type = vtkStringArray::SafeDownCast(d->GetPointData()->GetAbstractArray("type"));
  ASSERT_NE(type, nullptr);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CriticalPoint& p = points[i];
    const auto id = static_cast<vtkIdType>(i);
    double xyz[3];
    d->GetPoint(id, xyz);
    EXPECT_EQ(Vec3(xyz[0], xyz[1], xyz[2]), p.position);
    EXPECT_EQ(type->GetValue(id), p.typeName());
    EXPECT_EQ(value(d, "type_code", id), static_cast<int>(p.type));
    EXPECT_EQ(value(d, "index", id), p.index);
    EXPECT_EQ(value(d, "morse", id), p.morse ? 1 : 0);
    EXPECT_EQ(value(d, "det", id), p.det);
    EXPECT_EQ(value(d, "trace", id), p.trace);
    EXPECT_EQ(value(d, "normalized_det", id), p.normalized_det);
    EXPECT_EQ(value(d, "hyperbolic", id), p.sectors.hyperbolic);
    EXPECT_EQ(value(d, "elliptic", id), p.sectors.elliptic);
    EXPECT_EQ(value(d, "parabolic", id), p.sectors.parabolic);
    EXPECT_EQ(value(d, "index_measured", id), p.index_measured ? 1 : 0);
    EXPECT_EQ(value(d, "cluster_size", id), p.cluster_size);
  }
  // The code legend names every type at its code.
  auto* names = vtkStringArray::SafeDownCast(d->GetFieldData()->GetAbstractArray("type_names"));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->GetValue(static_cast<int>(CriticalPointType::Saddle)), "saddle");
  EXPECT_EQ(names->GetValue(static_cast<int>(CriticalPointType::MonkeySaddle)), "monkey_saddle");
  EXPECT_EQ(names->GetValue(static_cast<int>(CriticalPointType::Unknown)), "unknown");
}

TEST(TopologyPolyData, SeparatricesArePolylinesWithTheirOriginAndEnd) {
  const VectorField field = testField();
  const std::vector<CriticalPoint> points = findCriticalPoints(field, {});
  const std::vector<Separatrix> seps = computeSeparatrices(field, points, {});
  ASSERT_GE(seps.size(), 4u);
  vtkSmartPointer<vtkPolyData> d = separatricesToPolyData(seps);
  ASSERT_EQ(d->GetNumberOfLines(), static_cast<vtkIdType>(seps.size()));
  vtkCellData* cd = d->GetCellData();
  vtkNew<vtkIdList> ids;
  for (std::size_t s = 0; s < seps.size(); ++s) {
    const auto c = static_cast<vtkIdType>(s);
    EXPECT_EQ(cd->GetArray("origin")->GetTuple1(c), seps[s].origin);
    EXPECT_EQ(cd->GetArray("outgoing")->GetTuple1(c), seps[s].start.outflow ? 1 : 0);
    EXPECT_EQ(cd->GetArray("end")->GetTuple1(c), static_cast<int>(seps[s].end));
    EXPECT_EQ(cd->GetArray("end_point")->GetTuple1(c),
              seps[s].end == SeparatrixEnd::CriticalPoint ? seps[s].end_point : -1);
    d->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), static_cast<vtkIdType>(seps[s].points.size()));
    double first[3];
    d->GetPoint(ids->GetId(0), first);
    EXPECT_EQ(Vec3(first[0], first[1], first[2]), seps[s].points.front());
  }
  // The saddle at the origin connects to its neighbours: some separatrix ends at a point.
  int connected = 0;
  for (const Separatrix& s : seps) connected += s.end == SeparatrixEnd::CriticalPoint;
  EXPECT_GE(connected, 1);
}

TEST(fvTopologyFilter, ChosenArrayGivesTheCoresPointsAndSeparatrices) {
  const VectorField field = testField();
  vtkSmartPointer<vtkImageData> image = imageOf(field);
  vtkNew<fvTopologyFilter> f;
  f->SetInputData(image);
  f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  f->Update();
  EXPECT_EQ(f->GetLastError(), "");
  const std::vector<CriticalPoint> points = findCriticalPoints(field, {});
  const std::vector<Separatrix> seps = computeSeparatrices(field, points, {});
  ASSERT_EQ(f->GetCriticalPoints()->GetNumberOfPoints(), static_cast<vtkIdType>(points.size()));
  EXPECT_EQ(f->GetSeparatrices()->GetNumberOfLines(), static_cast<vtkIdType>(seps.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_EQ(value(f->GetCriticalPoints(), "index", static_cast<vtkIdType>(i)), points[i].index);

  f->ComputeSeparatricesOff();
  f->Update();
  EXPECT_EQ(f->GetSeparatrices()->GetNumberOfLines(), 0);
  EXPECT_EQ(f->GetCriticalPoints()->GetNumberOfPoints(), static_cast<vtkIdType>(points.size()));
}

TEST(fvTopologyFilter, SliceOfA3DImage) {
  const VectorField field = testField(3);
  vtkNew<fvTopologyFilter> f;
  f->SetInputData(imageOf(field));
  f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  TopologyParams params;
  params.slice_index = 2;
  f->SetParams(params);
  f->ComputeSeparatricesOff();
  f->Update();
  ASSERT_EQ(f->GetLastError(), "");
  const auto planar = findCriticalPoints(testField(), {});
  ASSERT_EQ(f->GetCriticalPoints()->GetNumberOfPoints(), static_cast<vtkIdType>(planar.size()));
  for (vtkIdType i = 0; i < f->GetCriticalPoints()->GetNumberOfPoints(); ++i)
    EXPECT_DOUBLE_EQ(f->GetCriticalPoints()->GetPoint(i)[2], 1.0);  // z of layer 2: 2 * 0.5
}

TEST(fvTopologyFilter, BadInputIsReportedAndLeavesBothOutputsEmpty) {
  vtkObject::GlobalWarningDisplayOff();  // the errors below are expected
  VectorField field = testField();
  vtkNew<fvTopologyFilter> f;
  f->SetInputData(imageOf(field));
  f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "speed");
  f->Update();
  EXPECT_NE(f->GetLastError().find("'speed' has 1 component"), std::string::npos)
      << f->GetLastError();
  EXPECT_EQ(f->GetCriticalPoints()->GetNumberOfPoints(), 0);
  EXPECT_EQ(f->GetSeparatrices()->GetNumberOfPoints(), 0);

  // A 2D field's NaN nodes are masked (below); a 3D one's analysed layer must be finite.
  VectorField layers = testField(3);
  layers.values[layers.grid.index(7, 11, 0)].x() = std::nan("");
  vtkNew<fvTopologyFilter> g;
  g->SetInputData(imageOf(layers));
  g->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  g->Update();
  EXPECT_NE(g->GetLastError().find("array 'velocity' has a non-finite value"), std::string::npos)
      << g->GetLastError();
  EXPECT_NE(g->GetLastError().find("at node (7, 11, 0)"), std::string::npos) << g->GetLastError();
  EXPECT_EQ(g->GetCriticalPoints()->GetNumberOfPoints(), 0);

  TopologyParams bad;
  bad.cluster_radius = -1;
  vtkNew<fvTopologyFilter> b;
  b->SetInputData(imageOf(testField()));
  b->SetParams(bad);
  b->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  b->Update();
  EXPECT_NE(b->GetLastError().find("parameter cluster_radius"), std::string::npos)
      << b->GetLastError();
  vtkObject::GlobalWarningDisplayOn();
}

namespace {

// The critical points and separatrices `fluidviz topology` finds in `field` with `mask`.
struct MaskedCore {
  std::vector<CriticalPoint> points;
  std::vector<Separatrix> separatrices;
};

MaskedCore maskedCore(const VectorField& field, const PointMask& mask) {
  const VectorField analysed = withWallLayerContinued(field, mask);
  MaskedCore c;
  c.points = findCriticalPointsInFluid(analysed, mask, {});
  c.separatrices = computeSeparatrices(analysed, c.points, {});
  return c;
}

void expectFilterGives(fvTopologyFilter* f, const MaskedCore& core) {
  ASSERT_EQ(f->GetLastError(), "");
  ASSERT_EQ(f->GetCriticalPoints()->GetNumberOfPoints(),
            static_cast<vtkIdType>(core.points.size()));
  for (std::size_t i = 0; i < core.points.size(); ++i) {
    double xyz[3];
    f->GetCriticalPoints()->GetPoint(static_cast<vtkIdType>(i), xyz);
    EXPECT_EQ(Vec3(xyz[0], xyz[1], xyz[2]), core.points[i].position);
  }
  EXPECT_EQ(f->GetSeparatrices()->GetNumberOfLines(),
            static_cast<vtkIdType>(core.separatrices.size()));
}

bool hasPointNear(vtkPolyData* points, double x, double y, double radius) {
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    const double* p = points->GetPoint(i);
    if (std::hypot(p[0] - x, p[1] - y) < radius) return true;
  }
  return false;
}

}  // namespace

// As `fluidviz topology` does: a 2D field's NaN nodes are masked, not refused.
TEST(fvTopologyFilter, NaNNodesOfA2DFieldAreMaskedAsTheCommandMasksThem) {
  VectorField field = testField();
  field.values[field.grid.index(7, 11)].x() = std::nan("");
  vtkNew<fvTopologyFilter> f;
  f->SetInputData(imageOf(field));
  f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  f->Update();
  PointMask nan(field.values.size(), 0);
  nan[field.grid.index(7, 11)] = 1;
  expectFilterGives(f, maskedCore(field, nan));
  // Node (7, 11) is far from every critical point: all of the unmasked field's are kept.
  EXPECT_EQ(f->GetCriticalPoints()->GetNumberOfPoints(),
            static_cast<vtkIdType>(findCriticalPoints(testField(), {}).size()));
}

// The image's vtkValidPointMask (a snapshot's solids) holds no critical point: a block of zeros
// over the centre at (1/2, 1/2) removes it and keeps the other three centres.
TEST(fvTopologyFilter, NoCriticalPointInsideTheImagesValidPointMask) {
  const VectorField field = testField();
  ScalarField valid{kValidPointMaskArray, field.grid,
                    std::vector<double>(field.values.size(), 1.0)};
  PointMask block(field.values.size(), 0);
  for (int j = 40; j <= 50; ++j)  // nodes at (j - 30) / 30: y in [0.33, 0.67]
    for (int i = 40; i <= 50; ++i) {
      valid.values[field.grid.index(i, j)] = 0.0;
      block[field.grid.index(i, j)] = 1;
    }
  FieldSet set;
  set.grid = field.grid;
  set.add(field);
  set.add(valid);
  vtkNew<fvTopologyFilter> f;
  f->SetInputData(toImageData(set));
  f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  f->Update();
  expectFilterGives(f, maskedCore(field, block));
  EXPECT_FALSE(hasPointNear(f->GetCriticalPoints(), 0.5, 0.5, 0.15));
  EXPECT_TRUE(hasPointNear(f->GetCriticalPoints(), -0.5, 0.5, 0.02));
  EXPECT_TRUE(hasPointNear(f->GetCriticalPoints(), -0.5, -0.5, 0.02));
  EXPECT_TRUE(hasPointNear(f->GetCriticalPoints(), 0.5, -0.5, 0.02));
}
