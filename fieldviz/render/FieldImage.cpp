#include "fieldviz/render/FieldImage.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "fieldviz/core/ParamRanges.h"
#include "fieldviz/render/ColorMapVtk.h"

namespace fluidviz {

// ---------------------------------------------------------------------------------------------
// Parameter checks

void validateFieldImageParams(const FieldImageParams& params) {
  params::checkRanges(params);
  if (params.range_min && params.range_max && !(*params.range_min < *params.range_max))
    throw ParamError("range_max",
                     "is " + formatNumber(*params.range_max, 10) +
                         ", must be greater than range_min = " + formatNumber(*params.range_min, 10));
  if (params.axes_unit.size() > 16)
    throw ParamError("axes_unit", "is \"" + params.axes_unit + "\", allowed at most 16 characters");
}

namespace {
constexpr int kLabelCount = 5;  // legend labels wanted (round values: 3 to 7 of them)
}  // namespace

// Round ticks (1, 2 or 5 x 10^k): a density of 1000-1000.25 kg/m^3 prints 1000.05, not "1e+03".
std::string legendLabelFormat(const std::array<double, 2>& range) {
  return tickLabelFormat(legendTicks(range));
}

RoundTicks legendTicks(const std::array<double, 2>& range) {
  if (range[0] < range[1]) return roundTicks(range[0], range[1], kLabelCount);
  return {1.0, {range[0]}};  // a constant field: one label
}

// ---------------------------------------------------------------------------------------------
// The drawn slice: a 2D field, or one z-layer of a 3D field.

namespace {

struct Slice {
  std::string name;
  Grid grid;  // dims[2] == 1, origin[2] = the layer's z
  std::vector<double> values;
};

int checkedSliceIndex(const ScalarField& field, int sliceIndex) {
  const int nz = field.grid.dims[2];
  if (nz == 1) {
    if (sliceIndex > 0)
      throw ParamError("slice_index", "is " + std::to_string(sliceIndex) + ", but field '" +
                                          field.name +
                                      "' is 2D: allowed -1 or 0");
    return 0;
  }
  if (sliceIndex < 0)
    throw ParamError("slice_index", "must be given for the 3D field '" + field.name + "' (" +
                                    field.grid.describe() + "): the z index of the slice to " +
                                    "draw, [0, " + std::to_string(nz - 1) + "]");
  if (sliceIndex >= nz)
    throw ParamError("slice_index", "is " + std::to_string(sliceIndex) + ", outside [0, " +
                                    std::to_string(nz - 1) + "] for the 3D field '" + field.name +
                                    "'");
  return sliceIndex;
}

Slice extractSlice(const ScalarField& field, int sliceIndex) {
  field.grid.validate();
  if (field.values.size() != field.grid.nodeCount())
    throw std::invalid_argument("field '" + field.name + "' has " +
                                std::to_string(field.values.size()) + " values for " +
                                std::to_string(field.grid.nodeCount()) + " grid nodes");
  if (field.grid.dims[0] < 2 || field.grid.dims[1] < 2)
    throw std::invalid_argument("field '" + field.name + "' (" + field.grid.describe() +
                                ") needs at least 2 nodes along x and y to be drawn as a picture");
  const int k = checkedSliceIndex(field, sliceIndex);
  Slice slice{field.name, field.grid, {}};
  slice.grid.dims[2] = 1;
  slice.grid.origin[2] = field.grid.origin[2] + k * field.grid.spacing[2];
  const std::size_t layer = static_cast<std::size_t>(field.grid.dims[0]) * field.grid.dims[1];
  const auto first = field.values.begin() + static_cast<std::ptrdiff_t>(k * layer);
  slice.values.assign(first, first + static_cast<std::ptrdiff_t>(layer));
  return slice;
}

// Width given to a range that the data leave empty (constant field, or data on the wrong side
// of the one bound given): relative to the value, or 1 around zero.
double fallbackSpan(double v) { return v == 0.0 ? 1.0 : 0.1 * std::abs(v); }

std::array<double, 2> colourRange(const Slice& slice, const FieldImageParams& p) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : slice.values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (p.range_min && p.range_max) return {*p.range_min, *p.range_max};
  if (!std::isfinite(lo))
    throw std::invalid_argument("field '" + slice.name +
                                "' has no finite value to set the colour range from; give "
                                "range_min and range_max");
  if (p.range_min)
    return {*p.range_min, hi > *p.range_min ? hi : *p.range_min + fallbackSpan(*p.range_min)};
  if (p.range_max)
    return {lo < *p.range_max ? lo : *p.range_max - fallbackSpan(*p.range_max), *p.range_max};
  if (lo < hi) return {lo, hi};
  return {lo - 0.5 * fallbackSpan(lo), hi + 0.5 * fallbackSpan(hi)};  // middle colour
}

// ---------------------------------------------------------------------------------------------
// Layout: title band on top, field and legend side by side below, all inside `padding`.

struct LayoutStyle {
  Rgb background, text;
  int titleFontPx, labelFontPx;
};

LayoutStyle styleFor(const FieldImageParams& p) {
  const bool dark = p.background == Background::dark;
  const int shortSide = std::min(p.width, p.height);
  // Sizes that read well at 800 px (26 and 17 px), scale with the picture and stay readable
  // (>= 12 and 10 px) in small ones.
  return {dark ? Rgb{0.08, 0.08, 0.10} : Rgb{1.0, 1.0, 1.0},
          dark ? Rgb{0.95, 0.95, 0.95} : Rgb{0.0, 0.0, 0.0},
          std::clamp(static_cast<int>(std::lround(0.032 * shortSide)), 12, 96),
          std::clamp(static_cast<int>(std::lround(0.021 * shortSide)), 10, 64)};
}

void applyTextStyle(vtkTextProperty* t, const LayoutStyle& s, int fontPx, bool bold) {
  t->SetFontFamilyToArial();
  t->SetFontSize(fontPx);
  t->SetColor(s.text[0], s.text[1], s.text[2]);
  t->SetBold(bold);
  t->SetItalic(false);
  t->SetShadow(false);
}

// Width and height in px of `text` drawn with `property` (72 dpi: font size = px).
std::array<int, 2> textSize(vtkTextProperty* property, const std::string& text) {
  int box[4] = {0, 0, 0, 0};
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  if (text.empty() || renderer == nullptr || !renderer->GetBoundingBox(property, text, box, 72))
    return {0, 0};
  return {box[1] - box[0] + 1, box[3] - box[2] + 1};
}

constexpr int kTableEntries = 1024;
std::string formatLabel(double v, const std::string& format) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format.c_str(), v);
  return buffer;
}

