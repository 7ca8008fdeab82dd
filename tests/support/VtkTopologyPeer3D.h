#pragma once
// VTK's vtkVectorFieldTopology (VTK 9.1, Bujack et al. 2020) on 3D images, the peer of the volume
// topology core (filters/topology/VolumeTopology.h) in tests/filters/topology/vtk/. It splits
// every voxel into five tetrahedra (vtkDataSetTriangleFilter), takes the zero of the linear
// interpolant in each and classifies it by the eigenvalues of the image's gradient there; port 0
// has the point arrays "type" (0 sink, 1 1-saddle, 2 2-saddle, 3 source, i.e. the number of
// eigenvalues with positive real part) and "typeDetailed" (0 attracting node, 1 attracting focus,
// 2 node 1-saddle, 3 focus 1-saddle, 4 node 2-saddle, 5 focus 2-saddle, 6 repelling node,
// 7 repelling focus, 8 centre: an eigenvalue with zero real part and a complex pair).
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkVectorFieldTopology.h>

#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/CriticalPoint3D.h"

namespace fluidviz::testing {

struct VtkPoint3D {
  Vec3 position;
  int type = -1, detailed = -1;
};

/// VTK's critical points of a 3D field (separatrices cut to one step, surfaces off).
inline std::vector<VtkPoint3D> vtkCriticalPoints3D(const VectorField& field) {
  FieldSet set;
  set.grid = field.grid;
  VectorField v = field;
  v.name = "velocity";
  set.add(v);
  vtkSmartPointer<vtkImageData> image = toImageData(set);
  image->GetPointData()->SetActiveVectors("velocity");
  vtkNew<vtkVectorFieldTopology> vtk;
  vtk->SetInputData(image);
  vtk->SetMaxNumSteps(1);
  vtk->SetComputeSurfaces(false);
  vtk->Update();
  vtkPolyData* out = vtk->GetOutput(0);
  std::vector<VtkPoint3D> points;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    points.push_back({Vec3(p[0], p[1], p[2]),
                      static_cast<int>(out->GetPointData()->GetArray("type")->GetTuple1(i)),
                      static_cast<int>(out->GetPointData()->GetArray("typeDetailed")->GetTuple1(i))});
  }
  return points;
}

/// VTK's detailed 3D type in the core's vocabulary.
inline topology::CriticalPointType3D fromVtk3D(int detailed) {
  using topology::CriticalPointType3D;
  switch (detailed) {
    case 0: return CriticalPointType3D::Sink;
    case 1: return CriticalPointType3D::SpiralSink;
    case 2: return CriticalPointType3D::Saddle1;
    case 3: return CriticalPointType3D::SpiralSaddle1;
    case 4: return CriticalPointType3D::Saddle2;
    case 5: return CriticalPointType3D::SpiralSaddle2;
    case 6: return CriticalPointType3D::Source;
    case 7: return CriticalPointType3D::SpiralSource;
    case 8: return CriticalPointType3D::Centre;
    default: return CriticalPointType3D::Degenerate;
  }
}

}  // namespace fluidviz::testing
