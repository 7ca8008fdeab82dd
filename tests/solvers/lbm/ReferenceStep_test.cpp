// The optimised stream-collide kernel (kernel/StreamCollidePull.h, driven by LbmSolverImpl)
// against the plain reference step (kernel/ReferenceStreamCollide.h): for every boundary rule the
// solver builds, both lattices, both precisions and both collision operators, the two start from
// the same (non-equilibrium) post-collision populations, run kSteps steps on a small box, and
// must agree at every fluid node in every population and in density and velocity.
//
// Tolerances. The two evaluate the same formulas in a different order (the kernel sums the
// moments in four interleaved partial sums, splits the collision into the even and odd parts of
// each opposite pair, and folds the Bouzidi weights; the reference writes them out as
// equations), so they agree to round-off, not bitwise:
//  - double: max |difference| <= 1e-14 in the shifted populations g = f - w (|g| < 0.05 here)
//    and in the lattice density and velocity: a few ulp of 1 (2.2e-16) per quantity, growing
//    slowly over the 50 steps; measured at most 7e-16.
//  - float: the kernel computes in float, the reference in double and stores in float, so the
//    difference is the kernel's float round-off, a few ulp of the populations' size per step:
//    max |difference| <= 2e-6 (float ulp of 1 is 1.2e-7, and density and velocity carry the sum
//    of Q of them); measured at most 2e-7.
// A wrong rule (a sign, a missing momentum term, the wrong neighbour) differs by the size of a
// population change, 1e-5 to 1e-2, far above both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "solvers/lbm/LbmSolver.h"
#include "solvers/lbm/boundaries/SolidBody.h"
#include "solvers/lbm/kernel/ReferenceStreamCollide.h"
#include "solvers/lbm/lattice/LatticeD2Q9.h"
#include "solvers/lbm/lattice/LatticeD3Q19.h"