std::vector<double> labelValues(const std::array<double, 2>& range) {
  return legendTicks(range).values;
}

struct LegendSize {
  int barPx = 0, labelGapPx = 0, width = 0;
};

// The legend must hold the bar, a gap and the widest label, and its title above.
LegendSize legendSize(const std::array<double, 2>& range, const std::string& title,
                      const LayoutStyle& style) {
  vtkNew<vtkTextProperty> label, heading;
  applyTextStyle(label, style, style.labelFontPx, false);
  applyTextStyle(heading, style, style.labelFontPx, true);
  int widestLabel = 0;
  const std::string format = legendLabelFormat(range);
  for (double v : labelValues(range))
    widestLabel = std::max(widestLabel, textSize(label, formatLabel(v, format))[0]);
  LegendSize size;
  size.barPx = static_cast<int>(std::lround(1.3 * style.labelFontPx));
  size.labelGapPx = std::max(2, style.labelFontPx / 3);
  // TextPad pads a label on both sides; one more gap keeps the right edge clear.
  size.width =
      std::max(size.barPx + 3 * size.labelGapPx + widestLabel, textSize(heading, title)[0]);
  return size;
}

// The title shrinks (down to 8 px) when it would not fit between the side paddings.
int titleFontPx(const std::string& title, const LayoutStyle& style, const FieldImageParams& p) {
  vtkNew<vtkTextProperty> heading;
  applyTextStyle(heading, style, style.titleFontPx, true);
  const int widthPx = textSize(heading, title)[0];
  const int room = p.width - 2 * p.padding;
  if (widthPx <= room || widthPx == 0) return style.titleFontPx;
  return std::max(8, static_cast<int>(style.titleFontPx * static_cast<double>(room) / widthPx));
}

