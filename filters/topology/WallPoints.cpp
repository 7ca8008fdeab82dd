#include "filters/topology/WallPoints.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace fluidviz::topology {

namespace {

// One cell face of a wall: between a resting solid node s (possibly the virtual node outside a
// resting side) and the fluid node f = s + d. Positions in doubled index coordinates (2 i) keep
// the face ends (half-integer indices) exact.
struct WallFace {
  int fi = 0, fj = 0;              // the fluid node
  std::array<int, 2> from{}, to{}; // doubled index coordinates of the face's ends
  std::array<int, 2> step{};       // to - from, halved: the chain's direction (solid on the left)
  Vec2 middle;                     // index coordinates of the face's middle (the wall point)
};

// The sign change of u_t between two faces of a chain.
struct ShearZero {
  double arc = 0.0;  // cells along the chain
  Vec2 at;           // index coordinates
  Vec2 tangent;      // unit, index space, along the chain
  int sign = 0;      // +1: - to + (attachment), -1: + to - (separation)
  int corner = -1;   // the concave corner it lies within kWallCornerCells of, -1: none
};

bool insideGrid(const Grid& g, int i, int j) {
  return i >= 0 && j >= 0 && i < g.dims[0] && j < g.dims[1];
}

// A resting solid node, or the virtual node just outside a resting side (halfway bounce-back: the
// wall lies half a cell outside the edge nodes).
bool restingSolidAt(const Grid& g, const RestingWalls& walls, int i, int j) {
  if (insideGrid(g, i, j)) return !walls.solid.empty() && walls.solid[g.index(i, j)];
  const bool alongY = j >= 0 && j < g.dims[1], alongX = i >= 0 && i < g.dims[0];
  if (alongY && i == -1) return walls.side(DomainSide::x_min);
  if (alongY && i == g.dims[0]) return walls.side(DomainSide::x_max);
  if (alongX && j == -1) return walls.side(DomainSide::y_min);
  if (alongX && j == g.dims[1]) return walls.side(DomainSide::y_max);
  return false;
}

bool fluidAt(const VectorField& v, const PointMask& mask, int i, int j) {
  if (!insideGrid(v.grid, i, j)) return false;
  const std::size_t n = v.grid.index(i, j);
  return (mask.empty() || !mask[n]) && v.values[n].allFinite();
}

constexpr std::array<std::array<int, 2>, 4> kFaceNormals{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};

std::vector<WallFace> wallFaces(const VectorField& v, const PointMask& mask,
                                const RestingWalls& walls) {
  const Grid& g = v.grid;
  std::vector<WallFace> faces;
  for (int j = -1; j <= g.dims[1]; ++j)
    for (int i = -1; i <= g.dims[0]; ++i) {
      if (!restingSolidAt(g, walls, i, j)) continue;
      for (const auto& d : kFaceNormals) {
        if (!fluidAt(v, mask, i + d[0], j + d[1])) continue;
        WallFace f;
        f.fi = i + d[0], f.fj = j + d[1];
        f.step = {-d[1], d[0]};  // d turned by +90 degrees: the solid lies on the left
        const std::array<int, 2> middle2{2 * i + d[0], 2 * j + d[1]};
        f.from = {middle2[0] - f.step[0], middle2[1] - f.step[1]};
        f.to = {middle2[0] + f.step[0], middle2[1] + f.step[1]};
        f.middle = Vec2(0.5 * middle2[0], 0.5 * middle2[1]);
        faces.push_back(f);
      }
    }
  return faces;
}

// The face that continues `f` at its end: a left turn first (round the solid's corner), then
// straight on, then a right turn. Where two solids touch diagonally, the left turn keeps each
// chain on one side of the fluid.
int nextFace(const WallFace& f, const std::vector<WallFace>& faces,
             const std::map<std::array<int, 2>, std::vector<int>>& startingAt) {
  const auto found = startingAt.find(f.to);
  if (found == startingAt.end()) return -1;
  const std::array<std::array<int, 2>, 3> preference{
      {{-f.step[1], f.step[0]}, f.step, {f.step[1], -f.step[0]}}};
  for (const auto& want : preference)
    for (int e : found->second)
      if (faces[e].step == want) return e;
  return -1;
}

struct Chain {
  std::vector<int> faces;
  bool closed = false;
};

// The faces in wall order: open chains (a wall that ends at the domain edge or at a mask that is
// no resting wall) from their first face, then the closed loops.
std::vector<Chain> wallChains(const std::vector<WallFace>& faces) {
  std::map<std::array<int, 2>, std::vector<int>> startingAt;
  for (int e = 0; e < static_cast<int>(faces.size()); ++e) startingAt[faces[e].from].push_back(e);
  std::vector<int> next(faces.size(), -1);
  std::vector<char> hasPrevious(faces.size(), 0), used(faces.size(), 0);
  for (int e = 0; e < static_cast<int>(faces.size()); ++e) {
    next[e] = nextFace(faces[e], faces, startingAt);
    if (next[e] >= 0) hasPrevious[next[e]] = 1;
  }
  std::vector<Chain> chains;
  const auto follow = [&](int first) {
    Chain c;
    for (int e = first; e >= 0 && !used[e]; e = next[e]) {
      used[e] = 1;
      c.faces.push_back(e);
    }
    c.closed = next[c.faces.back()] == first;
    chains.push_back(std::move(c));
  };
  for (int e = 0; e < static_cast<int>(faces.size()); ++e)
    if (!hasPrevious[e]) follow(e);
  for (int e = 0; e < static_cast<int>(faces.size()); ++e)
    if (!used[e]) follow(e);
  return chains;
}

// The chain's tangent at face k: from face k - 2 to face k + 2 (wrapping round a closed chain,
// clamped at the ends of an open one), which smooths the staircase of a curved wall.
Vec2 smoothedTangent(const std::vector<WallFace>& faces, const Chain& c, int k) {
  const int n = static_cast<int>(c.faces.size());
  const auto at = [&](int m) {
    m = c.closed ? ((m % n) + n) % n : std::clamp(m, 0, n - 1);
    return faces[c.faces[m]].middle;
  };
  const Vec2 t = at(k + 2) - at(k - 2);
  if (t.norm() > 0) return t.normalized();
  const WallFace& f = faces[c.faces[k]];
  return Vec2(f.step[0], f.step[1]);
}

// The sign changes of the tangential velocity of the fluid nodes along one chain.
std::vector<ShearZero> shearZeros(const VectorField& v, const std::vector<WallFace>& faces,
                                  const Chain& c, double& length) {
  struct Sample {
    double arc, ut;
    Vec2 at, tangent;
  };
  std::vector<Sample> samples;
  length = 0.0;
  for (int k = 0; k < static_cast<int>(c.faces.size()); ++k) {
    const WallFace& f = faces[c.faces[k]];
    if (k > 0) length += (f.middle - faces[c.faces[k - 1]].middle).norm();
    const Vec2 t = smoothedTangent(faces, c, k);
    const Vec3& u = v.values[v.grid.index(f.fi, f.fj)];
    const double ut = u.x() * t.x() + u.y() * t.y();
    if (ut != 0.0) samples.push_back({length, ut, f.middle, t});
  }
  if (c.closed && c.faces.size() > 1)
    length += (faces[c.faces.front()].middle - faces[c.faces.back()].middle).norm();
  std::vector<ShearZero> zeros;
  const auto between = [&](const Sample& a, Sample b, double wrap) {
    if ((a.ut < 0) == (b.ut < 0)) return;
    b.arc += wrap;
    const double s = a.ut / (a.ut - b.ut);
    zeros.push_back({a.arc + s * (b.arc - a.arc), a.at + s * (b.at - a.at),
                     (a.tangent + s * (b.tangent - a.tangent)).normalized(),
                     a.ut < 0 ? +1 : -1});
  };
  for (std::size_t k = 1; k < samples.size(); ++k) between(samples[k - 1], samples[k], 0.0);
  if (c.closed && samples.size() > 1) between(samples.back(), samples.front(), length);
  return zeros;
}

// Arc positions (cells along the chain) of its concave corners: where the wall turns into the
// fluid (a right turn, the solid being on the left) between two straight runs of at least two
// faces. A staircase of a curved wall turns by single faces, a corner of a box or a step does
// not.
std::vector<double> concaveCorners(const std::vector<WallFace>& faces, const Chain& c) {
  const int n = static_cast<int>(c.faces.size());
  const auto step = [&](int k) -> const std::array<int, 2>& {
    return faces[c.faces[c.closed ? ((k % n) + n) % n : k]].step;
  };
  std::vector<double> corners;
  double arc = 0.0;
  for (int k = 0; k < n; ++k) {
    if (k > 0) arc += (faces[c.faces[k]].middle - faces[c.faces[k - 1]].middle).norm();
    if (!c.closed && (k < 1 || k + 2 >= n)) continue;
    const auto& a = step(k);
    const auto& b = step(k + 1);
    const bool rightTurn = a[0] * b[1] - a[1] * b[0] < 0;
    if (rightTurn && step(k - 1) == a && step(k + 2) == b) corners.push_back(arc + 0.5 * M_SQRT1_2);
  }
  return corners;
}

// Marks the sign changes within kWallCornerCells of a concave corner with that corner: the flow
// in a corner has eddies that shrink geometrically into it (Moffatt 1964, "Viscous and resistive
// eddies near a sharp corner"), so a grid cuts them off, and the cells next to the corner hold
// sign flips of that unresolved flow. They count together, with their signs, as one corner point
// (none when they cancel); a resolved corner eddy's points farther out stay points of their own.
void markCornerZeros(std::vector<ShearZero>& zeros, const std::vector<double>& corners,
                     bool closed, double length) {
  for (ShearZero& z : zeros)
    for (int k = 0; k < static_cast<int>(corners.size()); ++k) {
      double d = std::abs(z.arc - corners[k]);
      if (closed) d = std::min(d, length - std::fmod(d, length));
      if (d <= kWallCornerCells) z.corner = k;
    }
}

// Groups of zeros closer than kWallClusterCells along the chain, or next to one corner; on a
// closed chain the groups start after the widest gap, so that no group is cut where the chain closes.
std::vector<std::vector<ShearZero>> clusters(std::vector<ShearZero> zeros, bool closed,
                                             double length) {
  std::vector<std::vector<ShearZero>> groups;
  if (zeros.empty()) return groups;
  if (closed) {
    for (ShearZero& z : zeros) z.arc = std::fmod(z.arc, length);
    std::sort(zeros.begin(), zeros.end(),
              [](const ShearZero& a, const ShearZero& b) { return a.arc < b.arc; });
    std::size_t widest = 0;
    double gap = zeros.front().arc + length - zeros.back().arc;
    for (std::size_t k = 1; k < zeros.size(); ++k)
      if (zeros[k].arc - zeros[k - 1].arc > gap) gap = zeros[k].arc - zeros[k - 1].arc, widest = k;
    std::rotate(zeros.begin(), zeros.begin() + static_cast<long>(widest), zeros.end());
    for (std::size_t k = 1; k < zeros.size(); ++k)
      if (zeros[k].arc < zeros[k - 1].arc) zeros[k].arc += length;
  }
  groups.push_back({zeros.front()});
  for (std::size_t k = 1; k < zeros.size(); ++k) {
    const bool sameCorner = zeros[k].corner >= 0 && zeros[k].corner == zeros[k - 1].corner;
    if (zeros[k].arc - zeros[k - 1].arc > kWallClusterCells && !sameCorner) groups.emplace_back();
    groups.back().push_back(zeros[k]);
  }
  return groups;
}

CriticalPoint wallPoint(const Grid& g, const std::vector<ShearZero>& group, int sign) {
  Vec2 at = Vec2::Zero(), tangent = Vec2::Zero();
  for (const ShearZero& z : group) at += z.at, tangent += z.tangent;
  at /= static_cast<double>(group.size());
  tangent.normalize();
  CriticalPoint p;
  p.position = Vec3(g.origin[0] + at.x() * g.spacing[0], g.origin[1] + at.y() * g.spacing[1],
                    g.origin[2]);
  p.cell = {std::clamp(static_cast<int>(std::floor(at.x())), 0, std::max(g.dims[0] - 2, 0)),
            std::clamp(static_cast<int>(std::floor(at.y())), 0, std::max(g.dims[1] - 2, 0))};
  p.type = sign > 0 ? CriticalPointType::Attachment : CriticalPointType::Separation;
  // The fluid lies on the right of the chain: the normal into it is the tangent turned by -90
  // degrees (index space; world space differs only by the spacings).
  const Vec2 normal(tangent.y() * g.spacing[1], -tangent.x() * g.spacing[0]);
  p.separatrix_directions = {{normal.normalized(), sign < 0}};
  p.loop_radius = kWallSeparatrixOffsetCells;
  p.cluster_size = static_cast<int>(group.size());
  return p;
}

}  // namespace

