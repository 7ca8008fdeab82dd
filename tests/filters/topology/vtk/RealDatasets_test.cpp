// Validation of the topology core on public real flows (tests/data/vtkdata/README.md), issue 15:
// on a z layer of each dataset, as `fluidviz topology --slice z=K` sees it (its in-plane part),
//  1. every Morse point lies within 0.01 cells of an exact zero of the bilinear interpolant, and
//     every exact zero belongs to a reported point: the reference is the closed-form zero-finder
//     below, independent of the core's sign test + Newton + subdivision;
//  2. its type is the one VTK's vtkVectorFieldTopology gives the same zero (tests/support/
//     VtkTopologyPeer.h), wherever VTK finds one near it.
// The exact zeros: in a cell with corner values v00, v10, v01, v11 the interpolant is
// u(s, t) = a0 + a1 s + a2 t + a3 s t (likewise w with b0..b3). Eliminating s between u = 0 and
// w = 0 leaves (a0 + a2 t)(b1 + b3 t) - (b0 + b2 t)(a1 + a3 t) = 0, a quadratic in t; each root
// in [0, 1] gives s from the component whose coefficient of s is larger.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/CriticalPointClassifier.h"
#include "filters/topology/VectorFieldTopology.h"
#include "tests/support/RealDatasetLayers.h"
#include "tests/support/VtkTopologyPeer.h"

