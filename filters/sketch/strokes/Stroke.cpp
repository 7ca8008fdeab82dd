#include "filters/sketch/strokes/Stroke.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fluidviz::sketch {

namespace {

Vec3 planar(const Vec3& p) { return {p[0], p[1], 0.0}; }

std::vector<Vec3> distinctPoints(const Stroke& s) {
  std::vector<Vec3> out;
  for (const Vec3& p : s.points) {
    if (!p.allFinite()) throw std::invalid_argument("stroke point is not finite");
    const Vec3 q = planar(p);
    if (out.empty() || (q - out.back()).norm() > 0.0) out.push_back(q);
  }
  return out;
}

}  // namespace

double strokeLength(const Stroke& s) {
  double length = 0.0;
  for (std::size_t n = 1; n < s.points.size(); ++n)
    length += (planar(s.points[n]) - planar(s.points[n - 1])).norm();
  return length;
}

Stroke resampleStroke(const Stroke& s, double spacing) {
  if (!(spacing > 0.0)) throw std::invalid_argument("resampling spacing must be > 0");
  const std::vector<Vec3> pts = distinctPoints(s);
  if (pts.size() < 2) throw std::invalid_argument("a stroke needs two distinct points");
  std::vector<double> arc(pts.size(), 0.0);
  for (std::size_t n = 1; n < pts.size(); ++n) arc[n] = arc[n - 1] + (pts[n] - pts[n - 1]).norm();
  const double length = arc.back();
  const int intervals = std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
  Stroke out{.points = {}, .speed = s.speed};
  out.points.reserve(static_cast<std::size_t>(intervals) + 1);
  std::size_t seg = 1;
  for (int k = 0; k <= intervals; ++k) {
    const double target = length * k / intervals;
    while (seg + 1 < pts.size() && arc[seg] < target) ++seg;
    const double t = (target - arc[seg - 1]) / (arc[seg] - arc[seg - 1]);
    out.points.push_back(pts[seg - 1] + std::clamp(t, 0.0, 1.0) * (pts[seg] - pts[seg - 1]));
  }
  out.points.back() = pts.back();  // exactly the drawn end, whatever the round-off
  return out;
}

Stroke smoothStroke(const Stroke& s, double sigma) {
  if (sigma < 0.0) throw std::invalid_argument("stroke smoothing sigma must be >= 0");
  const int n = static_cast<int>(s.points.size());
  if (sigma == 0.0 || n < 3) return s;
  const double ds = strokeLength(s) / (n - 1);
  const int reach = static_cast<int>(std::ceil(3.0 * sigma / ds));
  Stroke out = s;
  for (int i = 1; i + 1 < n; ++i) {
    const int half = std::min({reach, i, n - 1 - i});  // symmetric window: ends stay put
    Vec3 sum = Vec3::Zero();
    double weights = 0.0;
    for (int k = -half; k <= half; ++k) {
      const double w = std::exp(-0.5 * (k * ds / sigma) * (k * ds / sigma));
      sum += w * s.points[static_cast<std::size_t>(i + k)];
      weights += w;
    }
    out.points[static_cast<std::size_t>(i)] = sum / weights;
  }
  return out;
}

std::vector<Vec3> strokeTangents(const Stroke& s) {
  const std::size_t n = s.points.size();
  std::vector<Vec3> t(n, Vec3::Zero());
  if (n < 2) return t;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = s.points[i == 0 ? 0 : i - 1];
    const Vec3& b = s.points[i + 1 == n ? n - 1 : i + 1];
    const Vec3 d = planar(b) - planar(a);
    const double len = d.norm();
    t[i] = len > 0.0 ? Vec3(d / len) : Vec3(Vec3::Zero());
  }
  return t;
}

}  // namespace fluidviz::sketch
