#include "fieldviz/render/ParticleImage.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include "fieldviz/render/FlatActors.h"
#include "fieldviz/render/ParticleRendering.h"
#include "fieldviz/render/View3D.h"

namespace fluidviz {

namespace {

// Spheres are exact and cheap enough below ~2e4 particles; sprites beyond.
constexpr vtkIdType kSphereLimit = 20000;

vtkSmartPointer<vtkTextActor> titleActor(const std::string& title, const FieldImageParams& p) {
  auto text = vtkSmartPointer<vtkTextActor>::New();
  text->SetInput(title.c_str());
  vtkTextProperty* t = text->GetTextProperty();
  const Rgb fg = foregroundColor(p.background);
  t->SetFontFamilyToArial();
  t->SetFontSize(std::clamp(static_cast<int>(0.03 * std::min(p.width, p.height)), 10, 72));
  t->SetColor(fg[0], fg[1], fg[2]);
  t->SetBold(true);
  t->SetJustificationToCentered();
  t->SetVerticalJustificationToTop();
  text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  text->GetPositionCoordinate()->SetValue(0.5, 1.0 - static_cast<double>(p.padding) / p.height);
  return text;
}

}  // namespace

RgbaImage renderParticlePicture(vtkPolyData* fluid, vtkPolyData* boundary,
                                const ParticlePictureParams& params) {
  const FieldImageParams& pic = params.picture;
  validateFieldImageParams(pic);
  if (!(params.radius > 0)) throw std::invalid_argument("particle radius must be > 0");

  View3DParams view;
  view.width = pic.width;
  view.height = pic.height;
  view.background = pic.background;
  view.scalar_bar = pic.scalar_bar;
  view.outline = false;  // the domain's own outline is drawn below
  view.multisamples = 4;
  const std::array<double, 6>& d = params.domain;
  std::array<double, 6> framed = d;
  if (params.dimension == 2) {
    view.camera.azimuth = 0;
    view.camera.elevation = 0;
    view.camera.projection = Projection::parallel;
    // Leave the right 18% to the legend and the top 10% to the title.
    const double w = d[1] - d[0], h = d[3] - d[2];
    const double wall = 6.0 * params.radius;  // three layers of boundary particles
    framed[0] = d[0] - wall - 0.02 * w;
    framed[1] = framed[0] + (w + 2 * wall + 0.02 * w) / (pic.scalar_bar ? 0.8 : 0.96);
    framed[3] = d[3] + wall + h * (pic.title.empty() ? 0.04 : 0.14);
    framed[2] = d[2] - wall - 0.04 * h;
    framed[4] = framed[5] = 0.0;
    const double aspect = static_cast<double>(pic.width) / pic.height;
    const double W = framed[1] - framed[0], H = framed[3] - framed[2];
    const double rho = 0.5 * std::hypot(W, H);
    const double halfHeight = std::max(0.5 * H, 0.5 * W / aspect);
    view.camera.zoom = rho / (halfHeight * std::min(1.0, aspect));
  }
  Scene3D scene(view);
  scene.setBounds(framed);

  ParticleStyle style;
  style.radius = params.radius;
  style.method = fluid->GetNumberOfPoints() > kSphereLimit ? ParticleMethod::sprites : ParticleMethod::spheres;
  style.sphere_resolution = 10;
  style.color_by = params.color_by;
  style.colormap = pic.colormap;
  style.range_min = pic.range_min;
  style.range_max = pic.range_max;
  const ParticleActor particles = makeParticleActor(fluid, style);
  scene.add(particles.actor);
  if (particles.coloring)
    scene.setLegend(particles.coloring->table, pic.scalar_bar_title.empty()
                                                   ? particles.coloring->title
                                                   : pic.scalar_bar_title);
  if (boundary && params.dimension == 2 && boundary->GetNumberOfPoints() > 0) {
    ParticleStyle wall;
    wall.radius = params.radius;
    wall.method = boundary->GetNumberOfPoints() > kSphereLimit ? ParticleMethod::sprites : ParticleMethod::spheres;
    wall.sphere_resolution = 8;
    wall.color = {0.72, 0.72, 0.72};
    scene.add(makeParticleActor(boundary, wall).actor);
  }
  scene.add(outlineActor(d, foregroundColor(pic.background)));
  if (!pic.title.empty()) scene.renderer().addProp(titleActor(pic.title, pic));
  return scene.render();
}

}  // namespace fluidviz
