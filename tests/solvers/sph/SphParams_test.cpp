// Parameter validation: every bad value or combination is a ParamError naming the key (relative
// to SphParams) and saying what to change; a valid scene lays out the expected particles.
#include <gtest/gtest.h>

#include "tests/support/SphScenes.h"

namespace fluidviz::sph {
namespace {

SphParams valid() { return test::damBreak2D("B", 0.5, 10); }

void expectParamError(const SphParams& p, const std::string& key, const std::string& hint) {
  try {
    validateSphParams(p);
    ADD_FAILURE() << "no ParamError for " << key;
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(hint), std::string::npos) << e.what();
  }
}

TEST(SphParams, RejectsBadValuesNamingTheKey) {
  SphParams p = valid();
  p.dimension = 4;
  expectParamError(p, "dimension", "[2, 3]");
  p = valid();
  p.model = static_cast<SphModel>(7);
  expectParamError(p, "model", "muller2003, weakly_compressible");
  p = valid();
  p.particle_spacing = 0;
  expectParamError(p, "particle_spacing", "> 0");
  p = valid();
  p.speed_of_sound = -1;
  expectParamError(p, "speed_of_sound", "> 0");
  p = valid();
  p.kernel = static_cast<SphKernel>(7);
  expectParamError(p, "kernel", "wendland_c2");
  p = valid();
  p.walls.x_max = static_cast<SphSide>(7);
  expectParamError(p, "walls.x_max", "periodic");
  p = valid();
  p.fluid_blocks[0].upper[1] = -1;
  expectParamError(p, "fluid_blocks[0].upper", "not above");
  p = valid();
  p.time_step = 0.0;
  expectParamError(p, "time_step", "> 0");
}

TEST(SphParams, RejectsBadCombinations) {
  SphParams p = valid();
  p.fluid_blocks.clear();
  expectParamError(p, "fluid_blocks", "at least one");
  p = valid();
  p.fluid_blocks[0].upper[0] = 5.0;  // domain is 2 m long
  expectParamError(p, "fluid_blocks[0]", "outside the domain");
  p = valid();
  p.walls.x_min = fluidviz::sph::SphSide::periodic;
  expectParamError(p, "walls.x_max", "pairs");
  p = valid();
  p.walls.x_min = p.walls.x_max = fluidviz::sph::SphSide::periodic;
  p.domain_upper[0] = 2.0 + 0.3 * p.particle_spacing;
  expectParamError(p, "domain_upper[0]", "whole number");
  p = valid();
  p.model = fluidviz::sph::SphModel::muller2003;
  p.alpha = 0.1;
  expectParamError(p, "alpha", "model weakly_compressible only");
  p = valid();
  p.surface_tension = 0.07;
  expectParamError(p, "surface_tension", "model muller2003 only");
  p = valid();
  p.rollers = {{{1.0, 1.0}, 0.01, 1.0}};
  expectParamError(p, "rollers[0].radius", "2 particle spacings");
  p = valid();
  p.rollers = {{{1.0, 1.0}, 0.3, 1.0}, {{1.4, 1.0}, 0.3, 1.0}};
  expectParamError(p, "rollers[1]", "overlaps");
  p = valid();
  p.boundary_exponents = {4, 12};
  expectParamError(p, "boundary_exponents", "n1 > n2");
}

TEST(SphParams, ValidSceneLaysOutLatticeAndWalls) {
  const SphParams p = valid();  // column 0.5 x 1.0 m, dx = 0.05 m, tank 2 x 1.5 m open top
  validateSphParams(p);
  SphSolver s(p);
  EXPECT_EQ(s.fluidCount(), 10u * 20u);
  EXPECT_DOUBLE_EQ(s.particleMass(), 1000.0 * 0.05 * 0.05);
  EXPECT_DOUBLE_EQ(s.smoothingLength(), 1.3 * 0.05);
  // 3 wall layers (2h = 2.6 dx): bottom 46 x 3 (with corners), sides 30 x 3 each; no top.
  EXPECT_EQ(s.boundaryParticles().size(), 46u * 3u + 2u * 30u * 3u);
  // Hydrostatic start: the bottom particle's density follows Tait from rho0 g (2a - dx/2).
  const particles::ParticleSet f = s.fluid();
  const double pBottom = 1000.0 * test::kGravity * (1.0 - 0.025);
  EXPECT_NEAR(f.findScalar("pressure")->values[0], pBottom, 1e-9 * pBottom);
  EXPECT_NE(f.findVector("velocity"), nullptr);
  EXPECT_NE(f.findScalar("density"), nullptr);
}

}  // namespace
}  // namespace fluidviz::sph
