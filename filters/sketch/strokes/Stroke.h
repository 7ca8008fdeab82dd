#pragma once
// A stroke: a polyline drawn by the user, read as a streamline of the flow it sketches, with the
// speed the flow has along it (Judice & Giraldi 2012, "Sketching fluid flows"). Noisy input is
// resampled at an even arc length and smoothed along the curve before it is projected.
#include <vector>

#include "fieldviz/core/Grid.h"

namespace fluidviz::sketch {

struct Stroke {
  std::vector<Vec3> points;  ///< in drawing order (the flow's direction); z ignored (2D)
  double speed = 1.0;        ///< speed of the flow along the stroke (m/s); sign flips direction
};

/// Arc length of the polyline.
double strokeLength(const Stroke& s);

/// Points at arc-length spacing `spacing` (m) from the first point to the last (both kept; the
/// last interval is stretched to fit so that every interval has length L / ceil(L / spacing)).
/// Repeated points are dropped first. Throws std::invalid_argument for fewer than two distinct
/// points or spacing <= 0.
Stroke resampleStroke(const Stroke& s, double spacing);

/// Gaussian smoothing along the curve of an evenly resampled stroke: point n becomes the
/// weighted mean of its neighbours n +- k with weights exp(-(k ds)^2 / (2 sigma^2)), the window
/// shrunk symmetrically near the ends so the end points stay where they were drawn (a
/// one-sided window would pull them inwards). sigma = 0 returns the stroke unchanged.
Stroke smoothStroke(const Stroke& s, double sigma);

/// Unit tangent at each point: central differences inside, one-sided at the ends.
std::vector<Vec3> strokeTangents(const Stroke& s);

}  // namespace fluidviz::sketch
