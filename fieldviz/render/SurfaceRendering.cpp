#include "fieldviz/render/SurfaceRendering.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz {

SurfaceActor makeSurfaceActor(vtkPolyData* surface, const SurfaceStyle& style) {
  params::checkRanges(style);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(surface);
  mapper->ScalarVisibilityOff();
  SurfaceActor s;
  if (!style.color_by.empty())
    s.coloring = colorByPointArray(mapper, surface, style.color_by, style.colormap,
                                   style.range_min, style.range_max);
  s.actor = vtkSmartPointer<vtkActor>::New();
  s.actor->SetMapper(mapper);
  vtkProperty* p = s.actor->GetProperty();
  p->SetColor(style.color[0], style.color[1], style.color[2]);
  p->SetOpacity(style.opacity);
  p->SetInterpolationToPhong();
  p->SetAmbient(0.1);
  p->SetDiffuse(0.8);
  p->SetSpecular(style.specular);
  p->SetSpecularPower(style.specular_power);
  return s;
}

}  // namespace fluidviz
