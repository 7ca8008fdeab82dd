#pragma once
// A 2D scalar field (or one z-slice of a 3D field) as a picture: the field fills the plot area
// with its true aspect ratio (parallel projection of the grid's physical extent, nodes at their
// grid positions, values interpolated bilinearly-by-triangles between nodes and coloured through
// the colour map per pixel), with an optional title above and colour legend on the right.
//
// Callers that want more on top (streamlines, glyphs, critical points) build a FieldImageScene,
// add their actors in world coordinates at z = overlayZ(), and render it.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/Params.h"
#include "fieldviz/core/RoundTicks.h"
#include "fieldviz/render/ColorMap.h"
#include "fieldviz/render/OffscreenRenderer.h"
#include "fieldviz/render/PictureStyle.h"
#include "fieldviz/render/RgbaImage.h"

namespace fluidviz {

// Units, ranges and meanings of the members: their describe() declarations below.
struct FieldImageParams {
  int width = kDefaultPictureWidth;
  int height = 800;
  std::string colormap = "viridis";  ///< one of ColorMap::names()
  std::string title;
  std::optional<double> range_min;  ///< in field units
  std::optional<double> range_max;  ///< must exceed range_min
  bool scalar_bar = true;
  std::string scalar_bar_title;
  Background background = Background::white;
  int slice_index = -1;  ///< z node layer of a 3D field, [0, nz - 1]; -1 (none) for 2D fields
  int padding = 16;
  bool axes = false;
  std::string axes_unit = "m";

  /// slice_z meant a layer index here and a height in output.lic; it is now two keys.
  static constexpr std::array retiredKeys{RetiredKey{
      "slice_z", "was split: give slice_index (the z node layer of a 3D field, [0, nz-1]) "
                 "here; slice_height (m) is the key of output.lic"}};

  template <class V>
  static void describe(V& v) {
    v(&FieldImageParams::width,
      {.key = "width", .unit = "px", .description = "picture width", .min = 16, .max = 8192});
    v(&FieldImageParams::height,
      {.key = "height", .unit = "px", .description = "picture height", .min = 16, .max = 8192});
    v(&FieldImageParams::colormap,
      {.key = "colormap", .description = "colour map", .choices = ColorMap::names()});
    v(&FieldImageParams::title,
      {.key = "title", .description = "text above the field; empty: no title"});
    v(&FieldImageParams::range_min,
      {.key = "range_min",
       .description = "value drawn with the first colour; empty: smallest finite value"});
    v(&FieldImageParams::range_max,
      {.key = "range_max",
       .description =
           "value drawn with the last colour (> range_min); empty: largest finite value"});
    v(&FieldImageParams::scalar_bar,
      {.key = "scalar_bar", .description = "draw a colour legend right of the field"});
    v(&FieldImageParams::scalar_bar_title,
      {.key = "scalar_bar_title", .description = "legend title; empty: the field's name"});
    v(&FieldImageParams::background, {.key = "background",
                                      .description = "white (black text) or dark (white text)"});
    v(&FieldImageParams::slice_index,
      {.key = "slice_index",
       .description = "z index of the slice of a 3D field, [0, nz-1]; -1: none (2D fields)",
       .min = -1,
       .max = 1000000});
    v(&FieldImageParams::axes,
      {.key = "axes",
       .description = "x and y axes with round ticks in world coordinates below and left of "
                      "the field"});
    v(&FieldImageParams::axes_unit,
      {.key = "axes_unit",
       .description = "length unit in the axis titles \"x (m)\", at most 16 characters, only a name (nothing is "
                      "converted)"});
    v(&FieldImageParams::padding, {.key = "padding",
                                   .unit = "px",
                                   .description = "empty margin around field, title and legend",
                                   .min = 0,
                                   .max = 1000});
  }
};

/// Checks every key's range and the rules between keys that need no field (range_min <
/// range_max, room left for the field). Throws ParamError naming the key and the allowed range.
void validateFieldImageParams(const FieldImageParams& params);

/// The legend labels of a colour range: about 5 round values (1, 2 or 5 x 10^k steps,
/// fieldviz/core/RoundTicks.h) inside it; one label for an empty range.
RoundTicks legendTicks(const std::array<double, 2>& range);
/// printf format of those labels: the decimals their step needs, so that neighbours differ.
std::string legendLabelFormat(const std::array<double, 2>& range);

/// A rectangle in picture pixels: x from the left edge, y from the top edge, continuous (pixel
/// (i, j) covers [i, i+1] x [j, j+1]).
struct PixelRect {
  double left = 0, top = 0, right = 0, bottom = 0;
};

/// The renderer with the field, title and legend set up, so that callers can add overlays.
class FieldImageScene {
 public:
  /// Throws ParamError (bad parameters, missing/invalid slice_index for the field) or
  /// std::invalid_argument (field values do not match its grid, no finite value to set a range).
  FieldImageScene(const ScalarField& field, const FieldImageParams& params);
  ~FieldImageScene();
  FieldImageScene(const FieldImageScene&) = delete;
  FieldImageScene& operator=(const FieldImageScene&) = delete;

  OffscreenRenderer& renderer();
  /// The value range mapped onto the colour map: {min, max}, min < max.
  std::array<double, 2> range() const;
  /// World z of the drawn field plane, and a z just above it (towards the camera) for overlays.
  double planeZ() const;
  double overlayZ() const;
  /// Where the field's physical extent [x0, x1] x [y0, y1] lands in the picture.
  PixelRect fieldPixels() const;
  /// fieldPixels() grown by the axes' bands (tick labels and titles left and below); equal to
  /// fieldPixels() without axes.
  PixelRect fieldPixelsWithAxes() const;

  RgbaImage render();
  void renderToPng(const std::filesystem::path& file);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The field as a picture (see FieldImageScene for errors).
RgbaImage renderFieldImage(const ScalarField& field, const FieldImageParams& params);
/// The field as a PNG file, written atomically.
void writeFieldImagePng(const ScalarField& field, const FieldImageParams& params,
                        const std::filesystem::path& file);

}  // namespace fluidviz
