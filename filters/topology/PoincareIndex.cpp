#include "filters/topology/PoincareIndex.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace fluidviz::topology {

namespace {
constexpr double kMaxTurn = std::numbers::pi / 16;  // field turn allowed between samples
constexpr int kMaxRefinement = 30;                  // halvings of one base segment

using LoopPoint = std::function<Vec2(double)>;  // loop parameter -> index-space point

/// Appends samples in (a, b] of the parametrised loop, halving segments where the field turns
/// by more than kMaxTurn. Returns false if the field is exactly zero at a sample.
bool refineSegment(const PlanarField& f, const LoopPoint& at, LoopSample a, double b,
                   int depth, std::vector<LoopSample>& out) {
  const Vec2 qb = at(b);
  const LoopSample sb{b, qb, f(qb)};
  if (sb.w.squaredNorm() == 0.0) return false;
  if (depth < kMaxRefinement && std::abs(turningAngle(a.w, sb.w)) > kMaxTurn) {
    const double m = 0.5 * (a.theta + b);
    if (!refineSegment(f, at, a, m, depth + 1, out)) return false;
    return refineSegment(f, at, out.back(), b, depth + 1, out);
  }
  out.push_back(sb);
  return true;
}

/// Samples a closed loop parametrised over [t0, t1) at `n` even steps with refinement.
std::optional<std::vector<LoopSample>> sampleLoop(const PlanarField& f, const LoopPoint& at,
                                                  double t0, double t1, int n) {
  std::vector<LoopSample> out;
  const Vec2 q0 = at(t0);
  out.push_back({t0, q0, f(q0)});
  if (out.back().w.squaredNorm() == 0.0) return std::nullopt;
  for (int k = 1; k <= n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    if (!refineSegment(f, at, out.back(), t, 0, out)) return std::nullopt;
  }
  out.pop_back();  // the last sample repeats the first
  return out;
}
}  // namespace

double turningAngle(const Vec2& a, const Vec2& b) {
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

std::optional<std::vector<LoopSample>> sampleCircle(const PlanarField& field, const Vec2& centre,
                                                    double radius, int base_samples) {
  const LoopPoint at = [&](double theta) {
    return Vec2(centre + radius * Vec2(std::cos(theta), std::sin(theta)));
  };
  return sampleLoop(field, at, 0.0, 2 * std::numbers::pi, base_samples);
}

int windingNumber(const std::vector<LoopSample>& loop) {
  double total = 0.0;
  for (std::size_t k = 0; k < loop.size(); ++k)
    total += turningAngle(loop[k].w, loop[(k + 1) % loop.size()].w);
  return static_cast<int>(std::lround(total / (2 * std::numbers::pi)));
}

std::optional<int> indexOnCircle(const PlanarField& field, const Vec2& centre, double radius,
                                 int base_samples) {
  auto loop = sampleCircle(field, centre, radius, base_samples);
  if (!loop) return std::nullopt;
  return windingNumber(*loop);
}

std::optional<int> windingNumberAlongPolygon(const PlanarField& field,
                                             const std::vector<Vec2>& polygon_world) {
  const int n = static_cast<int>(polygon_world.size());
  if (n < 3) throw std::invalid_argument("a winding-number loop needs at least 3 vertices");
  std::vector<Vec2> q;
  for (const Vec2& p : polygon_world) {
    q.push_back(field.toIndex(Vec3(p.x(), p.y(), 0.0)));
    if (field.distanceToBoundary(q.back()) < -1e-9)
      throw std::invalid_argument("winding-number loop leaves the grid");
  }
  // Parameter t in [0, n): edge floor(t), linear along it; 16 base samples per edge.
  const LoopPoint at = [&](double t) {
    const int e = std::min(static_cast<int>(std::floor(t)), n - 1);
    const double u = t - e;
    return Vec2((1 - u) * q[e] + u * q[(e + 1) % n]);
  };
  auto loop = sampleLoop(field, at, 0.0, double(n), 16 * n);
  if (!loop) return std::nullopt;
  return windingNumber(*loop);
}

}  // namespace fluidviz::topology
