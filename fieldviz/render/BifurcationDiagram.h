#pragma once
// Bifurcation diagram of a parameter sweep: the critical points found at each parameter value,
// drawn as their type's glyph (CriticalPointGlyphs.h) against the parameter, in two panels side
// by side - the x and the y coordinate of each point - so that points that split, merge or
// change type can be followed whichever way they move. A legend of the types shown is placed
// below. Drawn with 2D actors in picture pixels through the off-screen renderer (no X needed).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/render/PictureStyle.h"
#include "fieldviz/render/RgbaImage.h"

namespace fluidviz {

struct DiagramPoint {
  double parameter = 0.0;
  double x = 0.0, y = 0.0;  ///< position of the critical point (m)
  std::string type;         ///< type name (glyph)
};

struct BifurcationDiagramParams {
  int width = 1100;                   ///< px, [300, 8192]
  int height = 560;                   ///< px of the panels (legend added below), [200, 8192]
  std::string title;                  ///< above the panels; empty: none
  std::string parameter_label = "parameter";  ///< horizontal axis of both panels
  Background background = Background::white;
  double glyph_size = 13.0;           ///< px
  std::vector<double> steps;          ///< parameter values run (drawn as light vertical lines)
  /// Shared value range of the two panels' vertical axes (m); empty: from the points.
  std::optional<std::array<double, 2>> position_range;
};


/// The diagram with its legend. Throws std::invalid_argument for sizes out of range.
RgbaImage renderBifurcationDiagram(const std::vector<DiagramPoint>& points,
                                   const BifurcationDiagramParams& params);

}  // namespace fluidviz
