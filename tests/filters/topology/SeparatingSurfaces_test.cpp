// Separating surfaces of 3D saddles (filters/topology/SeparatingSurfaces.h):
// 1. Linear saddles of the four kinds (VolumeTestFields.h), rotated off the axes, zero off-node:
//    the trilinear interpolant reproduces the field, so the surface is the invariant plane of the
//    two eigenvalues sharing a sign. The reference plane is computed independently of the code's
//    eigenvectors: it is orthogonal to the LEFT eigenvector of the lone eigenvalue (n^T A = l n^T
//    makes n^T x an invariant coordinate that grows or decays on its own). Every vertex lies in it
//    within 1e-3 cells (the tolerance), no triangle edge exceeds max_edge, the mesh is an
//    oriented manifold with boundary, and it covers the plane: every point of the plane inside
//    the box (away from the saddle and the faces) is within max_edge of a vertex.
// 2. The nine points of the separable sine field: each saddle's surface lies in the grid plane
//    through it normal to its lone eigendirection (planes through zeros of the 1D interpolants are
//    invariant).
// 3. The limits end the growth as declared, and a value outside its range names its key.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include <Eigen/Eigenvalues>

#include "fieldviz/core/Params.h"
#include "filters/topology/SeparatingSurfaces.h"
#include "filters/topology/Separatrices3D.h"
#include "filters/topology/VolumeTopology.h"
#include "tests/filters/topology/VolumeTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

Vec3 inCells(const Grid& g, const Vec3& d) {
  return {d.x() / g.spacing[0], d.y() / g.spacing[1], d.z() / g.spacing[2]};
}

/// World unit normal of the invariant plane: the left eigenvector of the eigenvalue whose real
/// part has the sign the other two lack.
Vec3 referenceNormal(const Mat3& a) {
  const Eigen::EigenSolver<Mat3> s(Mat3(a.transpose()));
  int positive = 0;
  for (int k = 0; k < 3; ++k) positive += s.eigenvalues()[k].real() > 0;
  for (int k = 0; k < 3; ++k)
    if ((s.eigenvalues()[k].real() > 0) == (positive == 1))
      return s.eigenvectors().col(k).real().normalized();
  return Vec3::Zero();
}

/// Distance in cells from x to its orthogonal projection onto the plane through p with normal n.
double offPlaneCells(const Grid& g, const Vec3& x, const Vec3& p, const Vec3& n) {
  return inCells(g, (x - p).dot(n) * n).norm();
}

double longestEdgeCells(const Grid& g, const SeparatingSurface& s) {
  double worst = 0.0;
  for (const auto& t : s.triangles)
    for (int e = 0; e < 3; ++e)
      worst = std::max(worst, inCells(g, s.points[t[e]] - s.points[t[(e + 1) % 3]]).norm());
  return worst;
}

/// Each directed edge at most once (consistent orientation) and each undirected edge in at most
/// two triangles (a manifold with boundary).
void expectOrientedManifold(const SeparatingSurface& s) {
  std::map<std::pair<int, int>, int> directed, undirected;
  for (const auto& t : s.triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      ++directed[{a, b}];
      ++undirected[{std::min(a, b), std::max(a, b)}];
    }
  int badDirected = 0, badUndirected = 0;
  for (const auto& [edge, n] : directed) badDirected += n > 1;
  for (const auto& [edge, n] : undirected) badUndirected += n > 2;
  EXPECT_EQ(badDirected, 0);
  EXPECT_EQ(badUndirected, 0);
}

/// Largest distance (cells) from points of the plane inside the box to the nearest vertex.
double largestGapCells(const Grid& g, const SeparatingSurface& s, const Vec3& p, const Vec3& n) {
  const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(-6.0, 6.0);
  double worst = 0.0;
  for (int sample = 0, kept = 0; sample < 20000 && kept < 400; ++sample) {
    const Vec3 x = p + r(rng) * u + r(rng) * w;
    const Vec3 q = g.toIndexSpace(x);
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && q[a] > 1.5 && q[a] < g.dims[a] - 2.5;
    if (!inside || inCells(g, x - p).norm() < 1.5) continue;
    ++kept;
    double nearest = 1e300;
    for (const Vec3& v : s.points) nearest = std::min(nearest, inCells(g, v - x).norm());
    worst = std::max(worst, nearest);
  }
  return worst;
}

}  // namespace