namespace fluidviz::topology {
namespace {

using testing::RealLayer;

constexpr double kInCell = 1e-12;
constexpr double kClusterReach = 3.0;  // a root this far outside [0, 1] still counts (round-off)

std::vector<double> rootsInUnitInterval(double a, double b, double c) {
  std::vector<double> t;
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (scale == 0.0) return t;  // a curve of zeros, not isolated ones
  if (std::abs(a) <= 1e-12 * scale) {
    if (std::abs(b) > 1e-12 * scale) t.push_back(-c / b);
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return t;
    // Citardauq form for the smaller root: no cancellation.
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    t.push_back(q / a);
    if (q != 0.0) t.push_back(c / q);
  }
  std::vector<double> inside;
  for (double r : t)
    if (r >= -kInCell && r <= 1 + kInCell) inside.push_back(std::clamp(r, 0.0, 1.0));
  return inside;
}

// Cells the core leaves out on purpose (CriticalPointDetector.h): a non-finite corner, or an edge
// whose two nodes are exactly zero (a segment of zeros: a wall or a solid, not a point).
bool skippedCell(const Vec3 c[4]) {
  for (int k = 0; k < 4; ++k)
    if (!c[k].allFinite()) return true;
  const int edges[4][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}};
  for (const auto& e : edges)
    if (c[e[0]].head<2>().isZero(0) && c[e[1]].head<2>().isZero(0)) return true;
  return false;
}

// A zero exactly on a node with an exactly zero neighbour node ends a segment of zeros.
bool endOfAZeroSegment(const VectorField& f, const Vec2& q) {
  const int i = static_cast<int>(std::lround(q.x())), j = static_cast<int>(std::lround(q.y()));
  if ((q - Vec2(i, j)).norm() > 1e-12) return false;
  const int nx = f.grid.dims[0], ny = f.grid.dims[1];
  const int neighbours[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
  for (const auto& n : neighbours)
    if (n[0] >= 0 && n[0] < nx && n[1] >= 0 && n[1] < ny &&
        f.values[n[1] * nx + n[0]].head<2>().isZero(0))
      return true;
  return false;
}

/// Every isolated zero of the bilinear interpolant, in index coordinates, each once.
std::vector<Vec2> exactZeros(const VectorField& f) {
  const int nx = f.grid.dims[0], ny = f.grid.dims[1];
  std::vector<Vec2> zeros;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const Vec3 c[4] = {f.values[j * nx + i], f.values[j * nx + i + 1],
                         f.values[(j + 1) * nx + i], f.values[(j + 1) * nx + i + 1]};
      if (skippedCell(c)) continue;
      const double a0 = c[0].x(), a1 = c[1].x() - c[0].x(), a2 = c[2].x() - c[0].x(),
                   a3 = c[0].x() - c[1].x() - c[2].x() + c[3].x();
      const double b0 = c[0].y(), b1 = c[1].y() - c[0].y(), b2 = c[2].y() - c[0].y(),
                   b3 = c[0].y() - c[1].y() - c[2].y() + c[3].y();
      for (double t : rootsInUnitInterval(a2 * b3 - b2 * a3, a0 * b3 + a2 * b1 - b0 * a3 - b2 * a1,
                                          a0 * b1 - b0 * a1)) {
        const double da = a1 + a3 * t, db = b1 + b3 * t;
        const double s = std::abs(da) >= std::abs(db) ? -(a0 + a2 * t) / da : -(b0 + b2 * t) / db;
        if (!std::isfinite(s) || s < -kInCell || s > 1 + kInCell) continue;
        const Vec2 q(i + std::clamp(s, 0.0, 1.0), j + t);
        if (endOfAZeroSegment(f, q)) continue;
        bool seen = false;
        for (const Vec2& z : zeros) seen = seen || (z - q).norm() < 1e-9;
        if (!seen) zeros.push_back(q);
      }
    }
  return zeros;
}

Vec2 indexOf(const Grid& g, const Vec2& world) {
  return {(world.x() - g.origin[0]) / g.spacing[0], (world.y() - g.origin[1]) / g.spacing[1]};
}

template <class P, class F>
double nearestDistance(const std::vector<P>& set, const Vec2& q, F&& indexPosition) {
  double d = 1e300;
  for (const P& p : set) d = std::min(d, (indexPosition(p) - q).norm());
  return d;
}

class RealDatasets : public ::testing::TestWithParam<RealLayer> {};

TEST_P(RealDatasets, CriticalPointsAreExactBilinearZerosWithVtkVectorFieldTopologysTypes) {
  const RealLayer d = GetParam();
  const VectorField field = testing::readRealLayer(d);
  const Grid& g = field.grid;
  const std::vector<CriticalPoint> ours = findCriticalPoints(field, {});
  const std::vector<Vec2> exact = exactZeros(field);
  const std::vector<testing::VtkPoint> theirs = testing::vtkCriticalPoints(field);
  auto oursAt = [&](const CriticalPoint& p) {
    return indexOf(g, Vec2(p.position.x(), p.position.y()));
  };

  int morse = 0, typed = 0, sameType = 0;
  double worst = 0.0;
  for (const CriticalPoint& p : ours) {
    const Vec2 q = oursAt(p);
    if (!p.morse) {
      std::printf("  non-Morse %s at cell (%.3f, %.3f)\n", p.typeName().c_str(), q.x(), q.y());
      continue;
    }
    ++morse;
    const double apart = nearestDistance(exact, q, [](const Vec2& z) { return z; });
    worst = std::max(worst, apart);
    EXPECT_LE(apart, 0.01) << p.typeName() << " at cell (" << q.transpose()
                           << ") is not an exact zero of the bilinear field";
    const testing::VtkPoint* match = nullptr;
    double best = 0.5;  // VTK's triangle-linear zero of the same point is within half a cell
    for (const testing::VtkPoint& t : theirs) {
      const double e = (indexOf(g, t.position) - q).norm();
      if (e < best) best = e, match = &t;
    }
    if (!match) continue;
    ++typed;
    const bool same = testing::sameType(p.type, match->detailed);
    sameType += same;
    // Where the two linearisations disagree on the index (saddle against node or focus), the
    // winding number of the field on a loop around the point decides, and it must be ours.
    const bool vtkSaddle = match->detailed == 2, ourSaddle = p.type == CriticalPointType::Saddle;
    if (!same && vtkSaddle != ourSaddle) {
      EXPECT_TRUE(p.index_measured) << p.typeName() << " at cell (" << q.transpose() << ")";
      EXPECT_EQ(p.index, ourSaddle ? -1 : 1) << p.typeName() << " at cell (" << q.transpose() << ")";
    }
    if (!same)
      std::printf("  %s at cell (%.3f, %.3f), VTK typeDetailed %d %.3f cells away\n",
                  p.typeName().c_str(), q.x(), q.y(), match->detailed, best);
  }
  // Every exact zero is a Morse point, or one of the zeros a non-Morse point stands for (the
  // core merges the zeros of one degenerate point into one, IndexLoopPlacement.h).
  int unreported = 0;
  double farthestInCluster = 0.0;
  for (const Vec2& z : exact) {
    double toMorse = 1e300, toOther = 1e300;
    for (const CriticalPoint& p : ours)
      (p.morse ? toMorse : toOther) = std::min(p.morse ? toMorse : toOther, (oursAt(p) - z).norm());
    if (toMorse <= 0.01) continue;
    farthestInCluster = std::max(farthestInCluster, toOther);
    if (toOther > kClusterReach) {
      ++unreported;
      std::printf("  exact zero at cell (%.3f, %.3f): %.3f cells from a Morse point, %.3f from a "
                  "non-Morse one\n", z.x(), z.y(), toMorse, toOther);
    }
  }
  // VTK's types are those of its linearisation (tests/support/VtkTopologyPeer.h): the core's
  // classifier given VTK's gradient must name every VTK point as VTK does.
  int classifierAgrees = 0, vtkTyped = 0;
  for (const testing::VtkPoint& t : theirs) {
    if (t.detailed < 0) continue;  // VTK gives no type where its gradient is singular (walls)
    ++vtkTyped;
    const CriticalPointType mine = classifyMorse(linearize(t.gradient), 0.0);
    const bool agrees = testing::sameType(mine, t.detailed);
    classifierAgrees += agrees;
    if (!agrees)
      std::printf("  VTK point at cell (%.3f, %.3f): VTK typeDetailed %d, its gradient classified %s "
                  "(det %.3g, trace %.3g)\n", indexOf(g, t.position).x(), indexOf(g, t.position).y(),
                  t.detailed, toString(mine).c_str(), t.gradient.determinant(), t.gradient.trace());
  }
  std::printf("%s layer %d (%d x %d nodes): %zu points (%d Morse, worst %.2e cells from an exact "
              "zero), %zu exact zeros (%d unreported, farthest in a cluster %.2f cells); VTK %zu "
              "points (%d typed, classifier agrees on %d), %d of ours matched, %d of them the same type\n",
              d.file, d.layer, g.dims[0], g.dims[1], ours.size(), morse, worst, exact.size(),
              unreported, farthestInCluster, theirs.size(), vtkTyped, classifierAgrees, typed, sameType);
  EXPECT_EQ(classifierAgrees, vtkTyped);
  EXPECT_GT(morse, 0);
  EXPECT_EQ(unreported, 0);
  // The rest differ in kind only where the two linearisations do (VTK: its gradient filter's
  // central differences; ours: the bilinear interpolant's exact Jacobian, issue 15 defect 5).
  EXPECT_GE(sameType, 0.8 * typed);
}

INSTANTIATE_TEST_SUITE_P(VtkData, RealDatasets, ::testing::ValuesIn(testing::realLayers()),
                         [](const auto& info) { return testing::realLayerName(info.param); });

}  // namespace
}  // namespace fluidviz::topology
