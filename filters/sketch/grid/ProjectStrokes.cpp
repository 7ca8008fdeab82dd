#include "filters/sketch/grid/ProjectStrokes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fluidviz::sketch {

namespace {

/// The four nodes around a point and their bilinear weights; false if the point is off the grid
/// (beyond a zero-flux side; periodic sides wrap, the cell past the last node included).
struct Cell {
  int nodes[4];
  double weights[4];
};

bool cellAt(const Grid& grid, const PlaneGrid& g, const Vec3& p, Cell& c) {
  const Vec3 q = grid.toIndexSpace(p);
  auto axis = [](double x, int n, SketchBoundary b, int& i0, int& i1, double& f) {
    if (b == SketchBoundary::periodic) {
      const double wrapped = x - n * std::floor(x / n);
      i0 = std::min(static_cast<int>(std::floor(wrapped)), n - 1);
      f = wrapped - i0;
      i1 = (i0 + 1) % n;
      return true;
    }
    if (x < 0.0 || x > n - 1) return false;
    i0 = std::min(static_cast<int>(std::floor(x)), n - 2);
    f = x - i0;
    i1 = i0 + 1;
    return true;
  };
  int i0, i1, j0, j1;
  double fx, fy;
  if (!axis(q[0], g.nx, g.bx, i0, i1, fx) || !axis(q[1], g.ny, g.by, j0, j1, fy)) return false;
  c = {{g.index(i0, j0), g.index(i1, j0), g.index(i0, j1), g.index(i1, j1)},
       {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy}};
  return true;
}

/// A closed stroke (a circle), or one that crosses a periodic grid once (its last point the
/// image of its first): its last point is its first, which must deposit only once.
bool endsWhereItStarts(const Stroke& s, const Grid& grid, const PlaneGrid& g) {
  if (s.points.size() < 3) return false;
  Vec3 d = grid.toIndexSpace(s.points.back()) - grid.toIndexSpace(s.points.front());
  if (g.bx == SketchBoundary::periodic) d[0] -= g.nx * std::round(d[0] / g.nx);
  if (g.by == SketchBoundary::periodic) d[1] -= g.ny * std::round(d[1] / g.ny);
  return std::hypot(d[0], d[1]) < 1e-9;
}

double sampleAt(const Cell& c, const std::vector<double>& a) {
  double s = 0.0;
  for (int k = 0; k < 4; ++k) s += c.weights[k] * a[c.nodes[k]];
  return s;
}

}  // namespace

ProjectedStrokes projectStrokes(const std::vector<Stroke>& strokes, const Grid& grid,
                                const PlaneGrid& g, double sigmaCells, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(g.size());
  std::vector<double> mu(n, 0.0), mw(n, 0.0), weight(n, 0.0);
  std::vector<Cell> cells;  // of every deposited point, for W
  for (const Stroke& s : strokes) {
    const std::vector<Vec3> t = strokeTangents(s);
    const std::size_t deposited = s.points.size() - (endsWhereItStarts(s, grid, g) ? 1 : 0);
    for (std::size_t p = 0; p < deposited; ++p) {
      Cell c;
      if (!cellAt(grid, g, s.points[p], c)) continue;
      for (int k = 0; k < 4; ++k) {
        mu[c.nodes[k]] += c.weights[k] * s.speed * t[p][0];
        mw[c.nodes[k]] += c.weights[k] * s.speed * t[p][1];
        weight[c.nodes[k]] += c.weights[k];
      }
      cells.push_back(c);
    }
  }
  if (cells.empty()) throw std::invalid_argument("no stroke point lies on the grid");
  mu = gaussianSmooth(g, mu, sigmaCells);
  mw = gaussianSmooth(g, mw, sigmaCells);
  weight = gaussianSmooth(g, weight, sigmaCells);
  std::vector<double> atStrokes;
  atStrokes.reserve(cells.size());
  for (const Cell& c : cells) atStrokes.push_back(sampleAt(c, weight));
  auto middle = atStrokes.begin() + static_cast<std::ptrdiff_t>(atStrokes.size() / 2);
  std::nth_element(atStrokes.begin(), middle, atStrokes.end());
  const double full = *middle;
  ProjectedStrokes out{{name, grid, std::vector<Vec3>(n, Vec3::Zero())},
                       std::vector<double>(n, 0.0)};
  // Below 1e-12 of the full coverage a node is too far from every stroke for m / w to mean
  // anything (the truncated Gaussian's round-off).
  for (std::size_t k = 0; k < n; ++k) {
    if (!(weight[k] > 1e-12 * full)) continue;
    out.velocity.values[k] = Vec3(mu[k] / weight[k], mw[k] / weight[k], 0.0);
    out.coverage[k] = std::min(weight[k] / full, 1.0);
  }
  return out;
}

}  // namespace fluidviz::sketch