int titleHeightPx(const std::string& title, const LayoutStyle& style, int fontPx) {
  vtkNew<vtkTextProperty> heading;
  applyTextStyle(heading, style, fontPx, true);
  return textSize(heading, title)[1];
}

// Axes (FieldImageParams::axes): round ticks of the field's x and y extents, their labels and
// the two axis titles, in bands left of and below the field.
struct Axes {
  RoundTicks x, y;
  std::string formatX, formatY, titleX, titleY;
  int tickPx = 0, gapPx = 0, widestYLabelPx = 0, lineHeightPx = 0;
  double leftBand = 0, bottomBand = 0;  // px
};

Axes fieldAxes(const Grid& g, const FieldImageParams& p, const LayoutStyle& style) {
  Axes a;
  if (!p.axes) return a;
  const double x1 = g.origin[0] + (g.dims[0] - 1) * g.spacing[0];
  const double y1 = g.origin[1] + (g.dims[1] - 1) * g.spacing[1];
  a.x = roundTicks(g.origin[0], x1);
  a.y = roundTicks(g.origin[1], y1);
  a.formatX = tickLabelFormat(a.x);
  a.formatY = tickLabelFormat(a.y);
  const std::string unit = p.axes_unit.empty() ? "" : " (" + p.axes_unit + ")";
  a.titleX = "x" + unit;
  a.titleY = "y" + unit;
  a.tickPx = std::max(3, style.labelFontPx / 3);
  a.gapPx = std::max(2, style.labelFontPx / 4);
  vtkNew<vtkTextProperty> label;
  applyTextStyle(label, style, style.labelFontPx, false);
  for (double v : a.y.values)
    a.widestYLabelPx = std::max(a.widestYLabelPx, textSize(label, formatLabel(v, a.formatY))[0]);
  a.lineHeightPx = textSize(label, "0.9")[1];
  a.leftBand = a.tickPx + a.gapPx + a.widestYLabelPx + a.gapPx + a.lineHeightPx + a.gapPx;
  a.bottomBand = a.tickPx + a.gapPx + a.lineHeightPx + a.gapPx + a.lineHeightPx + a.gapPx;
  return a;
}

struct Layout {
  PixelRect field;      // top-left based picture pixels
  PixelRect legend;     // top-left based picture pixels
  double titleTop = 0;  // picture y of the title's top edge
  double pixelsPerUnit = 1.0;
};

// Title above, field and legend side by side below it; the whole group is centred in the
// picture inside `padding`, and the field keeps its aspect ratio.
Layout computeLayout(const Grid& grid, const FieldImageParams& p, const LayoutStyle& style,
                     const LegendSize& legend, int titleHeight, const Axes& axes) {
  const double pad = p.padding;
  const double titleBand = p.title.empty() ? 0.0 : titleHeight + pad;
  const double legendBand = p.scalar_bar ? legend.width + pad : 0.0;
  const double availW = p.width - 2 * pad - legendBand - axes.leftBand;
  const double availH = p.height - 2 * pad - titleBand - axes.bottomBand;
  if (availW < 4 || availH < 4)
    throw ParamError("padding", "leaves " + formatNumber(std::max(0.0, std::min(availW, availH)), 10) +
                                    " px for the field in a " + std::to_string(p.width) + " x " +
                                    std::to_string(p.height) +
                                    " px picture; make the picture larger or padding smaller");
  const double extentX = (grid.dims[0] - 1) * grid.spacing[0];
  const double extentY = (grid.dims[1] - 1) * grid.spacing[1];
  Layout layout;
  layout.pixelsPerUnit = std::min(availW / extentX, availH / extentY);
  const double fieldW = extentX * layout.pixelsPerUnit, fieldH = extentY * layout.pixelsPerUnit;
  // The legend is as tall as the field, but no shorter than 12 label lines when room allows.
  const double legendH =
      p.scalar_bar ? std::max(fieldH, std::min(availH, 12.0 * style.labelFontPx)) : 0.0;
  const double bodyH = std::max(fieldH, legendH);
  const double groupTop = pad + 0.5 * (availH - bodyH);
  const double middle = groupTop + titleBand + 0.5 * bodyH;
  layout.titleTop = groupTop;
  layout.field.left = 0.5 * (p.width - (axes.leftBand + fieldW + legendBand)) + axes.leftBand;
  layout.field.right = layout.field.left + fieldW;
  layout.field.top = middle - 0.5 * fieldH;
  layout.field.bottom = middle + 0.5 * fieldH;
  layout.legend = {layout.field.right + pad, middle - 0.5 * legendH,
                   layout.field.right + pad + legend.width, middle + 0.5 * legendH};
  return layout;
}

