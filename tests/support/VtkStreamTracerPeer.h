#pragma once
// vtkStreamTracer set up as the peer of fluidviz's streamline tracer, for the agreement test
// (tests/filters/streamlines/vtk/StreamTracerAgreement_test.cpp) and flow_bench: classic RK4
// with a fixed step given in cells, on the point array "velocity", no vorticity.
#include <vtkDataObject.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamTracer.h>

#include <cmath>
#include <vector>

#include "fieldviz/core/Field.h"

namespace fluidviz::testing {

/// The tracer for `seeds` on the 2D `image` with square cells, not yet updated (the caller picks
/// the direction and times Update()). CELL_LENGTH_UNIT is the cell's diagonal, sqrt(2) cells;
/// the maximum propagation is always a world length.
inline vtkSmartPointer<vtkStreamTracer> fixedStepRk4Tracer(vtkImageData* image,
                                                           const std::vector<Vec3>& seeds,
                                                           double stepCells,
                                                           double maxLengthCells) {
  vtkNew<vtkPoints> points;
  for (const Vec3& s : seeds) points->InsertNextPoint(s.data());
  vtkNew<vtkPolyData> seedSet;
  seedSet->SetPoints(points);
  const double diagonal = std::sqrt(2.0);
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

}  // namespace fluidviz::testing