TEST(SeparatingSurfaces, LinearSaddlesFillTheirInvariantPlane) {
  const Grid g = linearCaseGrid();
  const TopologyParams params;
  for (const LinearCase& c : linearCases()) {
    if (!isMorseSaddle(c.type)) continue;
    SCOPED_TRACE(c.name);
    const Mat3 a = c.rotated();
    const VectorField field = sampleLinear(g, a, linearCaseZero());
    const auto points = findCriticalPoints3D(field, params);
    ASSERT_EQ(points.size(), 1u);
    const auto surfaces = computeSeparatingSurfaces(field, points, params);
    ASSERT_EQ(surfaces.size(), 1u);
    const SeparatingSurface& s = surfaces[0];
    const bool twoPositive =
        c.type == CriticalPointType3D::Saddle2 || c.type == CriticalPointType3D::SpiralSaddle2;
    EXPECT_EQ(s.outgoing, twoPositive);
    EXPECT_EQ(s.end, SurfaceEnd::front_ended);
    ASSERT_GT(s.triangles.size(), 200u);
    const Vec3 n = referenceNormal(a);
    double off = 0.0;
    for (const Vec3& x : s.points) off = std::max(off, offPlaneCells(g, x, linearCaseZero(), n));
    const double edge = longestEdgeCells(g, s), gap = largestGapCells(g, s, linearCaseZero(), n);
    std::printf("%s: %zu triangles, off-plane %.2e cells, longest edge %.3f, largest gap %.3f\n",
                c.name.c_str(), s.triangles.size(), off, edge, gap);
    EXPECT_LT(off, 1e-3);
    EXPECT_LE(edge, params.separating_surface.max_edge);
    expectOrientedManifold(s);
    double signedArea = 0.0, area = 0.0;  // no fold: every triangle turns the same way
    for (const auto& t : s.triangles) {
      const double z = 0.5 * (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).dot(n);
      signedArea += z;
      area += std::abs(z);
    }
    EXPECT_LT(area, 1.001 * std::abs(signedArea));
    EXPECT_LT(gap, params.separating_surface.max_edge);
  }
}

TEST(SeparatingSurfaces, SineLatticeSurfacesLieInGridPlanes) {
  const VectorField field = SineLattice::sampled();
  const Grid g = field.grid;
  const auto points = findCriticalPoints3D(field, {});
  ASSERT_EQ(points.size(), 9u);
  TopologyParams params;
  params.separating_surface.max_edge = 2.0;  // coarse: the planes are exact at any edge length
  const auto surfaces = computeSeparatingSurfaces(field, points, params);
  ASSERT_EQ(surfaces.size(), 8u);  // four 1-saddles and four 2-saddles
  for (const SeparatingSurface& s : surfaces) {
    const CriticalPoint3D& p = points[s.origin];
    SCOPED_TRACE(p.typeName());
    // J = diag: the lone eigenvalue's axis is the one whose sign the other two lack.
    int axis = -1;
    for (int k = 0; k < 3; ++k) {
      const bool pos = p.jacobian(k, k) > 0;
      int same = 0;
      for (int m = 0; m < 3; ++m) same += (p.jacobian(m, m) > 0) == pos;
      if (same == 1) axis = k;
    }
    ASSERT_GE(axis, 0);
    EXPECT_EQ(s.outgoing, p.type == CriticalPointType3D::Saddle2);
    ASSERT_GT(s.triangles.size(), 50u);
    double off = 0.0;
    for (const Vec3& x : s.points)
      off = std::max(off, std::abs(x[axis] - p.position[axis]) / g.spacing[axis]);
    EXPECT_LT(off, 1e-3);
    expectOrientedManifold(s);
  }
}

