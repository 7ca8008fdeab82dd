#include "fieldviz/render/LicPicture.h"

#include <cmath>
#include <stdexcept>

#include "fieldviz/core/ParamRanges.h"
#include "fieldviz/render/ImageOverlay.h"

namespace fluidviz {

namespace {

double extentX(const Grid& g) { return (g.dims[0] - 1) * g.spacing[0]; }
double extentY(const Grid& g) { return (g.dims[1] - 1) * g.spacing[1]; }

double pixelsPerUnit(FieldImageScene& scene, const Grid& g) {
  const PixelRect r = scene.fieldPixels();
  return (r.right - r.left) / extentX(g);
}

void require2D(const ScalarField& field, const char* what) {
  if (!field.grid.is2D())
    throw std::invalid_argument(std::string(what) + " '" + field.name + "' must be 2D (" +
                                field.grid.describe() + "); take a z slice first");
}

}  // namespace

// FieldImageScene centres title, field (with its axes) and legend inside `padding`; whatever room
// the field does not use shows up as equal margins on both sides of it. A few rounds of "remove the spare margin,
// add what the field lacks" converge (fonts scale with the picture, so one round is not exact).
void fitPictureToField(const ScalarField& field, FieldImageParams& p, int fieldWidth) {
  require2D(field, "field");
  const double targetW = fieldWidth;
  const double targetH = fieldWidth * extentY(field.grid) / extentX(field.grid);
  p.width = fieldWidth + 2 * p.padding + (p.scalar_bar ? 160 : 0) + (p.axes ? 80 : 0);
  p.height = static_cast<int>(std::ceil(targetH)) + 2 * p.padding + (p.title.empty() ? 0 : 60) +
             (p.axes ? 60 : 0);
  for (int round = 0; round < 6; ++round) {
    if (p.width > 8192 || p.height > 8192)
      throw ParamError(p.width > 8192 ? "width" : "height",
                       "a field " + std::to_string(fieldWidth) + " px wide needs a picture of " +
                           std::to_string(p.width) + " x " + std::to_string(p.height) +
                           " px, above the 8192 px limit of pictures; make it smaller");
    FieldImageScene trial(field, p);
    const PixelRect r = trial.fieldPixels(), outer = trial.fieldPixelsWithAxes();
    const double spareW = 2 * (outer.left - p.padding);
    const double spareH = 2 * (p.height - outer.bottom - p.padding);
    const double lackW = targetW - (r.right - r.left), lackH = targetH - (r.bottom - r.top);
    if (std::abs(lackW) < 0.5 && std::abs(lackH) < 0.5 && spareW < 1 && spareH < 1) return;
    p.width = static_cast<int>(std::lround(p.width - spareW + lackW));
    p.height = static_cast<int>(std::lround(p.height - spareH + lackH));
  }
}

LicScene makeLicScene(const ScalarField& texture, const std::vector<std::uint8_t>& mask,
                      const ScalarField& colour, FieldImageParams picture,
                      const LicBlendParams& blend) {
  params::checkRanges(blend);
  require2D(colour, "colour field");
  fitPictureToField(colour, picture, texture.grid.dims[0]);
  LicScene out;
  out.scene = std::make_unique<FieldImageScene>(colour, picture);
  out.range = out.scene->range();
  const RgbaImage blended =
      blendLicTexture(texture, mask, colour, ColorMap::byName(picture.colormap), out.range, blend);
  out.texture = addPixelAlignedImage(*out.scene, blended, colour.grid);
  return out;
}

LicPicture renderLicPicture(const ScalarField& texture, const std::vector<std::uint8_t>& mask,
                            const ScalarField& colour, FieldImageParams picture,
                            const LicBlendParams& blend, const std::vector<LineOverlay>& lines) {
  LicScene lic = makeLicScene(texture, mask, colour, std::move(picture), blend);
  for (const LineOverlay& l : lines)
    addStreamlineOverlay(*lic.scene, l.lines, l.style, pixelsPerUnit(*lic.scene, colour.grid));
  return {lic.scene->render(), lic.texture, lic.range};
}

FieldPicture renderFieldPicture(const ScalarField& field, const FieldImageParams& picture,
                                const std::vector<LineOverlay>& lines) {
  FieldImageScene scene(field, picture);
  for (const LineOverlay& l : lines)
    addStreamlineOverlay(scene, l.lines, l.style, pixelsPerUnit(scene, field.grid));
  return {scene.render(), scene.range()};
}

}  // namespace fluidviz