namespace fluidviz::lbm {
namespace {

constexpr int kNx = 24, kNy = 20, kNz = 12;
constexpr int kSteps = 50;

// ---- scenes -------------------------------------------------------------------------------

/// The 24 x 20 (x 12) box, walls at rest, the given collision operator.
LbmParams smallBox(bool threeD, const std::string& collision) {
  LbmParams p;
  p.lattice = threeD ? Lattice::D3Q19 : Lattice::D2Q9;
  p.collision = choiceNamed<Collision>(collision);
  p.domain_size = {1.0, double(kNy) / kNx};
  if (threeD) p.domain_depth = double(kNz) / kNx;
  p.resolution = kNx;
  p.end_time = 1e6;
  return p;
}

/// Nothing moves: the time step from the relaxation time tau = 0.7, dt = (tau - 1/2) dx^2 / (3 nu).
constexpr double kStillViscosity = 1e-3;  // m^2/s
double stillTimeStep() {
  const double dx = 1.0 / kNx;
  return 0.2 / 3.0 * dx * dx / kStillViscosity;
}
void setStillTimeStep(LbmParams& p) {
  p.viscosity = kStillViscosity;
  p.time_step = stillTimeStep();
}

/// Something moves at speed U = 1 m/s: lattice speed 0.05, tau = 0.5 + 3 * 0.05 * 24 / 20 = 0.68.
void setMovingTimeStep(LbmParams& p) {
  p.reynolds = 20;
  p.lattice_velocity = 0.05;
}

/// A body acceleration of 1e-5 lattice units (g dt^2 / dx) along x, less along y and z.
void setBodyForce(LbmParams& p, bool threeD, double timeStep) {
  const double dx = 1.0 / kNx, g = 1e-5 * dx / (timeStep * timeStep);
  p.body_force = {g, -0.6 * g};
  if (threeD) p.body_force_z = 0.3 * g;
}

void periodic(WallParams& a, WallParams& b) { a.type = b.type = WallType::periodic; }

struct Scene {
  std::string name;
  std::function<LbmParams(bool threeD, const std::string& collision)> params;
  std::function<std::vector<SolidBody>()> extraBodies = [] { return std::vector<SolidBody>{}; };
};

std::vector<Scene> scenes() {
  std::vector<Scene> s;
  s.push_back({"WallsAtRest", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setStillTimeStep(p);
                 return p;
               }});
  // Moving lid, a second moving wall meeting it at an edge (their velocities add on the links
  // through the edge), and in 3D a lid moving along z too.
  s.push_back({"MovingWalls", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setMovingTimeStep(p);
                 p.walls.y_max.type = WallType::moving_wall;
                 p.walls.y_max.velocity = {1.0, 0.0};
                 p.walls.x_min.type = WallType::moving_wall;
                 p.walls.x_min.velocity = {0.0, -0.5};
                 if (threeD) {
                   p.walls.y_max.velocity_z = 0.4;
                   p.walls.z_max.type = WallType::moving_wall;
                   p.walls.z_max.velocity = {0.3, 0.5};
                 }
                 return p;
               }});
  s.push_back({"PeriodicChannelWithBodyForce", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setStillTimeStep(p);
                 setBodyForce(p, threeD, stillTimeStep());
                 periodic(p.walls.x_min, p.walls.x_max);
                 if (threeD) periodic(p.walls.z_min, p.walls.z_max);
                 return p;
               }});
  s.push_back({"PeriodicEverywhere", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setStillTimeStep(p);
                 setBodyForce(p, threeD, stillTimeStep());
                 periodic(p.walls.x_min, p.walls.x_max);
                 periodic(p.walls.y_min, p.walls.y_max);
                 if (threeD) periodic(p.walls.z_min, p.walls.z_max);
                 return p;
               }});
  s.push_back({"ZouHeInletAndOutlet", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setMovingTimeStep(p);
                 p.walls.x_min.type = WallType::velocity_inlet;
                 p.walls.x_min.velocity = {1.0, 0.2};
                 if (threeD) p.walls.x_min.velocity_z = -0.1;
                 p.walls.x_max.type = WallType::pressure_outlet;
                 p.walls.x_max.pressure = 500.0;  // Pa: lattice density about 1.0036
                 return p;
               }});
  // A parabolic inlet that ramps up: the velocity varies node by node along the side
  // (inletProfileFactor) and step by step (inletRampFactor).
  s.push_back({"ZouHeParabolicInlet", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setMovingTimeStep(p);
                 p.walls.x_min.type = WallType::velocity_inlet;
                 p.walls.x_min.velocity = {1.5, 0.0};
                 p.walls.x_min.profile = InletProfile::parabolic;
                 // dt = 0.05 dx / U_ref, U_ref the mean inlet speed: a ramp of 80 steps, longer
                 // than the comparison.
                 const double meanSpeed = 1.5 * (threeD ? 4.0 / 9.0 : 2.0 / 3.0);
                 p.walls.x_min.ramp_time = 80 * 0.05 / kNx / meanSpeed;
                 p.walls.x_max.type = WallType::pressure_outlet;
                 return p;
               }});
  // Open sides across y with a body force (the Zou-He momentum shift by g/2), periodic in x.
  s.push_back({"ZouHeAlongYWithBodyForce", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setMovingTimeStep(p);
                 periodic(p.walls.x_min, p.walls.x_max);
                 p.walls.y_min.type = WallType::velocity_inlet;
                 p.walls.y_min.velocity = {0.1, 1.0};
                 p.walls.y_max.type = WallType::pressure_inlet;
                 p.walls.y_max.pressure = -300.0;  // Pa: lattice density about 0.9978
                 // dt = 0.05 dx / U with U = |inlet velocity|.
                 setBodyForce(p, threeD, 0.05 / kNx / std::hypot(0.1, 1.0));
                 return p;
               }});
  s.push_back({"StaircaseRoller", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setMovingTimeStep(p);
                 p.walls.y_max.type = WallType::moving_wall;
                 p.walls.y_max.velocity = {0.5, 0.0};
                 p.rollers.push_back({{0.45, 0.4}, 0.2, 5.0, RollerBoundary::staircase});
                 return p;
               }});
  // Wall fractions on both sides of 1/2, and a roller touching the wall y = 0: links in the gap
  // have no second fluid node (Bouzidi falls back to halfway bounce-back there).
  s.push_back({"BouzidiRollers", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setMovingTimeStep(p);
                 p.rollers.push_back({{0.4, 0.45}, 0.21, 4.0, RollerBoundary::interpolated});
                 p.rollers.push_back({{0.8, 0.13}, 0.13, -6.0, RollerBoundary::interpolated});
                 return p;
               }});
  // A roller touching the periodic side x = 0: links of the last column wrap into it, and so do
  // the second nodes of its interpolated links.
  s.push_back({"BouzidiRollerAcrossPeriodicSide", [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setMovingTimeStep(p);
                 periodic(p.walls.x_min, p.walls.x_max);
                 p.rollers.push_back({{0.15, 0.42}, 0.15, 6.0, RollerBoundary::interpolated});
                 return p;
               }});
  // A body that is not a roller (extraBodies): the fixed outer cylinder of Taylor-Couette flow
  // around a turning staircase roller.
  s.push_back({"OuterCylinderAroundRoller",
               [](bool threeD, const std::string& c) {
                 LbmParams p = smallBox(threeD, c);
                 setMovingTimeStep(p);
                 p.rollers.push_back({{0.5, 0.42}, 0.17, 5.0, RollerBoundary::staircase});
                 return p;
               },
               [] {
                 const Vec2 centre(0.5, 0.42);
                 SolidBody outer{"outer cylinder",
                                 [=](const Vec2& x) { return (x - centre).norm() >= 0.38; },
                                 [](const Vec2&) { return Vec2(0.0, 0.0); }, true};
                 return std::vector<SolidBody>{outer};
               }});
  return s;
}