TEST(SeparatingSurfaces, LimitsEndTheGrowth) {
  const Grid g = linearCaseGrid();
  const VectorField field = sampleLinear(g, linearCases()[3].rotated(), linearCaseZero());
  TopologyParams params;
  const auto points = findCriticalPoints3D(field, params);
  ASSERT_EQ(points.size(), 1u);
  params.separating_surface.max_triangles = 100;
  auto s = computeSeparatingSurfaces(field, points, params);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].end, SurfaceEnd::max_triangles);
  EXPECT_GE(s[0].triangles.size(), 100u);
  EXPECT_LT(s[0].triangles.size(), 200u);  // one step's strip at most past the limit

  params = {};
  params.separating_surface.max_length = 2.0;
  s = computeSeparatingSurfaces(field, points, params);
  EXPECT_EQ(s[0].end, SurfaceEnd::max_length);
  double reach = 0.0;
  for (const Vec3& x : s[0].points) reach = std::max(reach, inCells(g, x - linearCaseZero()).norm());
  EXPECT_LE(reach, params.separatrix_offset + 2.0 + 1e-9);  // chords are not longer than arcs
  EXPECT_GT(reach, params.separatrix_offset + 1.0);

  params = {};
  params.separating_surface.max_edge = 0.0;
  try {
    computeSeparatingSurfaces(field, points, params);
    FAIL() << "max_edge 0 accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "separating_surface.max_edge");
  }
}

// A weakly unstable spiral (eigenvalues 0.05 +- i, -1) grows by only exp(2 pi 0.05) = 1.37 per
// turn: its front circles the saddle for many steps within the stop radius and must not stop
// there (a spiral vortex core of the lid-driven cubic cavity's mid-plane is such a point).
TEST(SeparatingSurfaces, WeakSpiralWindsOutOfItsSaddle) {
  const Grid g = linearCaseGrid();
  const VectorField field =
      sampleLinear(g, mat3(0.05, -1, 0, 1, 0.05, 0, 0, 0, -1), linearCaseZero());
  const auto points = findCriticalPoints3D(field, {});
  ASSERT_EQ(points.size(), 1u);
  ASSERT_EQ(points[0].type, CriticalPointType3D::SpiralSaddle2);
  TopologyParams params;
  params.separating_surface.max_length = 400;
  const auto s = computeSeparatingSurfaces(field, points, params);
  ASSERT_EQ(s.size(), 1u);
  double reach = 0.0, off = 0.0;
  for (const Vec3& x : s[0].points) {
    reach = std::max(reach, inCells(g, x - linearCaseZero()).norm());
    off = std::max(off, std::abs(x.z() - linearCaseZero().z()) / g.spacing[2]);
  }
  EXPECT_GT(reach, 6.0);  // the nearest side face is 6.3 cells away
  EXPECT_LT(off, 1e-3);
  // Folds: where the polygonal front turns faster than it grows (its edges' sagitta e^2/8r
  // exceeds the outward motion of a step), a strip lies partly over the last one. Measured and
  // printed, not asserted: a known limit until the front is refined by its curvature (the
  // strongly growing spirals of LinearSaddlesFillTheirInvariantPlane do not fold).
  double signedArea = 0.0, area = 0.0;
  for (const auto& t : s[0].triangles) {
    const Vec3 a = inCells(g, s[0].points[t[0]]), b = inCells(g, s[0].points[t[1]]),
               c = inCells(g, s[0].points[t[2]]);
    const double z = 0.5 * (b - a).cross(c - a).z();
    signedArea += z;
    area += std::abs(z);
  }
  std::printf("weak spiral: %zu triangles, area %.2f cells^2, signed %.2f (fold ratio %.2f)\n",
              s[0].triangles.size(), area, signedArea, area / std::abs(signedArea));
}
