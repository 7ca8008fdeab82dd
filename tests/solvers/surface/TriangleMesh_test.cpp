// The built-in surfaces and the manifold check. References: Euler's polyhedron formula
// chi = V - E + F (2 for a sphere, 0 for a torus) and the discrete Gauss-Bonnet theorem, sum of
// angle defects = 2 pi chi (Meyer et al. 2003, section 5), which holds to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solvers/surface/mesh/ManifoldCheck.h"
#include "solvers/surface/mesh/TriangleMesh.h"
#include "solvers/surface/operators/SurfaceOperators.h"

namespace fluidviz::surface {
namespace {

/// Signed volume enclosed by a closed mesh (divergence theorem): positive iff the faces are
/// counter-clockwise seen from outside.
double enclosedVolume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& f : m.faces)
    v += m.vertices[f[0]].dot(m.vertices[f[1]].cross(m.vertices[f[2]])) / 6.0;
  return v;
}

TEST(SurfaceMesh, IcosphereIsAClosedSphereOfTheRightSize) {
  for (int level = 0; level <= 4; ++level) {
    const TriangleMesh m = makeIcosphere(2.0, level);
    const ManifoldReport r = checkManifold(m);
    EXPECT_EQ(m.vertexCount(), 10 * (1 << (2 * level)) + 2);
    EXPECT_EQ(m.faceCount(), 20 * (1 << (2 * level)));
    EXPECT_TRUE(r.valid()) << r.describe();
    EXPECT_TRUE(r.closed()) << r.describe();
    EXPECT_EQ(r.eulerCharacteristic, 2) << r.describe();
    for (const auto& v : m.vertices) EXPECT_NEAR(v.norm(), 2.0, 1e-14);
    // Outward orientation; the inscribed polyhedron's volume approaches 4/3 pi R^3 from below.
    const double sphere = 4.0 / 3.0 * std::numbers::pi * 8.0;
    EXPECT_GT(enclosedVolume(m), 0.6 * sphere);
    EXPECT_LT(enclosedVolume(m), sphere);
  }
}

TEST(SurfaceMesh, TorusIsAClosedSurfaceOfGenusOne) {
  const TriangleMesh m = makeTorus(1.0, 0.4, 24, 12);
  const ManifoldReport r = checkManifold(m);
  EXPECT_EQ(m.vertexCount(), 24 * 12);
  EXPECT_TRUE(r.valid() && r.closed()) << r.describe();
  EXPECT_EQ(r.eulerCharacteristic, 0) << r.describe();
  // Volume of the torus 2 pi^2 R r^2, approached from below by the inscribed polyhedron.
  const double torus = 2.0 * std::numbers::pi * std::numbers::pi * 1.0 * 0.16;
  EXPECT_GT(enclosedVolume(m), 0.9 * torus);
  EXPECT_LT(enclosedVolume(m), torus);
}

TEST(SurfaceMesh, GaussBonnetHoldsToRoundOff) {
  const double twoPi = 2.0 * std::numbers::pi;
  EXPECT_NEAR(angleDefect(makeIcosphere(1.0, 3)).sum(), 2.0 * twoPi, 1e-10);
  EXPECT_NEAR(angleDefect(makeIcosphere(3.0, 1)).sum(), 2.0 * twoPi, 1e-10);
  EXPECT_NEAR(angleDefect(makeTorus(2.0, 0.5, 40, 16)).sum(), 0.0, 1e-10);
}

TEST(SurfaceMesh, ManifoldCheckNamesEachDefect) {
  TriangleMesh m = makeIcosphere(1.0, 1);
  std::swap(m.faces[0][1], m.faces[0][2]);  // one face flipped: its three edges disagree
  ManifoldReport r = checkManifold(m);
  EXPECT_EQ(r.inconsistentEdges, 3);
  EXPECT_FALSE(r.valid());
  EXPECT_NE(r.describe().find("disagree in orientation"), std::string::npos) << r.describe();

  m = makeIcosphere(1.0, 1);
  m.faces.pop_back();  // a hole: three boundary edges, chi = 1 (a disc)
  r = checkManifold(m);
  EXPECT_TRUE(r.valid()) << r.describe();
  EXPECT_EQ(r.boundaryEdges, 3);
  EXPECT_EQ(r.eulerCharacteristic, 1);
  EXPECT_THROW(requireClosedManifold(m), std::invalid_argument);

  m = makeIcosphere(1.0, 1);
  m.faces.push_back(m.faces[0]);  // a duplicated face: its edges have three faces
  r = checkManifold(m);
  EXPECT_EQ(r.nonManifoldEdges, 3);

  m = makeIcosphere(1.0, 1);
  m.faces.push_back({0, 0, 1});
  m.faces.push_back({0, 1, 99});
  r = checkManifold(m);
  EXPECT_EQ(r.degenerateFaces, 1);
  EXPECT_EQ(r.badIndices, 1);
  EXPECT_THROW(requireClosedManifold(m), std::invalid_argument);
  EXPECT_NO_THROW(requireClosedManifold(makeTorus(1.0, 0.3, 8, 6)));
}

}  // namespace
}  // namespace fluidviz::surface
