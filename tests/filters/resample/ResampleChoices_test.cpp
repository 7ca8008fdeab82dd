// What the resampler chooses when the user does not say (and says so), and how it refuses bad
// input: messages that name the key, the array or the particle, and grids refused before any
// memory is allocated.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "filters/resample/ParticleResampler.h"
#include "tests/filters/resample/ParticleClouds.h"

using namespace fluidviz;
using namespace fluidviz::resample;
using fluidviz::testing::addScalar;
using fluidviz::testing::jitteredBox;

namespace {

particles::ParticleSet lattice(double dx = 0.1) { return jitteredBox(3, 0.0, 1.0, dx, 0.0); }

// Runs `f`, expects `Exception` whose what() contains `text`.
template <class Exception, class F>
void expectThrowContaining(F&& f, const std::string& text) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one containing: " << text;
  } catch (const Exception& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

ParamError paramErrorOf(const particles::ParticleSet& ps, const ParticleResampleParams& p) {
  try {
    resampleParticles(ps, p);
  } catch (const ParamError& e) {
    return e;
  }
  ADD_FAILURE() << "no ParamError";
  return ParamError("", "");
}

}  // namespace

// A lattice without masses: s = the nearest-neighbour distance (exactly dx), h = 1.3 s, nodes
// s apart, uniform volume s^3, each choice named in the report.
TEST(ResampleChoices, DefaultsComeFromTheParticleSpacingAndAreReported) {
  const ResampleResult r = resampleParticles(lattice(0.1), ParticleResampleParams{});
  EXPECT_NEAR(r.report.particleSpacing, 0.1, 1e-12);
  EXPECT_EQ(r.report.spacingSource, "median nearest-neighbour distance");
  EXPECT_NEAR(r.report.smoothingLength, 0.13, 1e-12);
  EXPECT_NEAR(r.report.grid.spacing[0], 0.1, 1e-12);
  EXPECT_NE(r.report.volumeSource.find("uniform s^d (assumed: the particles have no 'mass' and "
                                       "no 'density' array)"),
            std::string::npos)
      << r.report.volumeSource;
  const std::string summary = r.report.summary();
  EXPECT_NE(summary.find("h = 0.13 m"), std::string::npos) << summary;
  EXPECT_EQ(r.report.dimension, 3);
}

// Masses and densities give V = m / rho per particle and s = median V^(1/3); with only one of
// the two arrays the report says which one is missing.
TEST(ResampleChoices, MassAndDensityGiveVolumesAndSpacing) {
  particles::ParticleSet ps = lattice(0.1);
  addScalar(ps, "mass", [](const Vec3&) { return 8e-3 * 1000.0; });  // V = 8e-3 m^3: s = 0.2 m
  addScalar(ps, "density", [](const Vec3&) { return 1000.0; });
  const ResampleResult r = resampleParticles(ps, ParticleResampleParams{});
  EXPECT_NEAR(r.report.particleSpacing, 0.2, 1e-12);
  EXPECT_EQ(r.report.volumeSource, "m/rho from arrays 'mass' and 'density'");
  ps.scalars.pop_back();
  const ResampleResult m = resampleParticles(ps, ParticleResampleParams{});
  EXPECT_NE(m.report.volumeSource.find("have no 'density' array"), std::string::npos)
      << m.report.volumeSource;
}

// All particles in one z plane: a 2D grid (one node in z, at their z) and the 2D kernel.
TEST(ResampleChoices, FlatParticlesGiveA2DGrid) {
  particles::ParticleSet ps = jitteredBox(2, 0.0, 1.0, 0.05, 0.0);
  for (Vec3& p : ps.positions) p.z() = 0.25;
  addScalar(ps, "f", [](const Vec3& p) { return p.x(); });
  const ResampleResult r = resampleParticles(ps, ParticleResampleParams{});
  EXPECT_EQ(r.report.dimension, 2);
  EXPECT_EQ(r.fields.grid.dims[2], 1);
  EXPECT_DOUBLE_EQ(r.fields.grid.origin[2], 0.25);
  const ScalarField& f = *r.fields.findScalar("f");
  const Grid& g = f.grid;
  const int mid = g.dims[0] / 2;
  EXPECT_NEAR(f.values[g.index(mid, mid)], g.position(mid, mid).x(), 1e-12);  // lattice: exact
}

