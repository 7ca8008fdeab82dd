#pragma once
// Line probes: a field sampled at `samples` evenly spaced points from `start` to `end` (both
// included), bilinearly in 2D and trilinearly in 3D (fieldviz/core/Sampling.h), and the
// deviation of the field along that line from a reference profile (e.g. Ghia, Ghia & Shin 1982,
// Tables I and II, for the lid-driven cavity's centrelines).
//
// The abscissa of a profile is the distance s from `start` along the line (m): the point at s is
// start + s (end - start) / |end - start|. Points outside the field's grid (e.g. Ghia's rows on
// the walls, outside the node-centred grid of a lattice-Boltzmann field) have no value: NaN in
// a profile, skipped in a comparison.
#include <vector>

#include "fieldviz/core/Field.h"

namespace fluidviz::probe {

/// A straight line of evenly spaced sample points.
struct ProbeLine {
  Vec3 start = Vec3::Zero();
  Vec3 end = Vec3::Zero();
  int samples = 2;  ///< >= 2

  double length() const { return (end - start).norm(); }
  /// The point at distance s from start, along the line.
  Vec3 pointAt(double s) const;
  /// Distance from start of sample n in [0, samples - 1].
  double distanceOf(int n) const;
};

/// One sampled point of a profile.
struct ProfilePoint {
  double distance = 0.0;  ///< s from the line's start (m)
  Vec3 position = Vec3::Zero();
  double value = 0.0;     ///< NaN outside the grid
};

/// The field at the line's samples. Throws std::invalid_argument if samples < 2 or the line has
/// zero length.
std::vector<ProfilePoint> sampleLine(const ScalarField& field, const ProbeLine& line);

/// A reference value at distance s along the line.
struct ReferencePoint {
  double distance = 0.0;
  double value = 0.0;
};

struct ProfileDeviation {
  int compared = 0;   ///< reference points inside the grid
  double max = 0.0;   ///< max |field - reference| over them
  double rms = 0.0;   ///< sqrt(mean (field - reference)^2) over them
};

/// |field - reference| with the field sampled at each reference point's position on the line
/// (the same bilinear/trilinear sample as the profile's); points outside the grid and reference
/// values that are NaN are skipped.
/// compared = 0 (max = rms = NaN) if no point lies inside.
ProfileDeviation compareWithReference(const ScalarField& field, const ProbeLine& line,
                                      const std::vector<ReferencePoint>& reference);

}  // namespace fluidviz::probe
