#pragma once
// VTK's vtkVectorFieldTopology (VTK 9.1, Bujack et al. 2020) as the peer of the topology core,
// for the agreement tests in tests/filters/topology/vtk/. It triangulates the image (two
// triangles per cell), takes the zero of the linear interpolant in each triangle and classifies
// it by the eigenvalues of the image's gradient there; its output port 0 has a point array
// "type" (0 sink, 1 saddle, 2 source, 3 complex eigenvalues) and "typeDetailed" (0 attracting
// node, 1 attracting focus, 2 saddle, 3 repelling node, 4 repelling focus, 5 centre).
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkVectorFieldTopology.h>

#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/CriticalPoint.h"

namespace fluidviz::testing {

struct VtkPoint {
  topology::Vec2 position;
  int type = -1, detailed = -1;
  /// VTK's linearisation at the point (its point array "gradient", d v_i / d x_j, in-plane
  /// part): vtkGradientFilter's node gradients, interpolated linearly in the triangle.
  topology::Mat2 gradient = topology::Mat2::Zero();
};

/// VTK's critical points of a 2D field (its separatrices are not computed: one step).
inline std::vector<VtkPoint> vtkCriticalPoints(const VectorField& field) {
  FieldSet set;
  set.grid = field.grid;
  VectorField v = field;
  v.name = "velocity";
  set.add(v);
  vtkSmartPointer<vtkImageData> image = toImageData(set);
  image->GetPointData()->SetActiveVectors("velocity");
  vtkNew<vtkVectorFieldTopology> vtk;
  vtk->SetInputData(image);
  vtk->SetMaxNumSteps(1);  // separatrices are not compared (VTK 9.1 cannot switch them off)
  vtk->Update();
  vtkPolyData* out = vtk->GetOutput(0);
  std::vector<VtkPoint> points;
  vtkDataArray* gradient = out->GetPointData()->GetArray("gradient");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    VtkPoint point{{p[0], p[1]},
                   static_cast<int>(out->GetPointData()->GetArray("type")->GetTuple1(i)),
                   static_cast<int>(out->GetPointData()->GetArray("typeDetailed")->GetTuple1(i))};
    const double* g = gradient->GetTuple9(i);
    point.gradient << g[0], g[1], g[3], g[4];
    points.push_back(point);
  }
  return points;
}

/// VTK's detailed type in the core's vocabulary (VTK calls every complex pair with a non-zero
/// real part a focus).
inline topology::CriticalPointType fromVtk(int detailed) {
  using topology::CriticalPointType;
  switch (detailed) {
    case 0: return CriticalPointType::Sink;
    case 1: return CriticalPointType::SpiralSink;
    case 2: return CriticalPointType::Saddle;
    case 3: return CriticalPointType::Source;
    case 4: return CriticalPointType::SpiralSource;
    case 5: return CriticalPointType::Centre;
    default: return CriticalPointType::Degenerate;
  }
}

/// A centre of ours (|re| <= 1 % |im|) is a centre for VTK only if its real part is below 1e-10;
/// on sampled data VTK reports it as a focus of either sense (measured on the cellular flow: both).
inline bool sameType(topology::CriticalPointType ours, int vtkDetailed) {
  if (ours == topology::CriticalPointType::Centre)
    return vtkDetailed == 1 || vtkDetailed == 4 || vtkDetailed == 5;
  return ours == fromVtk(vtkDetailed);
}

}  // namespace fluidviz::testing