// ---- populations in and out of the solver --------------------------------------------------

template <class L, class T>
using Populations = typename ReferenceStreamCollide<L, T>::Populations;

/// Byte offset of the populations in a solver's checkpoint state: after the lattice name,
/// sizeof(T), nx, ny, nz, the step count and the steady flag (LbmSolverState.cpp); the Q planes
/// of nodeCount values follow. Throws StateFormatError if the solver's populations are not T.
template <class T>
std::size_t populationOffset(const std::vector<std::uint8_t>& state) {
  StateReader r(state);
  r.getString();
  StateReader::requireSame("the population size (bytes)", r.get<std::int32_t>(),
                           static_cast<std::int32_t>(sizeof(T)));
  for (int k = 0; k < 3; ++k) r.get<std::int32_t>();
  r.get<std::int64_t>();
  r.get<std::uint8_t>();
  return r.offset();
}

template <class L, class T>
Populations<L, T> postCollisionPopulations(const LbmSolver& solver, std::int64_t nodes) {
  StateWriter w;
  solver.saveState(w);
  const std::uint8_t* at = w.bytes().data() + populationOffset<T>(w.bytes());
  Populations<L, T> f;
  for (int q = 0; q < L::Q; ++q) {
    f[q].resize(nodes);
    std::memcpy(f[q].data(), at + q * nodes * sizeof(T), nodes * sizeof(T));
  }
  return f;
}

template <class L, class T>
void setPostCollisionPopulations(LbmSolver& solver, const Populations<L, T>& f) {
  StateWriter w;
  solver.saveState(w);
  const std::int64_t nodes = static_cast<std::int64_t>(f[0].size());
  std::uint8_t* at = w.bytes().data() + populationOffset<T>(w.bytes());
  for (int q = 0; q < L::Q; ++q) std::memcpy(at + q * nodes * sizeof(T), f[q].data(), nodes * sizeof(T));
  StateReader r(w.bytes());
  solver.restoreState(r);
}

/// A smooth flow (density 1 +- 0.01, speed up to 0.03) off equilibrium: each population
/// perturbed by up to 2 % of its weight, so that every relaxation rate and rule acts from the
/// first step.
template <class L, class T>
Populations<L, T> initialPopulations(const LatticeUnits& u) {
  const int nz = L::D == 3 ? u.nz : 1;
  Populations<L, T> f;
  for (int q = 0; q < L::Q; ++q) f[q].resize(std::size_t(u.nx) * u.ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < u.ny; ++j)
      for (int i = 0; i < u.nx; ++i) {
        const std::size_t n = (std::size_t(k) * u.ny + j) * u.nx + i;
        const double x = 2 * M_PI * i / u.nx, y = 2 * M_PI * j / u.ny, z = 2 * M_PI * k / nz;
        const double rho = 1.0 + 0.01 * std::sin(x + 2 * y + z);
        const double ux = 0.03 * std::sin(y) * std::cos(z), uy = -0.02 * std::sin(x);
        const double uz = L::D == 3 ? 0.01 * std::cos(x + y) : 0.0;
        for (int q = 0; q < L::Q; ++q)
          f[q][n] = static_cast<T>(shiftedEquilibrium<L>(q, rho, ux, uy, uz) +
                                   0.02 * L::w[q] * std::sin(1.7 * double(n) + 2.3 * q));
      }
  return f;
}

