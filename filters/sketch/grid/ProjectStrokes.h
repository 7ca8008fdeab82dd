#pragma once
// Strokes onto the grid: every point of an evenly resampled stroke deposits its velocity
// (unit tangent x speed) on the four nodes around it with bilinear weights, and the deposits
// are smoothed by a Gaussian as a normalised convolution (Knutsson & Westin 1993):
//   v0 = G * m / max(G * w, W)
// m the deposited velocities, w the deposited weights, W the median of G * w at the strokes'
// own points. On a stroke G * w ~ W, so v0 is the drawn velocity (a plain convolution would
// scale it down by the kernel's width); off the strokes v0 fades like the Gaussian; where
// strokes cross, the velocities are averaged.
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/sketch/grid/PlaneGrid.h"
#include "filters/sketch/strokes/Stroke.h"

namespace fluidviz::sketch {

/// v0 on `grid` from strokes already resampled evenly (each at its own spacing). Points
/// outside the grid deposit nothing (a periodic side wraps them). sigma in cells (0 = no
/// smoothing). Throws std::invalid_argument if no stroke point lies on the grid.
VectorField projectStrokes(const std::vector<Stroke>& strokes, const Grid& grid,
                           const PlaneGrid& plane, double sigmaCells,
                           const std::string& name = "velocity");

}  // namespace fluidviz::sketch
