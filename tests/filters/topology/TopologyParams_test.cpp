// Parameter validation: values outside the declared ranges are rejected with the key named.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "filters/topology/PlanarField.h"
#include "filters/topology/TopologyParams.h"
#include "filters/topology/VectorFieldTopology.h"
#include "tests/filters/topology/TopologyTestFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;

namespace {
std::string rejectedKey(const TopologyParams& p) {
  try {
    validateTopologyParams(p);
  } catch (const ParamError& e) {
    return e.key();
  }
  return "";
}

struct KeyCollector {
  std::set<std::string> keys;
  template <class M>
  void operator()(M, const ParamInfo& info) {
    EXPECT_FALSE(info.description.empty()) << info.key;
    keys.insert(info.key);
  }
};
}  // namespace

TEST(TopologyParams, DefaultsAreValid) { EXPECT_EQ(rejectedKey(TopologyParams{}), ""); }

TEST(TopologyParams, OutOfRangeValuesNameTheirKey) {
  TopologyParams p;
  p.cluster_radius = -1;
  EXPECT_EQ(rejectedKey(p), "cluster_radius");
  p = {};
  p.loop_radius = 0;  // exclusive minimum
  EXPECT_EQ(rejectedKey(p), "loop_radius");
  p = {};
  p.subdivision_depth = 21;
  EXPECT_EQ(rejectedKey(p), "subdivision_depth");
  p = {};
  p.det_threshold = 2;
  EXPECT_EQ(rejectedKey(p), "det_threshold");
  p = {};
  p.stream_function_solver = static_cast<StreamFunctionSolver>(7);
  EXPECT_EQ(rejectedKey(p), "stream_function_solver");
  p = {};
  p.separatrix_integration.integrator = static_cast<fluidviz::streamlines::Integrator>(7);
  EXPECT_EQ(rejectedKey(p), "separatrix_integration.integrator");
  p = {};
  p.separatrix_integration.integrator = fluidviz::streamlines::Integrator::rk45;
  p.separatrix_integration.min_step = 1.0;
  p.separatrix_integration.step = 0.5;  // combination rule of the integrator
  EXPECT_EQ(rejectedKey(p), "separatrix_integration.step");
  p = {};
  p.separating_surface.max_triangles = 0;
  EXPECT_EQ(rejectedKey(p), "separating_surface.max_triangles");
}

TEST(TopologyParams, EveryMemberIsDeclaredOnce) {
  KeyCollector c;
  TopologyParams::describe(c);
  EXPECT_EQ(c.keys.size(), 17u);  // one key per member, no duplicates
  EXPECT_TRUE(c.keys.count("cluster_radius"));
  EXPECT_TRUE(c.keys.count("separatrix_integration"));
  EXPECT_TRUE(c.keys.count("separating_surface"));
}

TEST(TopologyParams, FindCriticalPointsRejectsBadParamsAndFields) {
  const Grid g = topology::testing::squareGrid(5, 0, 1);
  const VectorField f = topology::testing::sampleField(g, [](double x, double y) { return Vec2(x, y); });
  TopologyParams p;
  p.centre_tolerance = -0.1;
  EXPECT_THROW(findCriticalPoints(f, p), ParamError);
  VectorField tooFew = f;
  tooFew.values.pop_back();
  EXPECT_THROW(findCriticalPoints(tooFew, {}), std::invalid_argument);
  const VectorField line = topology::testing::sampleField(
      [] {
        Grid g1;
        g1.dims = {5, 1, 1};
        return g1;
      }(),
      [](double x, double) { return Vec2(x, 0); });
  EXPECT_THROW(findCriticalPoints(line, {}), std::invalid_argument);
}
