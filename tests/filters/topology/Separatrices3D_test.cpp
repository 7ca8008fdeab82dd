// 1D separatrices of 3D saddles (filters/topology/Separatrices3D.h):
// 1. Linear saddles of the four kinds (VolumeTestFields.h), zero off-node: the trilinear
//    interpolant reproduces the field, the line through the zero along the lone eigenvector is
//    invariant, so both separatrices stay on it (1e-6 cells), start along an eigenvector of the
//    eigenvalue of the lone sign, go the right way (forward for 1-saddles, backward for
//    2-saddles) and end on the boundary.
// 2. The nine points of the separable sine field: each 1-saddle's unstable axis runs along x or
//    y to the sink in the middle (the planes through the zeros of the 1D interpolants are
//    invariant) on one side and to the boundary on the other; the 2-saddles' stable axis is z
//    and both of their lines end on the z boundary.
#include <gtest/gtest.h>

#include <cmath>

#include "filters/topology/Separatrices3D.h"
#include "filters/topology/VolumeTopology.h"
#include "tests/filters/topology/VolumeTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;
using namespace fluidviz::topology::testing;

namespace {

/// Largest distance (cells) of the line's points from the line through p along d.
double offLine(const Grid& g, const std::vector<Vec3>& points, const Vec3& p, const Vec3& d) {
  const Vec3 h(g.spacing[0], g.spacing[1], g.spacing[2]);
  const Vec3 dq = d.cwiseQuotient(h).normalized();
  double worst = 0.0;
  for (const Vec3& x : points) {
    const Vec3 r = (x - p).cwiseQuotient(h);
    worst = std::max(worst, (r - r.dot(dq) * dq).norm());
  }
  return worst;
}

bool isSaddle(CriticalPointType3D t) {
  return t == CriticalPointType3D::Saddle1 || t == CriticalPointType3D::Saddle2 ||
         t == CriticalPointType3D::SpiralSaddle1 || t == CriticalPointType3D::SpiralSaddle2;
}

}  // namespace

TEST(Separatrices3D, LinearSaddlesAlongTheirLoneEigenvector) {
  const Grid g = linearCaseGrid();
  for (const LinearCase& c : linearCases()) {
    if (!isSaddle(c.type)) continue;
    SCOPED_TRACE(c.name);
    const Mat3 a = c.rotated();
    const VectorField field = sampleLinear(g, a, linearCaseZero());
    const auto points = findCriticalPoints3D(field, {});
    ASSERT_EQ(points.size(), 1u);
    const auto seps = computeSeparatrices3D(field, points, {});
    ASSERT_EQ(seps.size(), 2u);
    const bool unstable =
        c.type == CriticalPointType3D::Saddle1 || c.type == CriticalPointType3D::SpiralSaddle1;
    for (const Separatrix3D& s : seps) {
      EXPECT_EQ(s.outgoing, unstable);
      // An eigenvector of A whose eigenvalue has the lone sign.
      const Vec3 ad = a * s.direction;
      const double lambda = ad.dot(s.direction);
      EXPECT_LT((ad - lambda * s.direction).norm(), 1e-9);
      EXPECT_EQ(lambda > 0, unstable);
      EXPECT_EQ(s.end, SeparatrixEnd::Boundary);
      ASSERT_GE(s.points.size(), 3u);
      EXPECT_LT(offLine(g, s.points, linearCaseZero(), s.direction), 1e-6);
      // It leaves along +-direction: the last point lies on that side.
      EXPECT_GT((s.points.back() - linearCaseZero()).dot(s.direction), 0.0);
    }
    EXPECT_LT(seps[0].direction.dot(seps[1].direction), -0.999999);
  }
}

TEST(Separatrices3D, SaddleConnectionsOfTheSineLattice) {
  const VectorField field = SineLattice::sampled();
  const Grid g = field.grid;
  const auto points = findCriticalPoints3D(field, {});
  ASSERT_EQ(points.size(), 9u);
  int sink = -1;
  for (int k = 0; k < 9; ++k)
    if (points[k].type == CriticalPointType3D::Sink) sink = k;
  ASSERT_GE(sink, 0);
  const auto seps = computeSeparatrices3D(field, points, {});
  ASSERT_EQ(seps.size(), 16u);  // 4 1-saddles and 4 2-saddles, two lines each
  int toSink = 0, toBoundary = 0;
  double worst = 0.0;
  for (const Separatrix3D& s : seps) {
    const CriticalPoint3D& p = points[s.origin];
    SCOPED_TRACE(p.typeName());
    worst = std::max(worst, offLine(g, s.points, p.position, s.direction));
    if (p.type == CriticalPointType3D::Saddle1) {
      EXPECT_TRUE(s.outgoing);
      EXPECT_LT(std::abs(s.direction.z()), 1e-9);  // along x or y
    } else {
      EXPECT_EQ(p.type, CriticalPointType3D::Saddle2);
      EXPECT_FALSE(s.outgoing);
      EXPECT_GT(std::abs(s.direction.z()), 1 - 1e-9);  // along z
    }
    if (s.end == SeparatrixEnd::CriticalPoint) {
      ++toSink;
      EXPECT_EQ(s.end_point, sink);
      EXPECT_EQ(p.type, CriticalPointType3D::Saddle1);
    } else {
      ++toBoundary;
      EXPECT_EQ(s.end, SeparatrixEnd::Boundary);
    }
  }
  EXPECT_EQ(toSink, 4);
  EXPECT_EQ(toBoundary, 12);
  EXPECT_LT(worst, 1e-6);
}
