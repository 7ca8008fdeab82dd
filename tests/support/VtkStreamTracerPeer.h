#pragma once
// vtkStreamTracer set up as the peer of fluidviz's streamline tracer, for the agreement test
// (tests/filters/streamlines/vtk/StreamTracerAgreement_test.cpp) and flow_bench: classic RK4
// with a fixed step given in cells, on the point array "velocity", no vorticity.
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamTracer.h>

#include <cmath>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/streamlines/StreamlineParams.h"
#include "tests/support/FieldStats.h"

namespace fluidviz::testing {

/// The tracer for `seeds` on the 2D `image` with square cells or the 3D one with cubic cells, not
/// yet updated (the caller picks the direction and times Update()). CELL_LENGTH_UNIT is the
/// cell's diagonal, sqrt(2) cells for a pixel and sqrt(3) for a voxel; the maximum propagation
/// is always a world length.
inline vtkSmartPointer<vtkStreamTracer> fixedStepRk4Tracer(vtkImageData* image,
                                                           const std::vector<Vec3>& seeds,
                                                           double stepCells,
                                                           double maxLengthCells) {
  vtkNew<vtkPoints> points;
  for (const Vec3& s : seeds) points->InsertNextPoint(s.data());
  vtkNew<vtkPolyData> seedSet;
  seedSet->SetPoints(points);
  const double diagonal = std::sqrt(image->GetDimensions()[2] > 1 ? 3.0 : 2.0);
  auto tracer = vtkSmartPointer<vtkStreamTracer>::New();
  tracer->SetInputData(image);
  tracer->SetSourceData(seedSet);
  tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
  tracer->SetIntegratorTypeToRungeKutta4();
  tracer->SetIntegrationStepUnit(vtkStreamTracer::CELL_LENGTH_UNIT);
  tracer->SetInitialIntegrationStep(stepCells / diagonal);
  tracer->SetMinimumIntegrationStep(stepCells / diagonal);
  tracer->SetMaximumIntegrationStep(stepCells / diagonal);
  tracer->SetMaximumPropagation(maxLengthCells * image->GetSpacing()[0]);
  tracer->SetMaximumNumberOfSteps(1000000);
  tracer->SetComputeVorticity(false);
  return tracer;
}

/// The last point of each of the peer's forward lines, by seed (the seed itself where it traced
/// nothing), stopping where |v| <= terminalSpeed.
inline std::vector<Vec3> peerEndpoints(vtkImageData* image, const std::vector<Vec3>& seeds,
                                       double stepCells, double maxLengthCells,
                                       double terminalSpeed) {
  vtkSmartPointer<vtkStreamTracer> tracer =
      fixedStepRk4Tracer(image, seeds, stepCells, maxLengthCells);
  tracer->SetIntegrationDirectionToForward();
  tracer->SetTerminalSpeed(terminalSpeed);
  tracer->Update();
  vtkPolyData* out = tracer->GetOutput();
  auto* seedIds = vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("SeedIds"));
  std::vector<Vec3> ends = seeds;
  vtkNew<vtkIdList> ids;
  vtkIdType cell = 0;
  for (out->GetLines()->InitTraversal(); out->GetLines()->GetNextCell(ids); ++cell) {
    double p[3];
    out->GetPoint(ids->GetId(ids->GetNumberOfIds() - 1), p);
    ends.at(seedIds->GetValue(cell)) = Vec3(p[0], p[1], p[2]);
  }
  return ends;
}

/// The one vector field as the vtkImageData the peer traces (its point array keeps the field's
/// name: "velocity" for the peer).
inline vtkSmartPointer<vtkImageData> peerImageOf(const VectorField& field) {
  FieldSet set;
  set.grid = field.grid;
  set.add(field);
  return toImageData(set);
}

/// fluidviz's tracer set up as the peer's twin: classical RK4, fixed `stepCells`, forward,
/// `maxLengthCells`, no loop detection (VTK does not stop closed lines).
inline streamlines::StreamlineParams peerTwinParams(double stepCells, double maxLengthCells) {
  streamlines::StreamlineParams p;
  p.integrator = streamlines::Integrator::rk4;
  p.step = stepCells;
  p.direction = streamlines::TraceDirection::forward;
  p.max_length = maxLengthCells;
  p.loop_detection = false;
  return p;
}

}  // namespace fluidviz::testing