// ---------------------------------------------------------------------------------------------
// VTK pieces

vtkSmartPointer<vtkImageData> toImageData(const Slice& slice) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(slice.grid.dims[0], slice.grid.dims[1], 1);
  image->SetOrigin(slice.grid.origin[0], slice.grid.origin[1], slice.grid.origin[2]);
  image->SetSpacing(slice.grid.spacing[0], slice.grid.spacing[1], 1.0);
  vtkNew<vtkDoubleArray> values;
  values->SetName(slice.name.empty() ? "values" : slice.name.c_str());
  values->SetNumberOfTuples(static_cast<vtkIdType>(slice.values.size()));
  std::copy(slice.values.begin(), slice.values.end(), values->GetPointer(0));
  image->GetPointData()->SetScalars(values);
  return image;
}

// Colours are looked up per pixel from the interpolated value (InterpolateScalarsBeforeMapping),
// not interpolated between node colours, and drawn unlit, so a pixel shows exactly the map's
// colour for the field value there.
vtkSmartPointer<vtkActor> makeFieldActor(const Slice& slice, vtkLookupTable* table) {
  vtkNew<vtkDataSetMapper> mapper;
  mapper->SetInputData(toImageData(slice));
  mapper->SetLookupTable(table);
  mapper->UseLookupTableScalarRangeOn();
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToMapScalars();
  mapper->ScalarVisibilityOn();
  mapper->InterpolateScalarsBeforeMappingOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkTextActor> makeTitle(const std::string& text, const LayoutStyle& style, int fontPx,
                                        double x, double y) {
  auto title = vtkSmartPointer<vtkTextActor>::New();
  title->SetInput(text.c_str());
  title->SetTextScaleModeToNone();
  applyTextStyle(title->GetTextProperty(), style, fontPx, true);
  title->GetTextProperty()->SetJustificationToCentered();
  title->GetTextProperty()->SetVerticalJustificationToTop();
  title->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
  title->SetPosition(x, y);
  return title;
}

// The axes' tick marks and lines as one 2D actor, labels and titles as text actors, placed in
// display coordinates (origin bottom-left) around the field's rectangle.
void addAxes(OffscreenRenderer& renderer, const Axes& a, const Grid& g, const Layout& layout,
             const LayoutStyle& style, int height) {
  const PixelRect& f = layout.field;
  const double s = layout.pixelsPerUnit;
  const double bottom = height - f.bottom, top = height - f.top;  // display y of the field edges
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  const auto segment = [&](double x0, double y0, double x1, double y1) {
    const vtkIdType ids[2] = {points->InsertNextPoint(x0, y0, 0), points->InsertNextPoint(x1, y1, 0)};
    lines->InsertNextCell(2, ids);
  };
  segment(f.left, bottom, f.right, bottom);
  segment(f.left, bottom, f.left, top);
  const auto text = [&](const std::string& t, double x, double y, bool centred, double angle) {
    auto actor = vtkSmartPointer<vtkTextActor>::New();
    actor->SetInput(t.c_str());
    actor->SetTextScaleModeToNone();
    applyTextStyle(actor->GetTextProperty(), style, style.labelFontPx, false);
    actor->GetTextProperty()->SetOrientation(angle);
    if (centred) {
      actor->GetTextProperty()->SetJustificationToCentered();
      actor->GetTextProperty()->SetVerticalJustificationToTop();
    } else {
      actor->GetTextProperty()->SetJustificationToRight();
      actor->GetTextProperty()->SetVerticalJustificationToCentered();
    }
    actor->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    actor->SetPosition(x, y);
    renderer.addProp(actor);
  };
  const double labelY = bottom - a.tickPx - a.gapPx;
  for (double v : a.x.values) {
    const double x = f.left + (v - g.origin[0]) * s;
    segment(x, bottom, x, bottom - a.tickPx);
    text(formatLabel(v, a.formatX), x, labelY, true, 0);
  }
  const double labelX = f.left - a.tickPx - a.gapPx;
  for (double v : a.y.values) {
    const double y = bottom + (v - g.origin[1]) * s;
    segment(f.left, y, f.left - a.tickPx, y);
    text(formatLabel(v, a.formatY), labelX, y, false, 0);
  }
  text(a.titleX, 0.5 * (f.left + f.right), labelY - a.lineHeightPx - a.gapPx, true, 0);
  // The y title turned by 90 degrees: "centred, top" then means centred on y, right of x.
  text(a.titleY, labelX - a.widestYLabelPx - a.gapPx - a.lineHeightPx, 0.5 * (bottom + top), true,
       90);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(style.text[0], style.text[1], style.text[2]);
  actor->GetProperty()->SetLineWidth(1.0);
  renderer.addProp(actor);
}

// `box` is in display coordinates (origin bottom-left): x, y, width, height.
vtkSmartPointer<vtkScalarBarActor> makeLegend(vtkLookupTable* table, const std::string& title,
                                              const LayoutStyle& style, const LegendSize& size,
                                              const std::array<double, 4>& box) {
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(table);
  bar->SetTitle(title.c_str());
  vtkNew<vtkDoubleArray> labels;
  for (double v : labelValues({table->GetRange()[0], table->GetRange()[1]}))
    labels->InsertNextValue(v);
  bar->SetCustomLabels(labels);
  bar->UseCustomLabelsOn();
  bar->SetLabelFormat(legendLabelFormat({table->GetRange()[0], table->GetRange()[1]}).c_str());
  bar->SetMaximumNumberOfColors(table->GetNumberOfTableValues());
  bar->UnconstrainedFontSizeOn();
  bar->SetTextPositionToSucceedScalarBar();
  bar->SetBarRatio(static_cast<double>(size.barPx) / size.width);
  bar->SetTextPad(size.labelGapPx);
  bar->SetVerticalTitleSeparation(size.labelGapPx);
  bar->DrawTickLabelsOn();
  bar->DrawFrameOff();
  bar->DrawBackgroundOff();
  applyTextStyle(bar->GetLabelTextProperty(), style, style.labelFontPx, false);
  applyTextStyle(bar->GetTitleTextProperty(), style, style.labelFontPx, true);
  bar->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
  bar->GetPositionCoordinate()->SetValue(box[0], box[1]);
  bar->GetPosition2Coordinate()->SetCoordinateSystemToDisplay();
  bar->GetPosition2Coordinate()->SetValue(box[2], box[3]);
  return bar;
}

// Parallel projection looking down -z, scaled and shifted so the grid extent lands on
// layout.field (pixel = W/2 + (x - focal_x) * s, s = H / (2 * ParallelScale)).
void placeCamera(vtkCamera* camera, const Grid& grid, const Layout& layout, int width, int height) {
  const double s = layout.pixelsPerUnit;
  const double extentX = (grid.dims[0] - 1) * grid.spacing[0];
  const double extentY = (grid.dims[1] - 1) * grid.spacing[1];
  const double centreX = grid.origin[0] + 0.5 * extentX, centreY = grid.origin[1] + 0.5 * extentY;
  const double pixelX = 0.5 * (layout.field.left + layout.field.right);
  const double pixelY = 0.5 * (layout.field.top + layout.field.bottom);
  const double focalX = centreX - (pixelX - 0.5 * width) / s;
  const double focalY = centreY + (pixelY - 0.5 * height) / s;  // picture y runs downwards
  const double z = grid.origin[2];
  const double distance = 10.0 * std::max(extentX, extentY);
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(focalX, focalY, z);
  camera->SetPosition(focalX, focalY, z + distance);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(0.5 * height / s);
  // Anything within `distance` of the plane, in front or behind, stays visible (overlays).
  camera->SetClippingRange(1e-3 * distance, 2.0 * distance);
}

}  // namespace

