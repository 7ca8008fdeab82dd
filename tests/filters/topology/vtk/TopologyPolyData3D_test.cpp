// The VTK wrapper of the volume topology (computeTopology3D, criticalPoints3DToPolyData,
// separatrices3DToPolyData) on the separable sine field (VolumeTestFields.h): the poly data carry
// the core's values; a vtkValidPointMask block around the sink removes it, and the four 1-saddle
// separatrices that reached it end at the mask instead.
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include "fieldviz/core/PointMask.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/vtk/TopologyPolyData.h"
#include "tests/filters/topology/VolumeTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {
vtkSmartPointer<vtkImageData> sineImage(const ScalarField* fluid = nullptr) {
  FieldSet set;
  set.grid = SineLattice::grid();
  VectorField v = SineLattice::sampled();
  v.name = "velocity";
  set.add(v);
  if (fluid) set.add(*fluid);
  return toImageData(set);
}
}  // namespace

TEST(TopologyPolyData3D, PointsAndSeparatricesCarryTheCoresValues) {
  const Topology3DResult r = computeTopology3D(sineImage(), "velocity", {}, true);
  ASSERT_EQ(r.points.size(), 9u);
  vtkPolyData* pd = r.pointsPolyData;
  ASSERT_EQ(pd->GetNumberOfPoints(), 9);
  auto* type = vtkStringArray::SafeDownCast(pd->GetPointData()->GetAbstractArray("type"));
  ASSERT_NE(type, nullptr);
  vtkDataArray* jacobian = pd->GetPointData()->GetArray("jacobian");
  ASSERT_NE(jacobian, nullptr);
  for (vtkIdType i = 0; i < 9; ++i) {
    const CriticalPoint3D& p = r.points[i];
    double x[3];
    pd->GetPoint(i, x);
    EXPECT_EQ(Vec3(x[0], x[1], x[2]), p.position);
    EXPECT_EQ(type->GetValue(i), p.typeName());
    EXPECT_EQ(pd->GetPointData()->GetArray("type_code")->GetTuple1(i), static_cast<int>(p.type));
    EXPECT_EQ(pd->GetPointData()->GetArray("index")->GetTuple1(i), p.index);
    EXPECT_EQ(pd->GetPointData()->GetArray("det")->GetTuple1(i), p.det);
    for (int c = 0; c < 9; ++c) EXPECT_EQ(jacobian->GetComponent(i, c), p.jacobian(c / 3, c % 3));
  }
  ASSERT_EQ(r.separatrices.size(), 16u);
  ASSERT_EQ(r.separatricesPolyData->GetNumberOfLines(), 16);
  for (vtkIdType c = 0; c < 16; ++c) {
    EXPECT_EQ(r.separatricesPolyData->GetCellData()->GetArray("origin")->GetTuple1(c),
              r.separatrices[c].origin);
    EXPECT_EQ(r.separatricesPolyData->GetCellData()->GetArray("end")->GetTuple1(c),
              static_cast<int>(r.separatrices[c].end));
  }
}

TEST(TopologyPolyData3D, ValidPointMaskRemovesTheSinkAndEndsItsSeparatrices) {
  // The sink lies at (0.17 + pi, 0.23 + pi, 0.31): nodes (21.6, 21.9, 6.6). Mask the
  // 4 x 4 x 4 nodes around it.
  const Grid g = SineLattice::grid();
  ScalarField fluid{kValidPointMaskArray, g, std::vector<double>(g.nodeCount(), 1.0)};
  for (int k = 5; k <= 8; ++k)
    for (int j = 20; j <= 23; ++j)
      for (int i = 19; i <= 22; ++i) fluid.values[g.index(i, j, k)] = 0.0;
  const Topology3DResult r = computeTopology3D(sineImage(&fluid), "velocity", {}, true);
  ASSERT_EQ(r.points.size(), 8u);
  for (const CriticalPoint3D& p : r.points) EXPECT_NE(p.type, CriticalPointType3D::Sink);
  int atMask = 0;
  for (const Separatrix3D& s : r.separatrices) atMask += s.end == SeparatrixEnd::Mask;
  EXPECT_EQ(atMask, 4);
}
