#pragma once
// Poincaré index of a planar field: the winding number of the field along a closed loop, i.e.
// the number of turns the field vector makes while the loop is traversed once counter-clockwise,
//   index = (1 / 2 pi) * sum over loop samples of the wrapped angle increments of w.
// By the Poincaré–Hopf theorem (for the plane: the argument principle) the winding number of a
// loop on which the field does not vanish equals the sum of the indices of the zeros it
// encloses. Valid for any integer index.
//
// Loops are refined adaptively: a segment is split until the field turns by less than pi/16
// between its ends, so the sum of wrapped increments is the true winding number whenever the
// field stays away from zero on the loop.
#include <optional>
#include <vector>

#include "filters/topology/PlanarField.h"

namespace fluidviz::topology {

/// One sample of the field on a loop (index space).
struct LoopSample {
  double theta;  ///< loop parameter; for circles the polar angle around the centre (rad)
  Vec2 q;        ///< position (cells)
  Vec2 w;        ///< field (index-space velocity)
};

/// Samples the interpolant on the circle of `radius` cells around `centre`, starting at angle 0,
/// counter-clockwise, `base_samples` evenly plus adaptive refinement. nullopt if the field is
/// exactly zero at a sample.
std::optional<std::vector<LoopSample>> sampleCircle(const PlanarField& field, const Vec2& centre,
                                                    double radius, int base_samples);

/// Winding number of the sampled field (samples of one closed traversal; the last sample
/// connects back to the first).
int windingNumber(const std::vector<LoopSample>& loop);

/// Index of the field on a circle (index space). nullopt if the field vanishes on the loop.
std::optional<int> indexOnCircle(const PlanarField& field, const Vec2& centre, double radius,
                                 int base_samples = 720);

/// Winding number along a closed polygon given in WORLD coordinates (x, y; closed implicitly,
/// counter-clockwise gives the index sum). Each edge is sampled adaptively. nullopt if the
/// field vanishes on the polygon. Throws std::invalid_argument if a vertex is outside the grid.
std::optional<int> windingNumberAlongPolygon(const PlanarField& field,
                                             const std::vector<Vec2>& polygon_world);

/// Angle in (-pi, pi] by which vector b is turned against vector a.
double turningAngle(const Vec2& a, const Vec2& b);

}  // namespace fluidviz::topology
