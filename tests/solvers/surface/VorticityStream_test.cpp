// Incompressible flow on closed surfaces in vorticity - stream-function form. References:
// - u = grad psi x n lies in each face's plane (tangent by construction);
// - a solid-body rotation Omega about z (omega = 2 Omega z / R, psi = Omega R z) is a steady
//   Euler flow, and the scheme conserves kinetic energy and enstrophy exactly (Galerkin Jacobian,
//   Jespersen 1974; implicit midpoint rule, Cooper 1987);
// - viscous decay of a vorticity mode Y_l on the sphere of radius R: nu (l (l + 1) - 2) / R^2
//   with the deformation Laplacian nu (Delta_H u + 2 K u) of the Navier-Stokes equations on a
//   Riemannian manifold (Ebin & Marsden 1970; Chan, Czubak & Disconzi 2017), nu l (l + 1) / R^2
//   with the Laplacian of vorticity alone (spectral models' Delta omega);
// - the Rossby-Haurwitz wave (Haurwitz 1940, J. Mar. Res. 3:254): a vorticity Y_l^m on a sphere
//   turning at Omega drifts at -2 Omega / (l (l + 1)) relative to the frame, exactly also for a
//   finite amplitude; in an inertial frame, on a solid-body rotation Omega, it turns at
//   Omega (1 - 2 / (l (l + 1))) (5 Omega / 6 for l = 3).
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "solvers/surface/VorticityStream.h"
#include "solvers/surface/validation/SphericalHarmonics.h"

