// Isosurfaces and isolines of analytic fields against exact geometry.
//
// f(x) = |x| on [-1, 1]^d, level R = 0.7: a sphere (3D) or circle (2D) of radius R. Flying Edges
// places vertices on grid edges by linear interpolation of f (exact for |x| along an edge only
// to O(h^2/R)) and joins them with flat triangles (chords): both make the area, enclosed volume
// and length errors second order in the node spacing h, so they fall ~4x per doubling of the
// resolution. Measured (area): -1.14e-2 (16^3), -2.67e-3 (32^3), -6.44e-4 (64^3), -1.58e-4
// (128^3): ratios 4.2-4.3.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "fieldviz/core/Params.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/isosurface/vtk/Isosurface.h"

using namespace fluidviz;
using namespace fluidviz::isosurface;

namespace {

constexpr double kR = 0.7;

// |x| (plus `noise` times a uniform random number in [-1, 1]) on n^d nodes over [-1, 1]^d.
FieldSet distanceField(int dimension, int n, double noise = 0.0) {
  Grid g;
  const double d = 2.0 / (n - 1);
  g.dims = {n, n, dimension == 3 ? n : 1};
  g.origin = {-1, -1, 0};
  if (dimension == 3) g.origin[2] = -1;
  g.spacing = {d, d, d};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ScalarField f{"r", g, std::vector<double>(g.nodeCount())};
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) f.values[g.index(i, j, k)] = g.position(i, j, k).norm() + noise * u(rng);
  FieldSet s;
  s.grid = g;
  s.add(f);
  return s;
}

IsosurfaceParams sphereParams() { return IsosurfaceParams{.array = "r", .value = kR}; }

double areaError(int n) {
  const SurfaceMeasures m = measureSurface(extractIsosurface(distanceField(3, n), sphereParams()));
  return m.area / (4 * std::numbers::pi * kR * kR) - 1.0;
}

}  // namespace

// Issue acceptance: within 0.5% of the analytic area at 64^3 (measured 0.064%), error ~4x
// smaller per doubling (ratios in [3.5, 4.8]).
TEST(AnalyticIsosurface, SphereAreaWithinHalfPercentAt64AndSecondOrder) {
  const double e32 = areaError(32), e64 = areaError(64), e128 = areaError(128);
  EXPECT_LT(std::abs(e64), 5e-3);
  EXPECT_NEAR(e32 / e64, 4.0, 0.8);
  EXPECT_NEAR(e64 / e128, 4.0, 0.8);
}

// Enclosed volume (vtkMassProperties): measured -1.22e-3 at 64^3, -3.0e-4 at 128^3.
TEST(AnalyticIsosurface, SphereVolumeConvergesAtSecondOrder) {
  auto volumeError = [](int n) {
    const SurfaceMeasures m = measureSurface(extractIsosurface(distanceField(3, n), sphereParams()));
    return m.volume / (4.0 / 3.0 * std::numbers::pi * kR * kR * kR) - 1.0;
  };
  const double e64 = volumeError(64), e128 = volumeError(128);
  EXPECT_LT(std::abs(e64), 2e-3);
  EXPECT_NEAR(e64 / e128, 4.0, 0.8);
}

// Normals from the field's gradient: unit length and radial (|n . x/|x|| > 0.999), all with
// the same orientation.
TEST(AnalyticIsosurface, NormalsAreUnitRadialAndConsistent) {
  vtkSmartPointer<vtkPolyData> s = extractIsosurface(distanceField(3, 48), sphereParams());
  vtkDataArray* normals = s->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  int outward = 0;
  for (vtkIdType i = 0; i < s->GetNumberOfPoints(); ++i) {
    Vec3 x, n;
    s->GetPoint(i, x.data());
    normals->GetTuple(i, n.data());
    EXPECT_NEAR(n.norm(), 1.0, 1e-5);
    const double c = n.dot(x.normalized());
    EXPECT_GT(std::abs(c), 0.999);
    outward += c > 0;
  }
  EXPECT_TRUE(outward == 0 || outward == s->GetNumberOfPoints()) << outward;
}

// A noisy field (noise 0.2 node spacings) gives a bumpy surface whose area is too large
// (measured +1.49%); 30 windowed-sinc passes remove most of the excess (+0.05% left) without
// shrinking the enclosed volume (Taubin's filter does not shrink: -0.07%, raw -0.23%).
TEST(AnalyticIsosurface, SmoothingRemovesNoiseWithoutShrinking) {
  const FieldSet noisy = distanceField(3, 48, 0.2 * 2.0 / 47);
  IsosurfaceParams p = sphereParams();
  const SurfaceMeasures raw = measureSurface(extractIsosurface(noisy, p));
  p.smoothing_iterations = 30;
  vtkSmartPointer<vtkPolyData> smoothed = extractIsosurface(noisy, p);
  const SurfaceMeasures smooth = measureSurface(smoothed);
  const double area = 4 * std::numbers::pi * kR * kR, volume = 4.0 / 3.0 * std::numbers::pi * kR * kR * kR;
  EXPECT_GT(raw.area / area - 1.0, 0.01);  // noise adds area
  EXPECT_LT(std::abs(smooth.area / area - 1.0), 0.5 * (raw.area / area - 1.0));
  EXPECT_LT(std::abs(smooth.volume / volume - 1.0), 5e-3);
  EXPECT_NE(smoothed->GetPointData()->GetNormals(), nullptr);  // recomputed after smoothing
}