std::vector<CriticalPoint> findWallPoints(const VectorField& v, const PointMask& mask,
                                          const RestingWalls& walls) {
  require2DGrid(v.grid, "findWallPoints");
  std::vector<CriticalPoint> points;
  if (!walls.any()) return points;
  const std::vector<WallFace> faces = wallFaces(v, mask, walls);
  for (const Chain& c : wallChains(faces)) {
    double length = 0.0;
    std::vector<ShearZero> zeros = shearZeros(v, faces, c, length);
    markCornerZeros(zeros, concaveCorners(faces, c), c.closed, length);
    for (const auto& group : clusters(std::move(zeros), c.closed, length)) {
      int sign = 0;
      for (const ShearZero& z : group) sign += z.sign;
      // Consecutive sign changes alternate: a group sums to -1, 0 or +1.
      if (sign != 0) points.push_back(wallPoint(v.grid, group, sign));
    }
  }
  return points;
}

PointMask restingWallLayer(const Grid& g, const PointMask& mask, const RestingWalls& walls) {
  PointMask layer(g.nodeCount(), 0);
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      if (restingSolidAt(g, walls, i, j)) {
        layer[g.index(i, j)] = 1;
        continue;
      }
      if (!mask.empty() && mask[g.index(i, j)]) continue;
      for (const auto& d : kFaceNormals)
        if (restingSolidAt(g, walls, i + d[0], j + d[1])) layer[g.index(i, j)] = 1;
    }
  return layer;
}

bool inWallLayer(const Grid& g, const PointMask& layer, const Vec3& p) {
  if (layer.empty()) return false;
  for (std::size_t n : cellCornersAt(g, p).nodes)
    if (layer[n]) return true;
  return false;
}

}  // namespace fluidviz::topology