namespace fluidviz::surface {
namespace {

/// M-projection of the flow's vorticity onto y, relative to y.
double amplitudeOf(const VorticityStream& flow, const Eigen::VectorXd& y) {
  const Eigen::VectorXd my = flow.mass().cwiseProduct(y);
  return flow.vorticity().dot(my) / y.dot(my);
}

Eigen::VectorXd harmonic(const TriangleMesh& mesh, int l, int m) {
  return sampleSphericalHarmonic(mesh, l, m);
}

void expectTangent(const VorticityStream& flow) {
  const FaceGeometry g = computeFaceGeometry(flow.mesh());
  const auto uf = flow.faceVelocity();
  double largest = 0.0;
  for (std::size_t t = 0; t < uf.size(); ++t) {
    largest = std::max(largest, uf[t].norm());
    ASSERT_LE(std::abs(uf[t].dot(g.normal[t])), 1e-12 * uf[t].norm()) << "face " << t;
  }
  EXPECT_GT(largest, 0.1);  // a flow, not zero
  const auto uv = flow.vertexVelocity();
  const auto n = vertexNormals(flow.mesh());
  for (std::size_t i = 0; i < uv.size(); ++i)
    ASSERT_LE(std::abs(uv[i].dot(n[i])), 1e-12 * uv[i].norm()) << "vertex " << i;
}

TEST(SurfaceVorticityStream, VelocityIsTangentOnTheSphereAndTheTorus) {
  const TriangleMesh sphere = makeIcosphere(1.5, 3);
  VorticityStream onSphere(sphere, {});
  onSphere.setVorticity(harmonic(sphere, 2, 1) + harmonic(sphere, 3, -2) +
                        0.5 * harmonic(sphere, 4, 3));
  expectTangent(onSphere);

  const TriangleMesh torus = makeTorus(1.0, 0.4, 48, 16);
  VorticityStream onTorus(torus, {});
  Eigen::VectorXd omega(torus.vertexCount());
  for (int i = 0; i < torus.vertexCount(); ++i) {
    const Eigen::Vector3d& x = torus.vertices[i];
    omega[i] = x.z() * x.x() + std::sin(3.0 * std::atan2(x.y(), x.x()));
  }
  onTorus.setVorticity(omega);
  expectTangent(onTorus);
  // omega's mean was removed: a tangent field's vorticity integrates to zero.
  EXPECT_NEAR(onTorus.circulation(), 0.0, 1e-12);
}

// Level 4 (2562 vertices), Omega = 1, R = 1, dt = 0.02, t = 2: measured energy and enstrophy
// drifts 2e-15 and 0, vorticity change 9.1e-5 (relative), vertex velocities within 2.5e-3 of
// Omega z x x.
TEST(SurfaceVorticityStream, SolidBodyRotationIsSteadyAndConservesEnergy) {
  const TriangleMesh mesh = makeIcosphere(1.0, 4);
  VorticityStreamSettings settings;
  settings.timeStep = 0.02;
  VorticityStream flow(mesh, settings);
  flow.setVorticity(2.0 * harmonic(mesh, 1, 0));
  const double energy = flow.energy(), enstrophy = flow.enstrophy();
  const Eigen::VectorXd start = flow.vorticity();
  for (int s = 0; s < 100; ++s) flow.step();
  EXPECT_NEAR(flow.energy(), energy, 1e-12 * energy);
  EXPECT_NEAR(flow.enstrophy(), enstrophy, 1e-12 * enstrophy);
  EXPECT_LT((flow.vorticity() - start).norm() / start.norm(), 5e-4);
  EXPECT_NEAR(flow.circulation(), 0.0, 1e-12);
  // Kinetic energy of the rotation: 1/2 int |Omega z x x|^2 = 4 pi R^4 Omega^2 / 3.
  EXPECT_NEAR(energy, 4.0 * std::numbers::pi / 3.0, 2e-3 * energy);
  const auto u = flow.vertexVelocity();
  for (int i = 0; i < mesh.vertexCount(); ++i)
    ASSERT_LT((u[i] - Eigen::Vector3d::UnitZ().cross(mesh.vertices[i])).norm(), 5e-3) << i;
}

/// Measured decay rate of the vorticity mode Y_l^m on the icosphere of radius 1.5 (nu = 0.5,
/// dt = 0.004, t = 0.2), in units of nu / R^2.
double vorticityDecayRate(int level, int l, ViscousOperator op, int steps = 50,
                          bool smoothCurvature = false) {
  const double radius = 1.5, nu = 0.5;
  const TriangleMesh mesh = makeIcosphere(radius, level);
  VorticityStreamSettings settings;
  settings.viscosity = nu;
  settings.timeStep = 0.004;
  settings.viscousOperator = op;
  if (smoothCurvature)
    settings.gaussianCurvature = Eigen::VectorXd::Constant(mesh.vertexCount(), 1.0 / (radius * radius));
  VorticityStream flow(mesh, settings);
  const Eigen::VectorXd y = harmonic(mesh, l, (l + 1) / 2);
  flow.setVorticity(y);
  for (int s = 0; s < steps; ++s) flow.step();
  return -std::log(amplitudeOf(flow, y)) / (steps * settings.timeStep) * radius * radius / nu;
}

// Measured at level 4: deformation 3.989 (l = 2), 9.946 (l = 3); laplacian 2.000, 5.991,
// 11.948 (l = 1, 2, 3): 0.55% at most (issue 24 asks 2% for the deformation rates).
TEST(SurfaceVorticityStream, ViscousModesDecayAtTheRateOfTheirOperator) {
  for (int l = 2; l <= 3; ++l) {
    const double expected = l * (l + 1.0) - 2.0;
    EXPECT_NEAR(vorticityDecayRate(4, l, ViscousOperator::deformation), expected, 0.01 * expected)
        << "deformation, l = " << l;
  }
  for (int l = 1; l <= 3; ++l) {
    const double expected = l * (l + 1.0);
    EXPECT_NEAR(vorticityDecayRate(4, l, ViscousOperator::laplacian), expected, 0.01 * expected)
        << "laplacian, l = " << l;
  }
}

// Rigid rotation under the deformation operator should not decay. Discretely its rate is
// nu (z.S z / z.M z - 2 z.D z / z.M z) with D the angle defects: measured -9.6e-3 (level 3) and
// -2.4e-3 nu / R^2 (level 4; a slow growth), falling 4x per subdivision. Issue 24 asks for less
// than 1e-3 of energy over t = 10 R^2 / nu, i.e. |rate| < 5e-5: not met before level 7.
TEST(SurfaceVorticityStream, RigidRotationBarelyDecaysUnderTheDeformationOperator) {
  const double r3 = vorticityDecayRate(3, 1, ViscousOperator::deformation, 10);
  const double r4 = vorticityDecayRate(4, 1, ViscousOperator::deformation, 10);
  EXPECT_LT(std::abs(r4), 5e-3);
  EXPECT_NEAR(r3 / r4, 4.0, 0.3);
}

// With the smooth sphere's K = 1 / R^2 (SurfaceParams' builtInCurvature) the l = 1 rate is
// z.S z / z.M z - 2 / R^2, zero by the icosahedral symmetry (z.S z = 2 A_mesh / 3 and
// z.M z = R^2 A_mesh / 3): rigid rotation keeps its energy to 2.2e-6 (measured) over
// t = 10 R^2 / nu at level 4 (issue 24: lose less than 1e-3), and the l = 2, 3 rates stay within
// 0.6% (measured 3.991 and 9.948 nu / R^2, against 4 and 10).
TEST(SurfaceVorticityStream, RigidRotationIsSteadyWithTheSmoothSurfaceCurvature) {
  const double radius = 1.5, nu = 0.5;
  const TriangleMesh mesh = makeIcosphere(radius, 4);
  VorticityStreamSettings settings;
  settings.viscosity = nu;
  settings.timeStep = 0.1 * radius * radius / nu;
  settings.gaussianCurvature = Eigen::VectorXd::Constant(mesh.vertexCount(), 1.0 / (radius * radius));
  VorticityStream flow(mesh, settings);
  flow.setVorticity(2.0 * harmonic(mesh, 1, 0) / radius);
  const double energy = flow.energy();
  for (int s = 0; s < 100; ++s) flow.step();  // t = 10 R^2 / nu
  EXPECT_NEAR(flow.energy(), energy, 1e-5 * energy);
  for (int l = 2; l <= 3; ++l) {
    const double expected = l * (l + 1.0) - 2.0;
    EXPECT_NEAR(vorticityDecayRate(4, l, ViscousOperator::deformation, 50, true), expected,
                0.01 * expected) << "l = " << l;
  }
}

// On an oblate spheroid x^2 + y^2 + z^2 / c^2 = 1 (c = 0.6) the curvature varies,
// K = 1 / (c^2 (x^2 + y^2 + z^2 / c^4)^2) (from 0.13 at the poles to 2.8 on the equator), and
// rotation about z is still a Killing field: the deformation operator must leave it steady. That
// needs its - 2 grad K . grad psi term: measured with the term removed, the rotation loses 99.96%
// of its energy over t = 2 / nu; with it, 6.0% (level 3) and 1.5% (level 4), second order.
// Initial vorticity 2 n_z (n . curl of z x x), smooth K, nu = 0.5, dt = 0.1, t = 4.
double spheroidRotationEnergyChange(int level) {
  const double c = 0.6, nu = 0.5;
  TriangleMesh mesh = makeIcosphere(1.0, level);
  for (Eigen::Vector3d& x : mesh.vertices) x.z() *= c;
  Eigen::VectorXd k(mesh.vertexCount()), omega(mesh.vertexCount());
  for (int i = 0; i < mesh.vertexCount(); ++i) {
    const Eigen::Vector3d& x = mesh.vertices[i];
    const Eigen::Vector3d normal = Eigen::Vector3d(x.x(), x.y(), x.z() / (c * c)).normalized();
    const double q = x.x() * x.x() + x.y() * x.y() + x.z() * x.z() / (c * c * c * c);
    k[i] = 1.0 / (c * c * q * q);
    omega[i] = 2.0 * normal.z();
  }
  VorticityStreamSettings settings;
  settings.viscosity = nu;
  settings.timeStep = 0.1;
  settings.gaussianCurvature = k;
  VorticityStream flow(mesh, settings);
  flow.setVorticity(omega);
  const double energy = flow.energy();
  for (int s = 0; s < 40; ++s) flow.step();
  return flow.energy() / energy - 1.0;
}

TEST(SurfaceVorticityStream, RotationOfASpheroidIsSteadyUnderTheDeformationOperator) {
  const double e3 = spheroidRotationEnergyChange(3), e4 = spheroidRotationEnergyChange(4);
  EXPECT_LT(std::abs(e4), 0.02);
  EXPECT_GT(e3 / e4, 3.5);
}

struct WaveRun {
  double speed;           ///< angular speed of the Y_3^2 pattern about z
  double energyDrift;     ///< relative
  double potentialEnstrophyDrift;  ///< of q = omega + f, relative
};

/// A Y_3^2 wave of peak vorticity 0.2 on a super-rotation superRotation about z, in a frame
/// turning at frameRotation, on the unit icosphere (level 4), dt = 0.02, t = 1.
WaveRun rossbyHaurwitz(double frameRotation, double superRotation) {
  const TriangleMesh mesh = makeIcosphere(1.0, 4);
  VorticityStreamSettings settings;
  settings.timeStep = 0.02;
  settings.rotationRate = frameRotation;
  VorticityStream flow(mesh, settings);
  const Eigen::VectorXd cosine = harmonic(mesh, 3, 2), sine = harmonic(mesh, 3, -2);
  flow.setVorticity(0.2 * cosine / cosine.cwiseAbs().maxCoeff() +
                    2.0 * superRotation * harmonic(mesh, 1, 0));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.vertexCount());
  const auto n = vertexNormals(mesh);
  for (int i = 0; i < mesh.vertexCount(); ++i) f[i] = 2.0 * frameRotation * n[i].z();
  auto potentialEnstrophy = [&] {
    const Eigen::VectorXd q = flow.vorticity() + f;
    return 0.5 * q.dot(flow.mass().cwiseProduct(q));
  };
  const double e0 = flow.energy(), z0 = potentialEnstrophy();
  const int steps = 50;
  for (int s = 0; s < steps; ++s) flow.step();
  // The pattern cos(2 (lambda - lambda0)) projects as (cos 2 lambda0, sin 2 lambda0).
  const double lambda0 = std::atan2(amplitudeOf(flow, sine), amplitudeOf(flow, cosine)) / 2.0;
  return {lambda0 / flow.time(), flow.energy() / e0 - 1.0, potentialEnstrophy() / z0 - 1.0};
}

/// Haurwitz's angular speed of the wave cos^R(phi) sin(phi) cos(R lambda) (degree l = R + 1) on
/// a super-rotation w in a frame turning at Omega: (R (3 + R) w - 2 Omega) / ((1 + R)(2 + R))
/// (Haurwitz 1940; Williamson et al. 1992, J. Comput. Phys. 102:211, test case 6).
double haurwitzSpeed(int r, double frameRotation, double superRotation) {
  return (r * (3.0 + r) * superRotation - 2.0 * frameRotation) / ((1.0 + r) * (2.0 + r));
}

// Measured: -0.16624 (0.26% off -1/6) in a frame turning at Omega = 1 (no super-rotation),
// 0.82595 (0.89% off 5/6) on a super-rotation 1 in an inertial frame, 0.24717 (1.13% off 1/4) on
// a super-rotation 0.5 in a frame turning at 1; energy and potential-enstrophy drifts below
// 1e-14. Bound: issue 24's 2%.
TEST(SurfaceVorticityStream, RossbyHaurwitzWaveTurnsAtItsAnalyticSpeed) {
  for (const auto& [frame, super] : {std::pair{1.0, 0.0}, std::pair{0.0, 1.0}, std::pair{1.0, 0.5}}) {
    const WaveRun run = rossbyHaurwitz(frame, super);
    const double expected = haurwitzSpeed(2, frame, super);
    EXPECT_NEAR(run.speed, expected, 0.02 * std::abs(expected)) << frame << " " << super;
    EXPECT_LT(std::abs(run.energyDrift), 1e-10);
    EXPECT_LT(std::abs(run.potentialEnstrophyDrift), 1e-10);
  }
}

/// b_i = -int psi_h J(phi_i, q_h) dA = -sum over the faces T of i of A_T mean(psi on T)
/// n_T . (grad phi_i x grad q_T): the same Galerkin Jacobian by the other side of the identity
/// int a J(b, c) = -int b J(a, c), which holds when int J(f, g) = 0 for continuous piecewise
/// smooth f, g (the tangential derivatives along a shared edge agree on both sides).
Eigen::VectorXd jacobianByAntisymmetry(const TriangleMesh& mesh, const Eigen::VectorXd& psi,
                                       const Eigen::VectorXd& q) {
  const FaceGeometry g = computeFaceGeometry(mesh);
  const auto gradQ = faceGradient(g, mesh, q);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(mesh.vertexCount());
  for (int t = 0; t < mesh.faceCount(); ++t) {
    const auto& f = mesh.faces[t];
    const double meanPsi = (psi[f[0]] + psi[f[1]] + psi[f[2]]) / 3.0;
    for (int k = 0; k < 3; ++k)
      b[f[k]] -= g.area[t] * meanPsi * g.normal[t].dot(g.hatGradient[t][k].cross(gradQ[t]));
  }
  return b;
}

// On a torus with arbitrary fields: the kernel against the antisymmetric form above, and the
// discrete conservation laws sum b = 0 (circulation), psi . b = 0 (energy), q . b = 0
// (enstrophy), to round-off (Jespersen 1974; Arakawa 1966).
// One revolution (t = 2 pi / (5/6)) of the degree-3 wave on a super-rotation 1 on the level-3
// icosphere (642 vertices), dt = 0.04: issue 24 asks for energy and enstrophy drifts below 1% per
// revolution; the implicit midpoint rule keeps both to round-off (measured 3e-15 and 4e-15). The
// pattern lags by 0.219 rad after the turn (speed 3.5% slow at this level, 0.89% at level 4:
// second order) and keeps its amplitude to 0.15%.
TEST(SurfaceVorticityStream, OneRevolutionOfARossbyHaurwitzWaveConservesEnergyAndEnstrophy) {
  const TriangleMesh mesh = makeIcosphere(1.0, 3);
  VorticityStreamSettings settings;
  const double period = 2.0 * std::numbers::pi / (5.0 / 6.0);
  const int steps = 190;
  settings.timeStep = period / steps;
  VorticityStream flow(mesh, settings);
  const Eigen::VectorXd cosine = harmonic(mesh, 3, 2), sine = harmonic(mesh, 3, -2);
  flow.setVorticity(0.2 * cosine / cosine.cwiseAbs().maxCoeff() + 2.0 * harmonic(mesh, 1, 0));
  const double e0 = flow.energy(), z0 = flow.enstrophy();
  const double c0 = amplitudeOf(flow, cosine);
  for (int s = 0; s < steps; ++s) flow.step();
  const double lag = std::atan2(amplitudeOf(flow, sine), amplitudeOf(flow, cosine)) / 2.0;
  EXPECT_LT(std::abs(flow.energy() / e0 - 1.0), 1e-10);
  EXPECT_LT(std::abs(flow.enstrophy() / z0 - 1.0), 1e-10);
  EXPECT_LT(std::abs(lag), 0.3);
  EXPECT_NEAR(std::hypot(amplitudeOf(flow, sine), amplitudeOf(flow, cosine)), c0, 0.01 * c0);
}

TEST(SurfaceVorticityStream, GalerkinJacobianConservesCirculationEnergyAndEnstrophy) {
  const TriangleMesh mesh = makeTorus(1.0, 0.35, 40, 16);
  const VorticityStream flow(mesh, {});
  Eigen::VectorXd psi(mesh.vertexCount()), q(mesh.vertexCount());
  for (int i = 0; i < mesh.vertexCount(); ++i) {
    const Eigen::Vector3d& x = mesh.vertices[i];
    psi[i] = std::sin(2.0 * x.x()) + x.y() * x.z();
    q[i] = std::cos(3.0 * x.y() + x.z()) - x.x() * x.x();
  }
  const Eigen::VectorXd b = flow.galerkinJacobian(psi, q);
  const double scale = b.cwiseAbs().sum();
  EXPECT_GT(scale, 1e-2);
  EXPECT_LT((b - jacobianByAntisymmetry(mesh, psi, q)).cwiseAbs().maxCoeff(), 1e-13 * scale);
  EXPECT_LT(std::abs(b.sum()), 1e-13 * scale);
  EXPECT_LT(std::abs(psi.dot(b)), 1e-13 * scale * psi.cwiseAbs().maxCoeff());
  EXPECT_LT(std::abs(q.dot(b)), 1e-13 * scale * q.cwiseAbs().maxCoeff());
}

// A steady body force F = grad Y_l x n (the velocity of the stream function Y_l; n . curl F =
// l (l + 1) Y_l on the unit sphere) against viscosity: the flow settles where
// nu (l (l + 1) - 2) omega = l (l + 1) Y_l (deformation operator), i.e. omega = A Y_l with
// A = l (l + 1) / (nu (l (l + 1) - 2)) (1.5 for l = 2, 1.2 for l = 3, nu = 1, smooth K = 1);
// measured 1.50108 and 1.20071 at level 4 (7e-4 and 6e-4 off).
TEST(SurfaceVorticityStream, ABodyForceBalancesViscosityAtTheAnalyticAmplitude) {
  const TriangleMesh mesh = makeIcosphere(1.0, 4);
  const FaceGeometry g = computeFaceGeometry(mesh);
  for (int l : {2, 3}) {
    const Eigen::VectorXd y = harmonic(mesh, l, 1);
    std::vector<Eigen::Vector3d> force = faceGradient(g, mesh, y);
    for (std::size_t t = 0; t < force.size(); ++t) force[t] = force[t].cross(g.normal[t]);
    VorticityStreamSettings settings;
    settings.viscosity = 1.0;
    settings.timeStep = 0.1;
    settings.bodyForce = force;
    settings.gaussianCurvature = Eigen::VectorXd::Ones(mesh.vertexCount());
    VorticityStream flow(mesh, settings);
    // The weak curl of a discrete velocity grad g x n is S g, exactly.
    const Eigen::VectorXd sy = cotanStiffness(mesh) * y;
    EXPECT_LT((flow.weakCurl(force) - sy).cwiseAbs().maxCoeff(), 1e-12 * sy.cwiseAbs().maxCoeff());
    for (int s = 0; s < 50; ++s) flow.step();  // t = 5: transients decay as e^{-20} or faster
    const double expected = l * (l + 1.0) / (l * (l + 1.0) - 2.0);
    EXPECT_NEAR(amplitudeOf(flow, y), expected, 0.01 * expected) << "l = " << l;
  }
}

TEST(SurfaceVorticityStream, RefusesAnOpenMeshAndNamesWhy) {
  TriangleMesh mesh = makeIcosphere(1.0, 1);
  mesh.faces.pop_back();
  try {
    VorticityStream flow(mesh, {});
    FAIL() << "an open mesh was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("closed"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidviz::surface
