// Scene parameters of the surface solver (SurfaceParams.h): values out of range and impossible
// combinations are refused naming the key; valid ones build the mesh they describe
// (10 * 4^L + 2 icosphere vertices, n m torus vertices).
#include <gtest/gtest.h>

#include <cmath>

#include "solvers/surface/SurfaceParams.h"

namespace fluidviz::surface {
namespace {

std::string refusedKey(const SurfaceParams& p) {
  try {
    validateSurfaceParams(p);
  } catch (const ParamError& e) {
    return e.key();
  }
  return "(accepted)";
}

TEST(SurfaceParams, ValuesOutOfRangeAreRefusedNamingTheKey) {
  SurfaceParams p;
  EXPECT_EQ(refusedKey(p), "(accepted)");
  p.radius = 0.0;
  EXPECT_EQ(refusedKey(p), "radius");
  p = {};
  p.subdivision_level = 8;
  EXPECT_EQ(refusedKey(p), "subdivision_level");
  p = {};
  p.viscosity = -1.0;
  EXPECT_EQ(refusedKey(p), "viscosity");
  p = {};
  p.time_step = 0.0;
  EXPECT_EQ(refusedKey(p), "time_step");
  p = {};
  p.harmonic_degree = 2;
  p.harmonic_order = 3;
  EXPECT_EQ(refusedKey(p), "harmonic_order");
  p = {};
  p.shape = SurfaceShape::torus;
  p.torus_minor_radius = 1.5;
  EXPECT_EQ(refusedKey(p), "torus_major_radius");
  p.shape = SurfaceShape::icosphere;  // the torus radii do not matter then
  EXPECT_EQ(refusedKey(p), "(accepted)");
}

TEST(SurfaceParams, ValidParametersBuildTheirMesh) {
  SurfaceParams p;
  p.subdivision_level = 3;
  EXPECT_EQ(makeSurfaceMesh(p).vertexCount(), 642);
  p.shape = SurfaceShape::torus;
  p.torus_segments = 30;
  p.torus_tube_segments = 12;
  EXPECT_EQ(makeSurfaceMesh(p).vertexCount(), 360);
  p.viscosity = 0.25;
  p.viscous_operator = ViscousOperator::laplacian;
  const TriangleMesh torus = makeSurfaceMesh(p);
  const VorticityStreamSettings s = vorticityStreamSettings(p, torus);
  EXPECT_EQ(s.gaussianCurvature.size(), torus.vertexCount());
  EXPECT_EQ(s.viscosity, 0.25);
  EXPECT_EQ(s.viscousOperator, ViscousOperator::laplacian);
  EXPECT_EQ(choiceName(SurfaceShape::torus), "torus");
  EXPECT_EQ(choiceName(ViscousOperator::deformation), "deformation");
}

// The smooth torus's curvature cos v / (r (R + r cos v)) against the mesh's angle defect per
// mixed Voronoi area, and Gauss-Bonnet (int K = 2 pi chi = 0) in the lumped quadrature.
TEST(SurfaceParams, BuiltInTorusCurvatureMatchesTheAngleDefects) {
  SurfaceParams p;
  p.shape = SurfaceShape::torus;
  p.torus_major_radius = 1.0;
  p.torus_minor_radius = 0.4;
  p.torus_segments = 96;
  p.torus_tube_segments = 48;
  const TriangleMesh mesh = makeSurfaceMesh(p);
  const Eigen::VectorXd k = builtInCurvature(p, mesh);
  const Eigen::VectorXd mass = lumpedMass(mesh, MassLumping::mixed_voronoi);
  const Eigen::VectorXd discrete = angleDefect(mesh).cwiseQuotient(mass);
  const double largest = k.cwiseAbs().maxCoeff();  // 1 / (r (R - r)) on the inner equator
  EXPECT_NEAR(largest, 1.0 / (0.4 * 0.6), 1e-12);
  EXPECT_LT((k - discrete).cwiseAbs().maxCoeff(), 0.02 * largest);
  EXPECT_LT(std::abs(mass.dot(k)), 0.01 * mass.dot(k.cwiseAbs()));
}

}  // namespace
}  // namespace fluidviz::surface
