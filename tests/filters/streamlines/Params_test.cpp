// Parameter and input errors name the key or the array and the allowed range.
#include <gtest/gtest.h>

#include "filters/streamlines/Seeding.h"
#include "filters/streamlines/Streamline.h"
#include "tests/support/AnalyticFields.h"

using namespace fluidviz;
using namespace fluidviz::streamlines;
using namespace fluidviz::testing;

namespace {
template <class F>
std::pair<std::string, std::string> paramError(F&& f) {
  try {
    f();
  } catch (const ParamError& e) {
    return {e.key(), e.what()};
  }
  return {"<no error>", ""};
}
const VectorField kField = uniformField(squareGrid(11, 0.0, 10.0), Vec3(1.0, 0.0, 0.0));
}  // namespace

TEST(StreamlineParams, DefaultsAreValid) { EXPECT_NO_THROW(validateStreamlineParams({})); }

TEST(StreamlineParams, OutOfRangeValuesNameTheKeyAndRange) {
  StreamlineParams p;
  p.step = 0.0;
  auto [key, msg] = paramError([&] { StreamlineTracer(kField, p); });
  EXPECT_EQ(key, "step");
  EXPECT_NE(msg.find("(0, 100]"), std::string::npos) << msg;

  p = {};
  p.integrator = static_cast<Integrator>(7);
  std::tie(key, msg) = paramError([&] { validateStreamlineParams(p); });
  EXPECT_EQ(key, "integrator");
  EXPECT_NE(msg.find("rk2, rk4, rk45"), std::string::npos) << msg;

  p = {};
  p.stagnation_speed = 1.0;
  EXPECT_EQ(paramError([&] { validateStreamlineParams(p); }).first, "stagnation_speed");
  p = {};
  p.max_steps = 0;
  EXPECT_EQ(paramError([&] { validateStreamlineParams(p); }).first, "max_steps");
}

TEST(StreamlineParams, Rk45StepMustLieBetweenMinAndMaxStep) {
  StreamlineParams p;
  p.integrator = fluidviz::streamlines::Integrator::rk45;
  p.step = 3.0;
  p.max_step = 2.0;
  auto [key, msg] = paramError([&] { validateStreamlineParams(p); });
  EXPECT_EQ(key, "step");
  EXPECT_NE(msg.find("[min_step, max_step]"), std::string::npos) << msg;
  p.step = 1.0;
  p.min_step = 2.5;
  p.max_step = 2.0;
  EXPECT_EQ(paramError([&] { validateStreamlineParams(p); }).first, "min_step");
}

TEST(StreamlineParams, FieldWithWrongValueCountNamesTheArray) {
  VectorField bad = kField;
  bad.name = "u_lattice";
  bad.values.pop_back();
  try {
    StreamlineTracer tracer(bad, {});
    FAIL() << "accepted a field with a missing value";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'u_lattice'"), std::string::npos) << e.what();
  }
}

TEST(Seeding, LineAndGridSeedsArePlacedEvenly) {
  const auto line = seedLine(Vec3(0, 0, 0), Vec3(4, 2, 0), 5);
  ASSERT_EQ(line.size(), 5u);
  EXPECT_EQ(line[1], Vec3(1, 0.5, 0));
  EXPECT_EQ(line[4], Vec3(4, 2, 0));
  EXPECT_EQ(seedLine(Vec3(0, 0, 0), Vec3(4, 2, 0), 1)[0], Vec3(2, 1, 0));

  const auto grid = seedGrid(kField.grid, 5, 2);
  ASSERT_EQ(grid.size(), 10u);
  EXPECT_EQ(grid[0], Vec3(1.0, 2.5, 0.0));   // cell centres of a 5 x 2 partition of [0, 10]^2
  EXPECT_EQ(grid[9], Vec3(9.0, 7.5, 0.0));
  EXPECT_THROW(seedGrid(kField.grid, 2, 2, 2), std::invalid_argument);
}

TEST(Seeding, GenerateSeedsChecksTheStrategyParameters) {
  SeedingParams s;
  s.strategy = fluidviz::streamlines::SeedStrategy::points;
  EXPECT_EQ(paramError([&] { generateSeeds(kField.grid, s); }).first, "points");
  s.strategy = fluidviz::streamlines::SeedStrategy::grid;
  s.grid_counts = {3, 2.5, 1};
  EXPECT_EQ(paramError([&] { generateSeeds(kField.grid, s); }).first, "grid_counts[1]");
  s.grid_counts = {3, 2, 2};
  EXPECT_EQ(paramError([&] { generateSeeds(kField.grid, s); }).first, "grid_counts[2]");
  s.grid_counts = {3, 2, 1};
  EXPECT_EQ(generateSeeds(kField.grid, s).size(), 6u);
  s.strategy = fluidviz::streamlines::SeedStrategy::line;
  s.line_count = 0;
  EXPECT_EQ(paramError([&] { generateSeeds(kField.grid, s); }).first, "line_count");

  s.line_count = 3;
  EXPECT_EQ(generateSeeds(kField.grid, s).size(), 3u);
  s.strategy = fluidviz::streamlines::SeedStrategy::points;
  s.points = {SeedPoint{{1.0, 2.0, 7.0}}};
  const auto lines = traceSeeded(kField, s, {});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].points[lines[0].seed_index], Vec3(1.0, 2.0, 0.0));  // z into the plane
}
