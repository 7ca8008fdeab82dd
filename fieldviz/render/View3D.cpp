#include "fieldviz/render/View3D.h"

#include <Eigen/Geometry>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDoubleArray.h>
#include <vtkLightKit.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "fieldviz/core/Grid.h"
#include "fieldviz/core/ParamRanges.h"
#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/FlatActors.h"

namespace fluidviz {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Unit vectors of the camera frame: up, front (towards the camera at azimuth 0) and right.
struct Frame {
  Vec3 up, front, right;
};

Frame frameFor(Axis up) {
  Frame f;
  if (up == Axis::z) {
    f.up = Vec3::UnitZ(), f.front = -Vec3::UnitY();
  } else if (up == Axis::x) {
    f.up = Vec3::UnitX(), f.front = Vec3::UnitY();
  } else {
    f.up = Vec3::UnitY(), f.front = Vec3::UnitZ();
  }
  f.right = f.up.cross(f.front);
  return f;
}

// Direction from the focal point to the camera: the front turned by the azimuth about up, then
// lifted by the elevation.
Vec3 viewDirection(const CameraParams& p) {
  const Frame f = frameFor(p.up);
  const double az = p.azimuth * kDegree, el = p.elevation * kDegree;
  return std::cos(el) * (std::cos(az) * f.front + std::sin(az) * f.right) + std::sin(el) * f.up;
}

void styleText(vtkTextProperty* t, const Rgb& color, int fontPx, bool bold) {
  t->SetFontFamilyToArial();
  t->SetFontSize(fontPx);
  t->SetColor(color[0], color[1], color[2]);
  t->SetBold(bold);
  t->SetItalic(false);
  t->SetShadow(false);
}

int legendFontPx(const View3DParams& p) {
  return std::clamp(static_cast<int>(0.021 * std::min(p.width, p.height)), 10, 64);
}

// One line of text centred at the top of the picture, a little larger than the legend's.
vtkSmartPointer<vtkTextActor> makeTitle(const std::string& title, const View3DParams& p) {
  auto text = vtkSmartPointer<vtkTextActor>::New();
  text->SetInput(title.c_str());
  styleText(text->GetTextProperty(), foregroundColor(p.background), legendFontPx(p) * 5 / 4, true);
  text->GetTextProperty()->SetJustificationToCentered();
  text->GetTextProperty()->SetVerticalJustificationToTop();
  text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  text->GetPositionCoordinate()->SetValue(0.5, 0.97);
  return text;
}

// Vertical legend along the right edge: round labels (as FieldImage's), text in the foreground
// colour.
vtkSmartPointer<vtkScalarBarActor> makeLegend(vtkScalarsToColors* colors, const std::string& title,
                                              const View3DParams& p) {
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(colors);
  bar->SetTitle(title.c_str());
  const std::array<double, 2> range{colors->GetRange()[0], colors->GetRange()[1]};
  vtkNew<vtkDoubleArray> labels;
  for (double v : legendTicks(range).values) labels->InsertNextValue(v);
  bar->SetCustomLabels(labels);
  bar->UseCustomLabelsOn();
  bar->SetLabelFormat(legendLabelFormat(range).c_str());
  bar->UnconstrainedFontSizeOn();
  bar->DrawFrameOff();
  bar->DrawBackgroundOff();
  const int fontPx = legendFontPx(p);
  const Rgb text = foregroundColor(p.background);
  styleText(bar->GetLabelTextProperty(), text, fontPx, false);
  styleText(bar->GetTitleTextProperty(), text, fontPx, true);
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(0.86, 0.12);
  bar->SetWidth(0.12);
  bar->SetHeight(0.76);
  return bar;
}

}  // namespace

void validateView3DParams(const View3DParams& params) { params::checkRanges(params); }

Rgb backgroundColor(Background background) {
  return background == Background::dark ? Rgb{0.08, 0.08, 0.10} : Rgb{1.0, 1.0, 1.0};
}

Rgb foregroundColor(Background background) {
  return background == Background::dark ? Rgb{0.95, 0.95, 0.95} : Rgb{0.0, 0.0, 0.0};
}

