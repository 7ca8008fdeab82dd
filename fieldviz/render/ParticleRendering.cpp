#include "fieldviz/render/ParticleRendering.h"

#include <vtkActor.h>
#include <vtkGlyph3DMapper.h>
#include <vtkPointGaussianMapper.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include "fieldviz/core/ParamRanges.h"

namespace fluidviz {

namespace {

// Fragment code of the sprites: offsetVCVSOutput runs over [-1, 1]^2 across the square; outside
// the unit disc is discarded, inside the colour falls off as 1 - d^2 (a sphere lit head-on).
constexpr const char* kSphereSpriteShader =
    "//VTK::Color::Impl\n"
    "float dist2 = dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy);\n"
    "if (dist2 > 1.0) { discard; }\n"
    "float shade = 1.0 - 0.7 * dist2;\n"
    "ambientColor *= shade;\n"
    "diffuseColor *= shade;\n";

vtkSmartPointer<vtkMapper> sphereGlyphs(vtkPolyData* particles, const ParticleStyle& style) {
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetRadius(style.radius);
  sphere->SetThetaResolution(style.sphere_resolution);
  sphere->SetPhiResolution(std::max(3, style.sphere_resolution / 2 + 1));
  auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
  mapper->SetInputData(particles);
  mapper->SetSourceConnection(sphere->GetOutputPort());
  mapper->ScalingOff();
  mapper->OrientOff();
  return mapper;
}

vtkSmartPointer<vtkMapper> sprites(vtkPolyData* particles, const ParticleStyle& style) {
  auto mapper = vtkSmartPointer<vtkPointGaussianMapper>::New();
  mapper->SetInputData(particles);
  mapper->SetScaleFactor(style.radius);
  mapper->SetSplatShaderCode(kSphereSpriteShader);
  mapper->EmissiveOff();
  return mapper;
}

}  // namespace

ParticleActor makeParticleActor(vtkPolyData* particles, const ParticleStyle& style) {
  params::checkRanges(style);
  vtkSmartPointer<vtkMapper> mapper =
      style.method == ParticleMethod::sprites ? sprites(particles, style) : sphereGlyphs(particles, style);
  mapper->ScalarVisibilityOff();
  ParticleActor p;
  if (!style.color_by.empty())
    p.coloring = colorByPointArray(mapper, particles, style.color_by, style.colormap,
                                   style.range_min, style.range_max);
  p.actor = vtkSmartPointer<vtkActor>::New();
  p.actor->SetMapper(mapper);
  vtkProperty* prop = p.actor->GetProperty();
  prop->SetColor(style.color[0], style.color[1], style.color[2]);
  prop->SetAmbient(0.15);
  prop->SetDiffuse(0.85);
  prop->SetSpecular(0.25);
  prop->SetSpecularPower(25.0);
  return p;
}

}  // namespace fluidviz