// ---------------------------------------------------------------------------------------------

struct FieldImageScene::Impl {
  OffscreenRenderer renderer;
  std::array<double, 2> range;
  double planeZ;
  double overlayZ;
  PixelRect fieldPixels;
  PixelRect fieldPixelsWithAxes;

  Impl(const Slice& slice, const FieldImageParams& p, const LayoutStyle& style)
      : renderer(p.width, p.height, style.background),
        range(colourRange(slice, p)),
        planeZ(slice.grid.origin[2]) {
    const Grid& g = slice.grid;
    overlayZ =
        planeZ + 1e-3 * std::max((g.dims[0] - 1) * g.spacing[0], (g.dims[1] - 1) * g.spacing[1]);
    const std::string legendTitle = p.scalar_bar_title.empty() ? slice.name : p.scalar_bar_title;
    const LegendSize legend = legendSize(range, legendTitle, style);
    const int titlePx = titleFontPx(p.title, style, p);
    const Axes axes = fieldAxes(g, p, style);
    const Layout layout =
        computeLayout(g, p, style, legend, titleHeightPx(p.title, style, titlePx), axes);
    fieldPixels = layout.field;
    fieldPixelsWithAxes = {layout.field.left - axes.leftBand, layout.field.top, layout.field.right,
                           layout.field.bottom + axes.bottomBand};
    // 1024 entries: the table's quantisation stays below one 8-bit level even where viridis
    // changes fastest (256 entries would be up to ~2.5 levels off on a smooth ramp).
    vtkSmartPointer<vtkLookupTable> table =
        makeLookupTable(ColorMap::byName(p.colormap), range[0], range[1], kTableEntries, kMaskedGrey);
    renderer.addProp(makeFieldActor(slice, table));
    if (!p.title.empty())
      renderer.addProp(
          makeTitle(p.title, style, titlePx, 0.5 * p.width, p.height - layout.titleTop));
    if (p.scalar_bar) {
      const PixelRect& b = layout.legend;
      renderer.addProp(
          makeLegend(table, legendTitle, style, legend,
                     {b.left, p.height - b.bottom, b.right - b.left, b.bottom - b.top}));
    }
    if (p.axes) addAxes(renderer, axes, g, layout, style, p.height);
    placeCamera(renderer.camera(), g, layout, p.width, p.height);
  }
};

