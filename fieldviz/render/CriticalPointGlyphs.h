#pragma once
// Critical points drawn as glyphs: one shape and colour per critical point type, a filled shape
// with a dark outline so that it reads on any background (LIC, colour maps), and a legend strip
// that lists the types shown. Types are named as the topology core names them ("saddle",
// "monkey_saddle", "centre", ...: filters/topology/CriticalPoint.h toString); this module only
// knows the names, so rendering does not depend on the filter.
//
//   FieldImageScene scene(speed, picture);
//   addCriticalPointGlyphs(scene, {{position, "saddle"}, ...}, 16.0, pixelsPerUnit);
//   RgbaImage img = stackImages(scene.render(), renderGlyphLegend(entries, img.width, "white"));
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/RgbaImage.h"

namespace fluidviz {

/// Shapes a glyph can have (outline within the unit circle).
enum class GlyphShape {
  Circle, Square, Diamond, TriangleUp, TriangleDown, Pentagon, Hexagon, Octagon,
  Star3, Cross, Star5, Star6, Star4, Star8
};

struct GlyphStyle {
  GlyphShape shape = GlyphShape::Circle;
  Rgb fill{0.6, 0.6, 0.6};
  double scale = 1.0;  ///< size relative to the nominal glyph size (stars are drawn larger)
};

/// The glyph of a critical point type name. Every type of the topology core has its own shape
/// and colour:
///   saddle: red cross (X)              monkey_saddle: magenta 6-point star
///   centre: white circle               spiral_sink: cyan triangle down
///   spiral_source: orange triangle up  sink: blue square
///   source: yellow diamond             saddle_node: tan pentagon
///   cusp: pink 3-point star            dipole: green hexagon
///   degenerate: grey octagon           unknown (and names not listed): dark grey 5-point star
///   attachment: green 4-point star     separation: crimson 8-point star (points on walls)
GlyphStyle criticalPointGlyph(const std::string& typeName);

/// Type names in legend order (the order of the table above).
const std::vector<std::string>& criticalPointTypeOrder();

/// Closed outline of a shape in the unit circle, counter-clockwise, first point not repeated.
std::vector<std::array<double, 2>> glyphOutline(GlyphShape shape);

struct GlyphPoint {
  Vec3 position;     ///< world coordinates (z is replaced by the overlay depth)
  std::string type;  ///< type name
};

/// Adds the glyphs to the scene above every other overlay (texture, lines, arrowheads):
/// `sizePx` is the diameter of a glyph in picture pixels, `pixelsPerUnit` the scene's scale
/// (picture pixels per world unit). Throws std::invalid_argument for sizePx outside [2, 200].
void addCriticalPointGlyphs(FieldImageScene& scene, const std::vector<GlyphPoint>& points,
                            double sizePx, double pixelsPerUnit);

/// Adds glyphs of `type` centred at display positions (px from the bottom-left corner) as 2D
/// actors of `renderer`: for legends and plots drawn in picture pixels.
void addGlyphs2D(OffscreenRenderer& renderer, const std::vector<std::array<double, 2>>& centres,
                 const std::string& type, double sizePx);
/// The same with an explicit style (shape, fill, scale).
void addGlyphs2D(OffscreenRenderer& renderer, const std::vector<std::array<double, 2>>& centres,
                 const GlyphStyle& style, double sizePx);

/// One legend entry: a glyph of `type`, or (line = true) a short line in `line_color`.
struct LegendEntry {
  std::string label;
  std::string type;
  bool line = false;
  Rgb line_color{1.0, 1.0, 1.0};
  /// Set: a filled circle of this colour instead of the type's glyph (3D pictures draw their
  /// points as spheres).
  std::optional<Rgb> dot_color;
};

/// A strip `width` px wide that lists the entries left to right (wrapping into rows), each a
/// glyph of `glyphPx` px or a line sample followed by its label. `background` as
/// FieldImageParams::background. Height follows from the rows.
RgbaImage renderGlyphLegend(const std::vector<LegendEntry>& entries, int width,
                            Background background, double glyphPx = 16.0);

/// `top` above `bottom`, left-aligned; the narrower one is padded with `fill`.
RgbaImage stackImages(const RgbaImage& top, const RgbaImage& bottom,
                      const std::array<std::uint8_t, 3>& fill = {255, 255, 255});

}  // namespace fluidviz