// 2D: isolines of |x| = R are a circle; length error second order (measured -5.2e-4, -1.26e-4,
// -3.1e-5 at 32^2, 64^2, 128^2).
TEST(AnalyticIsosurface, CircleLengthConvergesAtSecondOrder) {
  auto lengthError = [](int n) {
    const SurfaceMeasures m = measureSurface(extractIsosurface(distanceField(2, n), sphereParams()));
    return m.length / (2 * std::numbers::pi * kR) - 1.0;
  };
  const double e32 = lengthError(32), e64 = lengthError(64), e128 = lengthError(128);
  EXPECT_LT(std::abs(e64), 5e-3);
  EXPECT_NEAR(e32 / e64, 4.0, 0.8);
  EXPECT_NEAR(e64 / e128, 4.0, 0.8);
}

// Other point arrays of the grid are interpolated onto the surface along the grid edges: the
// node positions as a vector array and x as a scalar come out as the points' own coordinates
// (to the float precision of the points: 1e-6). (VTK 9.1's own InterpolateAttributes is off by
// up to 5.9 on the vector here, which is why fluidviz does it.) Where one end of an edge is NaN
// the other end's value is used: with every node outside |x| > R + 0.5 spacing NaN, x on the
// surface is the inner node's x, within one node spacing of the point's.
TEST(AnalyticIsosurface, GridArraysAreInterpolatedAlongTheEdges) {
  FieldSet f = distanceField(3, 20);
  const Grid& g = f.grid;
  VectorField position{"position", g, {}};
  ScalarField x{"x", g, {}}, holes{"holes", g, {}};
  for (std::size_t n = 0; n < g.nodeCount(); ++n) {
    const Vec3 p = g.position(n % 20, (n / 20) % 20, n / 400);
    position.values.push_back(p);
    x.values.push_back(p.x());
    holes.values.push_back(p.norm() > kR + 0.5 * g.spacing[0] ? std::nan("") : p.x());
  }
  f.add(position);
  f.add(x);
  f.add(holes);
  vtkSmartPointer<vtkPolyData> s = extractIsosurface(f, sphereParams());
  vtkDataArray* pos = s->GetPointData()->GetArray("position");
  vtkDataArray* xs = s->GetPointData()->GetArray("x");
  vtkDataArray* hs = s->GetPointData()->GetArray("holes");
  ASSERT_TRUE(pos && xs && hs);
  ASSERT_EQ(pos->GetNumberOfComponents(), 3);
  double worst = 0.0, worstHole = 0.0;
  for (vtkIdType i = 0; i < s->GetNumberOfPoints(); ++i) {
    Vec3 p;
    s->GetPoint(i, p.data());
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(pos->GetComponent(i, c) - p[c]));
    worst = std::max(worst, std::abs(xs->GetComponent(i, 0) - p.x()));
    ASSERT_FALSE(std::isnan(hs->GetComponent(i, 0)));
    worstHole = std::max(worstHole, std::abs(hs->GetComponent(i, 0) - p.x()));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_LE(worstHole, g.spacing[0] + 1e-6);
}

TEST(AnalyticIsosurface, BadInputIsRefusedWithTheReason) {
  FieldSet f = distanceField(3, 16);
  IsosurfaceParams p = sphereParams();
  p.array = "rho";
  EXPECT_THROW(extractIsosurface(f, p), DataArrayError);
  p = sphereParams();
  p.value = 5.0;
  try {
    extractIsosurface(f, p);
    ADD_FAILURE() << "no ParamError";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "value");
    EXPECT_NE(std::string(e.what()).find("is 5, outside the range ["), std::string::npos) << e.what();
  }
  ScalarField holes = *f.findScalar("r");
  holes.name = "holes";
  holes.values[100] = std::numeric_limits<double>::quiet_NaN();
  f.add(holes);
  p = sphereParams();
  p.array = "holes";
  try {
    extractIsosurface(f, p);
    ADD_FAILURE() << "no DataArrayError";
  } catch (const DataArrayError& e) {
    EXPECT_NE(std::string(e.what()).find("has 1 NaN values"), std::string::npos) << e.what();
  }
  p = sphereParams();
  p.smoothing_passband = 0.0;
  EXPECT_THROW(extractIsosurface(f, p), ParamError);
}
