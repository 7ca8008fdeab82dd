#include "filters/topology/SectorAnalysis.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fluidviz::topology {

namespace {
constexpr double kPi = std::numbers::pi;

struct Crossing {
  double theta;
  int level;  // phi = level * pi at the crossing
};

/// phi along the loop, continuous (unwrapped), one value per sample, plus the value reached
/// after one full turn (phi[0] + 2 pi (index - 1)).
struct RelativeAngle {
  std::vector<double> phi;
  double afterTurn;
};

RelativeAngle relativeAngle(const std::vector<LoopSample>& loop) {
  RelativeAngle r;
  const std::size_t n = loop.size();
  double fieldAngle = std::atan2(loop[0].w.y(), loop[0].w.x());
  r.phi.push_back(fieldAngle - loop[0].theta);
  for (std::size_t k = 1; k <= n; ++k) {
    fieldAngle += turningAngle(loop[k - 1].w, loop[k % n].w);
    const double theta = k < n ? loop[k].theta : loop[0].theta + 2 * kPi;
    if (k < n)
      r.phi.push_back(fieldAngle - theta);
    else
      r.afterTurn = fieldAngle - theta;
  }
  return r;
}

/// Angle theta in (a, b) where phi = level * pi, by bisection on the interpolant: phi(theta) is
/// continued from sample a by the (small) turn of the field.
double refineCrossing(const PlanarField& f, const Vec2& centre, double radius,
                      const LoopSample& a, double phiA, double thetaB, double level) {
  double lo = a.theta, hi = thetaB;
  auto g = [&](double theta) {
    const Vec2 w = f(Vec2(centre + radius * Vec2(std::cos(theta), std::sin(theta))));
    return phiA + turningAngle(a.w, w) - (theta - a.theta) - level * kPi;
  };
  const double gLo = g(lo);
  if (gLo == 0.0) return lo;  // exactly radial at the sample
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double gMid = g(mid);
    if (gMid == 0.0) return mid;
    if ((gMid > 0) == (gLo > 0))
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

/// Schmitt-trigger pass over phi: the band floor(phi / pi) changes only when phi passes the
/// band's edge by more than `hysteresis`.
std::vector<Crossing> findCrossings(const PlanarField& f, const Vec2& centre, double radius,
                                    const std::vector<LoopSample>& loop, const RelativeAngle& ra,
                                    double hysteresis) {
  const int n = static_cast<int>(loop.size());
  const double shift = ra.afterTurn - ra.phi[0];
  auto phiAt = [&](int k) { return ra.phi[k % n] + (k >= n ? shift : 0.0); };
  auto sampleAt = [&](int k) {
    LoopSample s = loop[k % n];
    if (k >= n) s.theta += 2 * kPi;
    return s;
  };
  // Start where phi is farthest from a multiple of pi.
  int start = 0;
  for (int k = 1; k < n; ++k)
    if (std::abs(std::sin(ra.phi[k])) > std::abs(std::sin(ra.phi[start]))) start = k;
  int band = static_cast<int>(std::floor(ra.phi[start] / kPi));
  std::vector<Crossing> out;
  auto record = [&](int k, int level, bool up) {
    int j = k - 1;  // last sample on the far side of the level
    while (j > start && (up ? phiAt(j) > level * kPi : phiAt(j) < level * kPi)) --j;
    const double theta = refineCrossing(f, centre, radius, sampleAt(j), phiAt(j),
                                        sampleAt(j + 1).theta, level);
    out.push_back({std::fmod(theta, 2 * kPi), level});
  };
  for (int k = start + 1; k <= start + n; ++k) {
    const double phi = phiAt(k);
    while (phi > (band + 1) * kPi + hysteresis) record(k, ++band, true);
    while (phi < band * kPi - hysteresis) record(k, band--, false);
  }
  return out;
}

SectorType sectorBetween(int levelFrom, int levelTo) {
  if (levelTo == levelFrom + 1) return SectorType::Elliptic;
  if (levelTo == levelFrom - 1) return SectorType::Hyperbolic;
  return SectorType::Parabolic;
}

/// Merges cyclically adjacent parabolic sectors into one.
std::vector<Sector> mergeParabolicRuns(const std::vector<Sector>& raw) {
  const int m = static_cast<int>(raw.size());
  int first = 0;  // start after a non-parabolic sector so that runs do not wrap
  while (first < m && raw[first].type == SectorType::Parabolic) ++first;
  if (first == m) return {Sector{SectorType::Parabolic, raw.front().begin, raw.back().end}};
  std::vector<Sector> out;
  for (int c = 1; c <= m; ++c) {
    const Sector& s = raw[(first + c) % m];
    if (s.type == SectorType::Parabolic && !out.empty() &&
        out.back().type == SectorType::Parabolic)
      out.back().end = s.end;
    else
      out.push_back(s);
  }
  return out;
}
}  // namespace

std::vector<SectorBoundary> SectorDecomposition::hyperbolicBoundaries() const {
  std::vector<int> used;
  for (const Sector& s : sectors)
    if (s.type == SectorType::Hyperbolic) {
      used.push_back(s.begin);
      used.push_back(s.end);
    }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<SectorBoundary> out;
  for (int b : used) out.push_back(boundaries[b]);
  return out;
}

SectorDecomposition analyzeSectors(const PlanarField& field, const Vec2& centre, double radius,
                                   const std::vector<LoopSample>& loop, double hysteresis) {
  SectorDecomposition d;
  const RelativeAngle ra = relativeAngle(loop);
  const int turns = static_cast<int>(std::lround((ra.afterTurn - ra.phi[0]) / (2 * kPi)));
  d.index = 1 + turns;
  const std::vector<Crossing> crossings =
      findCrossings(field, centre, radius, loop, ra, hysteresis);
  if (crossings.empty()) {
    // No sector boundary: a centre or focus (field never radial), or a node whose field is
    // radial all around (one parabolic sector).
    const bool radialEverywhere = std::all_of(ra.phi.begin(), ra.phi.end(), [&](double p) {
      return std::abs(std::sin(p)) <= std::sin(std::max(hysteresis, 1e-12));
    });
    if (radialEverywhere) d.counts.parabolic = 1;
    return d;
  }
  const int m = static_cast<int>(crossings.size());
  for (const Crossing& c : crossings) d.boundaries.push_back({c.theta, c.level % 2 == 0});
  std::vector<Sector> raw;
  for (int i = 0; i < m; ++i) {
    const int next = i + 1 < m ? crossings[i + 1].level : crossings[0].level + 2 * turns;
    raw.push_back({sectorBetween(crossings[i].level, next), i, (i + 1) % m});
  }
  d.sectors = mergeParabolicRuns(raw);
  for (const Sector& s : d.sectors) {
    if (s.type == SectorType::Elliptic) ++d.counts.elliptic;
    if (s.type == SectorType::Hyperbolic) ++d.counts.hyperbolic;
    if (s.type == SectorType::Parabolic) ++d.counts.parabolic;
  }
  return d;
}

}  // namespace fluidviz::topology