// ---- the comparison -----------------------------------------------------------------------

struct Agreement {
  double populations = 0.0;  ///< max |g_kernel - g_reference| over fluid nodes and directions
  double density = 0.0;      ///< max |rho_kernel - rho_reference|, lattice units
  double velocity = 0.0;     ///< max |u_kernel - u_reference|, lattice units
  double maxSpeed = 0.0;     ///< max |u_reference|: the flow is not trivial
};

template <class L, class T>
Agreement compareWithReference(const Scene& scene, const std::string& collision) {
  LbmParams params = scene.params(L::D == 3, collision);
  params.precision = sizeof(T) == 4 ? Precision::float32 : Precision::float64;
  const std::unique_ptr<LbmSolver> solver = createLbmSolver(params, scene.extraBodies());
  ReferenceStreamCollide<L, T> reference(params, scene.extraBodies());
  const LatticeUnits& u = solver->units();
  const std::int64_t nodes = reference.nodeCount();

  const Populations<L, T> start = initialPopulations<L, T>(u);
  setPostCollisionPopulations<L, T>(*solver, start);
  reference.startFromPostCollision(start);
  solver->step(kSteps);
  for (int s = 0; s < kSteps; ++s) reference.step();

  Agreement a;
  const Populations<L, T> kernel = postCollisionPopulations<L, T>(*solver, nodes);
  const FieldSet fields = solver->fields();
  const auto& density = fields.findScalar("density")->values;
  const auto& velocity = fields.findVector("velocity")->values;
  for (std::int64_t n = 0; n < nodes; ++n) {
    const bool solid = reference.isSolid(n);
    EXPECT_EQ(solid, solver->isSolid(n % u.nx, n / u.nx % u.ny, n / (std::int64_t(u.nx) * u.ny)));
    if (solid) continue;
    for (int q = 0; q < L::Q; ++q)
      a.populations = std::max(
          a.populations, std::abs(double(kernel[q][n]) - double(reference.postCollision()[q][n])));
    const NodeMoments<double> m = reference.moments(n);
    const Vec3 uKernel = velocity[n] * (u.dt / u.dx);
    a.density = std::max(a.density, std::abs(u.toLatticeDensity(density[n]) - m.rho));
    a.velocity = std::max(a.velocity, (uKernel - Vec3(m.ux, m.uy, m.uz)).norm());
    a.maxSpeed = std::max(a.maxSpeed, std::hypot(m.ux, m.uy, m.uz));
  }
  return a;
}

template <class L, class T>
void expectAgreement(const Scene& scene, const std::string& collision) {
  SCOPED_TRACE(std::string(L::name) + (sizeof(T) == 4 ? " float" : " double"));
  const Agreement a = compareWithReference<L, T>(scene, collision);
  const double tolerance = sizeof(T) == 8 ? 1e-14 : 2e-6;
  EXPECT_LE(a.populations, tolerance);
  EXPECT_LE(a.density, tolerance);
  EXPECT_LE(a.velocity, tolerance);
  EXPECT_GT(a.maxSpeed, 1e-3);
}

class ReferenceStep : public testing::TestWithParam<std::tuple<int, std::string>> {};

TEST_P(ReferenceStep, KernelMatchesThePlainStep) {
  const Scene scene = scenes()[std::get<0>(GetParam())];
  const std::string& collision = std::get<1>(GetParam());
  expectAgreement<LatticeD2Q9, double>(scene, collision);
  expectAgreement<LatticeD2Q9, float>(scene, collision);
  expectAgreement<LatticeD3Q19, double>(scene, collision);
  expectAgreement<LatticeD3Q19, float>(scene, collision);
}

INSTANTIATE_TEST_SUITE_P(
    EveryBoundaryRule, ReferenceStep,
    testing::Combine(testing::Range(0, static_cast<int>(scenes().size())),
                     testing::Values(std::string("bgk"), std::string("trt"))),
    [](const testing::TestParamInfo<ReferenceStep::ParamType>& info) {
      return scenes()[std::get<0>(info.param)].name + "_" + std::get<1>(info.param);
    });

}  // namespace
}  // namespace fluidviz::lbm
