#include "filters/probe/LineProbe.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "fieldviz/core/Sampling.h"

namespace fluidviz::probe {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void checkLine(const ProbeLine& line) {
  if (line.samples < 2)
    throw std::invalid_argument("a line probe needs at least 2 samples, not " +
                                std::to_string(line.samples));
  if (!(line.length() > 0.0))
    throw std::invalid_argument("a line probe's start and end must differ");
}

}  // namespace

Vec3 ProbeLine::pointAt(double s) const { return start + (s / length()) * (end - start); }

double ProbeLine::distanceOf(int n) const {
  return length() * static_cast<double>(n) / static_cast<double>(samples - 1);
}

std::vector<ProfilePoint> sampleLine(const ScalarField& field, const ProbeLine& line) {
  checkLine(line);
  std::vector<ProfilePoint> profile(static_cast<std::size_t>(line.samples));
  for (int n = 0; n < line.samples; ++n) {
    ProfilePoint& p = profile[static_cast<std::size_t>(n)];
    p.distance = line.distanceOf(n);
    // The last point is `end` itself, not start + length * unit (which may round outside).
    p.position = n == line.samples - 1 ? line.end : line.pointAt(p.distance);
    p.value = sample(field, p.position).value_or(kNaN);
  }
  return profile;
}

ProfileDeviation compareWithReference(const ScalarField& field, const ProbeLine& line,
                                      const std::vector<ReferencePoint>& reference) {
  checkLine(line);
  ProfileDeviation d;
  double sumSquares = 0.0;
  for (const ReferencePoint& r : reference) {
    const std::optional<double> v = sample(field, line.pointAt(r.distance));
    if (!v || !std::isfinite(r.value)) continue;
    const double e = std::abs(*v - r.value);
    d.max = std::max(d.max, e);
    sumSquares += e * e;
    ++d.compared;
  }
  if (d.compared == 0) return {0, kNaN, kNaN};
  d.rms = std::sqrt(sumSquares / d.compared);
  return d;
}

}  // namespace fluidviz::probe