FieldImageScene::FieldImageScene(const ScalarField& field, const FieldImageParams& params) {
  validateFieldImageParams(params);
  const Slice slice = extractSlice(field, params.slice_index);
  impl_ = std::make_unique<Impl>(slice, params, styleFor(params));
}

FieldImageScene::~FieldImageScene() = default;

OffscreenRenderer& FieldImageScene::renderer() { return impl_->renderer; }
std::array<double, 2> FieldImageScene::range() const { return impl_->range; }
double FieldImageScene::planeZ() const { return impl_->planeZ; }
double FieldImageScene::overlayZ() const { return impl_->overlayZ; }
PixelRect FieldImageScene::fieldPixels() const { return impl_->fieldPixels; }
PixelRect FieldImageScene::fieldPixelsWithAxes() const { return impl_->fieldPixelsWithAxes; }
RgbaImage FieldImageScene::render() { return impl_->renderer.render(); }
void FieldImageScene::renderToPng(const std::filesystem::path& file) {
  impl_->renderer.renderToPng(file);
}

RgbaImage renderFieldImage(const ScalarField& field, const FieldImageParams& params) {
  FieldImageScene scene(field, params);
  return scene.render();
}

void writeFieldImagePng(const ScalarField& field, const FieldImageParams& params,
                        const std::filesystem::path& file) {
  FieldImageScene scene(field, params);
  scene.renderToPng(file);
}

}  // namespace fluidviz