// Memory is the output arrays: f(1) + colour + mask + summation density = 4 doubles per node
// (56^3 nodes: 5.62 MB for 50^3 particles 0.02 m apart, padded by 2h = 0.052 m); the node sums
// exist for one block of layers per thread only. A limit just below that is
// refused with the grid size and the memory in the message; just above is accepted.
TEST(ResampleChoices, GridsNeedingMoreThanTheMemoryLimitAreRefused) {
  particles::ParticleSet ps = lattice(0.02);
  addScalar(ps, "f", [](const Vec3&) { return 1.0; });
  addScalar(ps, "mass", [](const Vec3&) { return 1.0; });
  ParticleResampleParams p;
  p.arrays = "f";
  p.particle_spacing = 0.02;
  const ResampleResult ok = resampleParticles(ps, p);
  const double bytes = 4.0 * 8.0 * ok.fields.grid.nodeCount();
  EXPECT_DOUBLE_EQ(ok.report.fieldBytes, bytes);
  p.max_memory_mb = 0.99 * bytes / 1e6;
  const ParamError e = paramErrorOf(ps, p);
  EXPECT_EQ(e.key(), "spacing");
  EXPECT_NE(std::string(e.what()).find("(not given: the particle spacing) gives a 56 x 56 x 56 "
                                       "grid (1.756e+05 nodes, node spacing 0.02 m) whose "
                                       "arrays would need 5.62 MB"),
            std::string::npos)
      << e.what();
  p.max_memory_mb = 1.01 * bytes / 1e6;
  EXPECT_NO_THROW(resampleParticles(ps, p));
}

TEST(ResampleChoices, BadParametersNameTheirKey) {
  const particles::ParticleSet ps = lattice();
  ParticleResampleParams p;
  p.kernel = static_cast<ResampleKernel>(7);
  EXPECT_EQ(paramErrorOf(ps, p).key(), "kernel");
  p = {};
  p.dims = 1;
  EXPECT_EQ(paramErrorOf(ps, p).key(), "dims");
  p = {};
  p.support_threshold = 1.5;
  EXPECT_EQ(paramErrorOf(ps, p).key(), "support_threshold");
  p = {};
  p.dimension = 1;
  EXPECT_EQ(paramErrorOf(ps, p).key(), "dimension");
  p = {};
  p.smoothing_length = 0.0;
  EXPECT_EQ(paramErrorOf(ps, p).key(), "smoothing_length");
}

TEST(ResampleChoices, UnknownOrReservedArraysAreRefusedListingThosePresent) {
  particles::ParticleSet ps = lattice();
  addScalar(ps, "pressure", [](const Vec3&) { return 1.0; });
  ps.vectors.push_back({"velocity", std::vector<Vec3>(ps.size(), Vec3::Zero())});
  ParticleResampleParams p;
  p.arrays = "pressure, vorticity";
  const ParamError missing = paramErrorOf(ps, p);
  EXPECT_EQ(missing.key(), "arrays");
  EXPECT_NE(std::string(missing.what())
                .find("names 'vorticity', which the particles do not have; arrays present: "
                      "pressure(1), velocity(3)"),
            std::string::npos)
      << missing.what();
  addScalar(ps, "mask", [](const Vec3&) { return 1.0; });
  p.arrays = "";
  EXPECT_NE(std::string(paramErrorOf(ps, p).what()).find("particle array 'mask' has the name of "
                                                         "an output array"),
            std::string::npos);
}

TEST(ResampleChoices, BadParticleDataNamesTheArrayOrParticle) {
  ParticleResampleParams p;
  expectThrowContaining<std::invalid_argument>(
      [&] { resampleParticles(particles::ParticleSet{}, p); }, "there are no particles");
  particles::ParticleSet ps = lattice();
  ps.positions[17].y() = std::numeric_limits<double>::quiet_NaN();
  expectThrowContaining<std::invalid_argument>([&] { resampleParticles(ps, p); },
                                               "particle 17 has a non-finite position");
  ps = lattice();
  addScalar(ps, "mass", [](const Vec3& x) { return x.x() > 0.5 ? -1.0 : 1.0; });
  expectThrowContaining<std::invalid_argument>([&] { resampleParticles(ps, p); },
                                               "particle array 'mass' is -1");
  ps = lattice();
  ps.scalars.push_back({"short", {1.0, 2.0}});
  expectThrowContaining<std::invalid_argument>([&] { resampleParticles(ps, p); },
                                               "particle array 'short' has 2 values for 1000");
}

TEST(ResampleChoices, SpacingThatCannotBeEstimatedAsksForParticleSpacing) {
  ParticleResampleParams p;
  particles::ParticleSet one;
  one.positions = {Vec3(0.5, 0.5, 0.5)};
  expectThrowContaining<std::invalid_argument>([&] { resampleParticles(one, p); },
                                               "give particle_spacing");
  p.particle_spacing = 0.1;  // then a lone particle is fine: a 2h ball of colour around it
  const ResampleResult r = resampleParticles(one, p);
  const auto& c = r.fields.findScalar("color")->values;
  EXPECT_GT(*std::max_element(c.begin(), c.end()), 0.0);
  particles::ParticleSet same;
  same.positions.assign(10, Vec3(0.1, 0.2, 0.3));
  same.positions.push_back(Vec3(0.2, 0.2, 0.3));
  p = {};
  expectThrowContaining<std::invalid_argument>([&] { resampleParticles(same, p); },
                                               "most particles coincide");
}