// Perspective: the bounding sphere (radius rho) fits the narrower of the vertical and horizontal
// fields of view when the camera stands rho / sin(half angle) away; parallel: the half-height
// shown is rho (divided by the aspect ratio when the picture is taller than wide).
void frameCamera(vtkRenderer* renderer, const std::array<double, 6>& b, int width, int height,
                 const CameraParams& p) {
  const Vec3 centre(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
  const double rho = std::max(1e-300, 0.5 * Vec3(b[1] - b[0], b[3] - b[2], b[5] - b[4]).norm());
  const double aspect = static_cast<double>(width) / height;
  const double halfV = 0.5 * p.view_angle * kDegree;
  const double half = std::min(halfV, std::atan(std::tan(halfV) * aspect));
  vtkCamera* camera = renderer->GetActiveCamera();
  const Vec3 up = frameFor(p.up).up;
  const Vec3 position = centre + (rho / std::sin(half) / p.zoom) * viewDirection(p);
  camera->SetFocalPoint(centre.data());
  camera->SetPosition(position.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(p.view_angle);
  camera->SetParallelProjection(p.projection == Projection::parallel);
  camera->SetParallelScale(rho / p.zoom / std::min(1.0, aspect));
  camera->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange(b[0], b[1], b[2], b[3], b[4], b[5]);
}

struct Scene3D::Impl {
  View3DParams params;
  OffscreenRenderer renderer;
  vtkSmartPointer<vtkActor> outline;
  vtkSmartPointer<vtkScalarBarActor> legend;
  vtkSmartPointer<vtkTextActor> title;
  std::optional<std::array<double, 6>> bounds;  // set: frame this box

  explicit Impl(const View3DParams& p)
      : params(p), renderer(p.width, p.height, backgroundColor(p.background)) {
    renderer.setMultiSamples(p.multisamples);
    vtkNew<vtkLightKit> lights;  // key, fill, back and head lights: shape reads at any angle
    lights->AddLightsToRenderer(renderer.renderer());
  }

  std::array<double, 6> dataBounds() {
    if (outline) renderer.removeProp(outline);
    if (bounds) return *bounds;
    std::array<double, 6> b{};
    renderer.renderer()->ComputeVisiblePropBounds(b.data());
    if (!(b[0] <= b[1])) b = {-1, 1, -1, 1, -1, 1};  // nothing visible: any box
    return b;
  }

  RgbaImage renderAt(const CameraParams& camera) {
    const std::array<double, 6> b = dataBounds();
    if (params.outline) {
      outline = outlineActor(b, foregroundColor(params.background));
      renderer.addProp(outline);
    }
    frameCamera(renderer.renderer(), b, params.width, params.height, camera);
    return renderer.render();
  }
};

Scene3D::Scene3D(const View3DParams& params) {
  validateView3DParams(params);
  impl_ = std::make_unique<Impl>(params);
}

Scene3D::~Scene3D() = default;

OffscreenRenderer& Scene3D::renderer() { return impl_->renderer; }
const View3DParams& Scene3D::params() const { return impl_->params; }

void Scene3D::add(vtkProp* prop) { impl_->renderer.addProp(prop); }

void Scene3D::setBounds(const std::array<double, 6>& bounds) { impl_->bounds = bounds; }

void Scene3D::setLegend(vtkScalarsToColors* colors, const std::string& title) {
  if (!impl_->params.scalar_bar) return;
  if (impl_->legend) impl_->renderer.removeProp(impl_->legend);
  impl_->legend = makeLegend(colors, title, impl_->params);
  impl_->renderer.addProp(impl_->legend);
}

void Scene3D::setTitle(const std::string& title) {
  if (impl_->title) impl_->renderer.removeProp(impl_->title);
  impl_->title = makeTitle(title, impl_->params);
  impl_->renderer.addProp(impl_->title);
}

RgbaImage Scene3D::render() { return impl_->renderAt(impl_->params.camera); }

void Scene3D::renderToPng(const std::filesystem::path& file) { writePicture(render(), file); }

std::vector<std::filesystem::path> Scene3D::renderTurntable(const std::filesystem::path& stem) {
  std::vector<std::filesystem::path> files;
  const int frames = impl_->params.turntable_frames;
  for (int i = 0; i < frames; ++i) {
    CameraParams camera = impl_->params.camera;
    camera.azimuth += 360.0 * i / frames;
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%04d.png", i);
    files.push_back(stem.string() + suffix);
    writePicture(impl_->renderAt(camera), files.back());
  }
  return files;
}

}  // namespace fluidviz
