#pragma once
// Analytic 3D fields with known critical points, for the volume topology tests and the agreement
// with vtkVectorFieldTopology (tests/filters/topology/vtk/).
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "fieldviz/core/Field.h"
#include "filters/topology/CriticalPoint3D.h"
#include "tests/support/AnalyticFields.h"

namespace fluidviz::topology::testing {

inline Mat3 mat3(double a, double b, double c, double d, double e, double f, double g, double h,
                 double i) {
  Mat3 m;
  m << a, b, c, d, e, f, g, h, i;
  return m;
}

/// A linear field v = R A R^T (x - x0) of a known Morse type: R a fixed rotation (axis
/// (1, 2, 3), 0.7 rad) so that no eigenvector is aligned with the grid.
struct LinearCase {
  std::string name;
  Mat3 a;                          ///< before rotation
  CriticalPointType3D type;
  int index;                       ///< sign(det A)
  Mat3 rotated() const {
    const Mat3 r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    return r * a * r.transpose();
  }
};

/// One linear field of every 3D Morse type (CriticalPointClassifier3D.h).
inline std::vector<LinearCase> linearCases() {
  using T = CriticalPointType3D;
  return {
      {"source", mat3(1, 0.2, 0, 0, 0.6, 0.1, 0, 0, 0.3), T::Source, 1},
      {"sink", mat3(-1, 0.2, 0, 0, -0.6, 0.1, 0, 0, -0.3), T::Sink, -1},
      {"saddle_1", mat3(0.8, 0.1, 0, 0, -0.5, 0.2, 0, 0, -1), T::Saddle1, 1},
      {"saddle_2", mat3(0.8, 0.1, 0, 0, 0.5, 0.2, 0, 0, -1), T::Saddle2, -1},
      {"spiral_source", mat3(0.3, -1, 0, 1, 0.3, 0, 0, 0, 0.5), T::SpiralSource, 1},
      {"spiral_sink", mat3(-0.3, -1, 0, 1, -0.3, 0, 0, 0, -0.5), T::SpiralSink, -1},
      {"spiral_saddle_1", mat3(-0.3, -1, 0, 1, -0.3, 0, 0, 0, 0.5), T::SpiralSaddle1, 1},
      {"spiral_saddle_2", mat3(0.3, -1, 0, 1, 0.3, 0, 0, 0, -0.5), T::SpiralSaddle2, -1},
      {"centre_outflow", mat3(0, -1, 0, 1, 0, 0, 0, 0, 0.5), T::Centre, 1},
      {"centre_inflow", mat3(0, -1, 0, 1, 0, 0, 0, 0, -0.5), T::Centre, -1},
  };
}

/// 17 x 15 x 13 nodes, spacings 0.25, 0.3, 0.35 (anisotropic: index space is exercised).
inline Grid linearCaseGrid() {
  Grid g;
  g.dims = {17, 15, 13};
  g.origin = {-2.0, -2.1, -2.1};
  g.spacing = {0.25, 0.3, 0.35};
  return g;
}

/// Off every node, edge and face: (9.48, 6.3, 6.371) cells from the origin.
inline Vec3 linearCaseZero() { return {0.37, -0.21, 0.13}; }

inline VectorField sampleLinear(const Grid& g, const Mat3& a, const Vec3& x0) {
  return fluidviz::testing::sampleField(g, [&](const Vec3& p) { return Vec3(a * (p - x0)); }, "v");
}

/// v = (sin(x - 0.17), sin(y - 0.23), -sin(z - 0.31)) on [-1, 7.6] x [-1, 7.6] x [-1, 1.2]:
/// zeros at x, y in {0.17, 0.17 + pi, 0.17 + 2 pi} (resp. 0.23 + ...) and z = 0.31, nine points;
/// J = diag(cos, cos, -cos): 2-saddles, 1-saddles and a sink, index s_x s_y (-1) (s = sign cos),
/// sum of indices (1 - 1 + 1)^2 (-1) = -1. Spacing 0.2 (44 x 44 x 12 nodes).
struct SineLattice {
  static constexpr double x0 = 0.17, y0 = 0.23, z0 = 0.31;
  static Grid grid() {
    Grid g;
    g.dims = {44, 44, 12};
    g.origin = {-1.0, -1.0, -1.0};
    g.spacing = {0.2, 0.2, 0.2};
    return g;
  }
  static Vec3 field(const Vec3& p) {
    return {std::sin(p.x() - x0), std::sin(p.y() - y0), -std::sin(p.z() - z0)};
  }
  static VectorField sampled() { return fluidviz::testing::sampleField(grid(), field, "v"); }
};

}  // namespace fluidviz::topology::testing
