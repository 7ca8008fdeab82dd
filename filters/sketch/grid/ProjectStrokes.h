#pragma once
// Strokes onto the grid: every point of an evenly resampled stroke deposits its velocity
// (unit tangent x speed) on the four nodes around it with bilinear weights (m), and its weight
// (w). The deposits are smoothed by a Gaussian as a normalised convolution (Knutsson & Westin
// 1993, "Normalized and differential convolution", CVPR):
//   velocity = G * m / G * w       the drawn velocity, averaged where strokes meet
//   coverage = min(G * w / W, 1)   W: the median of G * w at the strokes' own points
// A plain convolution G * m would scale the drawn speed down by the kernel's width (by about
// 1 / (sqrt(2 pi) sigma) across a straight stroke); here the speed stays the drawn one and the
// coverage says how firmly each node is held to it (1 on a stroke, fading like the Gaussian).
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/sketch/grid/PlaneGrid.h"
#include "filters/sketch/strokes/Stroke.h"

namespace fluidviz::sketch {

struct ProjectedStrokes {
  VectorField velocity;          ///< G * m / G * w; 0 where no stroke reaches
  std::vector<double> coverage;  ///< in [0, 1]; 0 where no stroke reaches
};

/// Strokes already resampled evenly (each at its own spacing) on `grid`. Points outside the grid
/// deposit nothing (a periodic side wraps them). The last point of a closed stroke, or of one
/// that crosses a periodic grid once (from x to x + period), is its first and is not deposited
/// again. sigma in cells (0 = no smoothing). Throws
/// std::invalid_argument if no stroke point lies on the grid.
ProjectedStrokes projectStrokes(const std::vector<Stroke>& strokes, const Grid& grid,
                                const PlaneGrid& plane, double sigmaCells,
                                const std::string& name = "velocity");

}  // namespace fluidviz::sketch
