#include "fieldviz/render/FlatActors.h"

#include <vtkNew.h>
#include <vtkOutlineSource.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace fluidviz {

vtkSmartPointer<vtkActor> flatActor(vtkPolyData* data, const Rgb& colour) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  return actor;
}

vtkSmartPointer<vtkActor> outlineActor(const std::array<double, 6>& bounds, const Rgb& colour) {
  vtkNew<vtkOutlineSource> box;
  box->SetBounds(bounds.data());
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(box->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLighting(false);
  actor->GetProperty()->SetLineWidth(1.5f);
  return actor;
}

}  // namespace fluidviz
