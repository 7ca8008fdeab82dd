// Scene parameters of the FHP solver and their units (FhpParams.h): values out of range and
// impossible combinations refused with the key named; the unit conversion reproduces the
// scene's Reynolds number with Re = g u L / nu (Frisch et al. 1987) and maps flow_velocity onto
// its lattice speed; a Reynolds number the lattice cannot reach is refused with the largest
// reachable one, g u_max L / nu.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "solvers/fhp/FhpParams.h"

namespace fluidviz::fhp {
namespace {

FhpParams channelScene() {
  FhpParams p;
  p.model = Model::fhp3;
  p.channel_density = 0.25;
  p.domain_size = {2.0, 1.0};
  p.resolution = 256;
  p.block_size = 8;
  p.reynolds = 20.0;
  p.reference_length = 0.5;
  p.flow_velocity = {0.3, 0.0};
  p.end_time = 1.0;
  return p;
}

std::string refusedKey(const FhpParams& p) {
  try {
    computeFhpUnits(p);
  } catch (const ParamError& e) {
    return e.key();
  }
  return "(accepted)";
}

TEST(FhpParams, ValuesOutOfRangeAreRefusedNamingTheKey) {
  FhpParams p = channelScene();
  p.channel_density = 0.5;  // g(1/2) = 0: no advection
  EXPECT_EQ(refusedKey(p), "channel_density");
  p = channelScene();
  p.resolution = 200;  // not a multiple of 64
  EXPECT_EQ(refusedKey(p), "resolution");
  p = channelScene();
  p.block_size = 12;  // does not divide 256
  EXPECT_EQ(refusedKey(p), "block_size");
  p = channelScene();
  p.max_lattice_velocity = 0.5;
  EXPECT_EQ(refusedKey(p), "max_lattice_velocity");
  p = channelScene();
  p.walls.x_min.type = SideType::slip;
  p.walls.x_max.type = SideType::slip;
  EXPECT_EQ(refusedKey(p), "walls.x_min.type");
  p = channelScene();
  p.walls.y_min.type = SideType::periodic;  // y_max stays a wall
  EXPECT_EQ(refusedKey(p), "walls.y_max.type");
  p = channelScene();
  p.walls.x_min.type = p.walls.x_max.type = SideType::wall;
  p.inflow_width = 4;  // an inflow zone needs periodic x sides
  EXPECT_EQ(refusedKey(p), "inflow_width");
  p = channelScene();
  p.obstacles.push_back({{1.95, 0.5}, 0.1});  // reaches past x = Lx
  EXPECT_EQ(refusedKey(p), "obstacles[0].center");
  p = channelScene();
  p.flow_velocity = {0.0, 0.0};  // no speed scale
  EXPECT_EQ(refusedKey(p), "reference_velocity");
  p = channelScene();
  p.body_force = 1e6;  // a flip probability far above 1
  EXPECT_EQ(refusedKey(p), "body_force");
  EXPECT_EQ(refusedKey(channelScene()), "(accepted)");
}

// Moving walls and rollers (kernel/MovingWall.h): the keys named, the speeds bounded.
TEST(FhpParams, MovingWallsAndRollersOutOfRangeAreRefusedNamingTheKey) {
  FhpParams p = channelScene();
  p.walls.y_min.velocity = {0.1, 0.0};  // a wall at rest given a velocity
  EXPECT_EQ(refusedKey(p), "walls.y_min.velocity");
  p.walls.y_min.type = SideType::moving_wall;
  EXPECT_EQ(refusedKey(p), "(accepted)");
  p.walls.y_min.velocity = {0.1, 0.05};  // a normal component
  EXPECT_EQ(refusedKey(p), "walls.y_min.velocity");
  p.walls.y_min.velocity = {30.0, 0.0};  // far above max_lattice_velocity
  EXPECT_EQ(refusedKey(p), "walls.y_min.velocity");
  p = channelScene();
  p.rollers.push_back({{1.0, 0.5}, 0.2, 1.0, lbm::RollerBoundary::interpolated});
  EXPECT_EQ(refusedKey(p), "rollers[0].boundary");
  p.rollers[0].boundary = lbm::RollerBoundary::staircase;
  EXPECT_EQ(refusedKey(p), "(accepted)");
  p.rollers[0].angular_velocity = 200.0;  // rim at 40 m/s
  EXPECT_EQ(refusedKey(p), "rollers[0].angular_velocity");
  p.rollers[0] = {{1.9, 0.5}, 0.2, 1.0};  // reaches past x = Lx
  EXPECT_EQ(refusedKey(p), "rollers[0].center");
  // No flow and no reference speed: U_ref is the fastest rim.
  p = channelScene();
  p.flow_velocity = {0.0, 0.0};
  p.rollers.push_back({{1.0, 0.5}, 0.2, -1.5});
  EXPECT_NEAR(computeFhpUnits(p).toLatticeVelocity(0.3), computeFhpUnits(p).referenceSpeed, 1e-12);
}

TEST(FhpParams, UnitsReproduceTheReynoldsNumberAndTheFlowSpeed) {
  const FhpParams p = channelScene();
  const FhpUnits u = computeFhpUnits(p);
  EXPECT_EQ(u.nx, 256);
  EXPECT_EQ(u.blockY, 9);  // round(8 / (sqrt(3)/2))
  // Rows: Ly / (sqrt(3)/2 dx) = 147.8, as a multiple of lcm(2, 9) = 18: 144.
  EXPECT_EQ(u.ny, 144);
  EXPECT_NEAR(u.dx, 2.0 / 256, 1e-15);
  // Re = U L / nu_phys with nu_phys = nu dx^2 / dt.
  EXPECT_NEAR(0.3 * 0.5 / u.viscosity, 20.0, 1e-10);
  // Re = g u L / nu in lattice units, L = 64 links.
  EXPECT_NEAR(u.g * u.referenceSpeed * 64.0 / u.nu, 20.0, 1e-10);
  EXPECT_NEAR(u.toPhysicalVelocity(u.flowSpeed[0]), 0.3, 1e-12);
  EXPECT_EQ(u.steps, static_cast<long long>(std::ceil(1.0 / u.dt - 1e-9)));
}

TEST(FhpParams, UnreachableReynoldsNumberIsRefusedWithTheLargestReachable) {
  FhpParams p = channelScene();
  p.reynolds = 200.0;
  const double nu = latticeViscosity(Model::fhp3, 0.25), g = galileanFactor(Model::fhp3, 0.25);
  const double reachable = g * 0.2 * 64.0 / nu;  // max_lattice_velocity 0.2 on L_ref = 64 links
  ASSERT_LT(reachable, 200.0);
  try {
    computeFhpUnits(p);
    FAIL() << "Re 200 accepted on 64 links";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "reynolds");
    const std::string m = e.what();
    std::smatch found;
    ASSERT_TRUE(std::regex_search(m, found, std::regex("largest reachable Re at resolution 256 is ([0-9.]+)")))
        << m;
    EXPECT_NEAR(std::stod(found[1]), reachable, 1e-3 * reachable) << m;
    EXPECT_NE(m.find("raise resolution to"), std::string::npos) << m;
  }
  p.reynolds = 0.99 * reachable;
  EXPECT_NO_THROW(computeFhpUnits(p));
}

TEST(FhpParams, ViscosityAndGalileanFactorAtTheTabulatedPoint) {
  // Frisch et al. 1987, section 6, at d = 1/4 (hand-evaluated from their closed forms):
  // FHP-I nu = 1/(12 * 1/4 * 27/64) - 1/8 = 64/81 - 1/8; g = (1/2)/(3/2) = 1/3.
  EXPECT_NEAR(latticeViscosity(Model::fhp1, 0.25), 64.0 / 81.0 - 0.125, 1e-14);
  EXPECT_NEAR(galileanFactor(Model::fhp1, 0.25), 1.0 / 3.0, 1e-14);
  // FHP-III: 1/(28 * 3/16 * (1 - 3/14)) - 1/8 = 1/(33/8) - 1/8 = 8/33 - 1/8; g = 7/18.
  EXPECT_NEAR(latticeViscosity(Model::fhp3, 0.25), 8.0 / 33.0 - 0.125, 1e-14);
  EXPECT_NEAR(galileanFactor(Model::fhp3, 0.25), 7.0 / 18.0, 1e-14);
  // FHP-II: 1/(28 * 1/4 * 27/64 * 6/7) - 1/8 = 1/(81/32) - 1/8 = 32/81 - 1/8.
  EXPECT_NEAR(latticeViscosity(Model::fhp2, 0.25), 32.0 / 81.0 - 0.125, 1e-14);
}

}  // namespace
}  // namespace fluidviz::fhp
