// Every scene-validation rule of the parameter visitors, each with its message.
#include "fieldviz/scene/SceneFile.h"
#include "fieldviz/core/ParamRanges.h"

#include <gtest/gtest.h>

using namespace fluidviz;
using namespace fluidviz::scene;

namespace {
struct Wheel {
  std::array<double, 2> center{0, 0};
  double radius = 1.0;
  template <class V>
  static void describe(V& v) {
    v(&Wheel::center, {.key = "center", .unit = "m", .description = "centre", .required = true});
    v(&Wheel::radius, {.key = "radius", .unit = "m", .description = "radius", .min = 0,
                       .minExclusive = true});
  }
};
struct Inner {
  int count = 3;
  template <class V>
  static void describe(V& v) {
    v(&Inner::count, {.key = "count", .description = "how many", .min = 1, .max = 10});
  }
};
struct Demo {
  int resolution = 64;
  double speed = 0.05;
  bool verbose = false;
  std::string kind = "bgk";
  std::optional<double> reynolds;
  Inner inner;
  std::vector<Wheel> wheels;
  template <class V>
  static void describe(V& v) {
    v(&Demo::resolution, {.key = "resolution", .unit = "nodes", .description = "nodes along x",
                          .min = 8, .max = 8192});
    v(&Demo::speed, {.key = "speed", .unit = "1", .description = "lattice speed", .min = 0,
                     .max = 0.4, .minExclusive = true});
    v(&Demo::verbose, {.key = "verbose", .description = "talk"});
    v(&Demo::kind, {.key = "kind", .description = "collision", .choices = {"bgk", "trt"}});
    v(&Demo::reynolds, {.key = "reynolds", .description = "Re", .min = 0, .minExclusive = true});
    v(&Demo::inner, {.key = "inner", .description = "nested"});
    v(&Demo::wheels, {.key = "wheels", .description = "rollers"});
  }
};

// Returns the SceneError message for a scene text, or "" if it was accepted.
std::string errorFor(const std::string& text) {
  try {
    readScene<Demo>(parseSceneText(text, "scene.json"), "scene.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(ParamVisitors, ReadsValuesAndKeepsDefaults) {
  Demo d = readScene<Demo>(parseSceneText(R"({"resolution": 128, "kind": "trt",
      "wheels": [{"center": [0.5, 0.25], "radius": 0.1}] // comment allowed
      })", "s.json"), "s.json");
  EXPECT_EQ(d.resolution, 128);
  EXPECT_EQ(d.kind, "trt");
  EXPECT_DOUBLE_EQ(d.speed, 0.05);
  EXPECT_FALSE(d.reynolds.has_value());
  ASSERT_EQ(d.wheels.size(), 1u);
  EXPECT_DOUBLE_EQ(d.wheels[0].center[1], 0.25);
  EXPECT_DOUBLE_EQ(d.wheels[0].radius, 0.1);
  EXPECT_EQ(d.inner.count, 3);
}

TEST(ParamVisitors, OutOfRangeNamesFileKeyAndRange) {
  EXPECT_EQ(errorFor(R"({"resolution": 4})"),
            "scene.json: key 'resolution' is 4 nodes, outside the allowed range [8, 8192] "
            "(nodes along x)");
  EXPECT_EQ(errorFor(R"({"speed": 0.5})"),
            "scene.json: key 'speed' is 0.5 1, outside the allowed range (0, 0.4] (lattice speed)");
  EXPECT_NE(errorFor(R"({"speed": 0})").find("(0, 0.4]"), std::string::npos);
  EXPECT_NE(errorFor(R"({"inner": {"count": 11}})").find("key 'inner.count' is 11"),
            std::string::npos);
}

TEST(ParamVisitors, UnknownKeyIsAnErrorListingAllowedKeys) {
  EXPECT_EQ(errorFor(R"({"resolutoin": 64})"),
            "scene.json: key 'resolutoin' is not a known key; allowed keys here: resolution, "
            "speed, verbose, kind, reynolds, inner, wheels");
  EXPECT_NE(errorFor(R"({"wheels": [{"center": [0,0], "radius": 1, "spin": 2}]})")
                .find("key 'wheels[0].spin' is not a known key"),
            std::string::npos);
}

TEST(ParamVisitors, WrongTypesAreNamed) {
  EXPECT_EQ(errorFor(R"({"resolution": 64.5})"),
            "scene.json: key 'resolution' must be a whole number, got the number 64.5 (allowed "
            "[8, 8192])");
  EXPECT_EQ(errorFor(R"({"resolution": "64"})"),
            "scene.json: key 'resolution' must be a whole number, got the string \"64\" (allowed "
            "[8, 8192])");
  EXPECT_EQ(errorFor(R"({"verbose": 1})"),
            "scene.json: key 'verbose' must be true or false, got the number 1");
  EXPECT_EQ(errorFor(R"({"wheels": [{"center": [1], "radius": 1}]})"),
            "scene.json: key 'wheels[0].center' must be a list of 2 numbers, got a list");
  EXPECT_EQ(errorFor(R"({"inner": 3})"), "scene.json: key 'inner' must be an object {...}, got the number 3");
  EXPECT_EQ(errorFor(R"([1, 2])"), "scene.json: must be an object {...}, got a list");
}

TEST(ParamVisitors, ChoicesAndRequiredKeys) {
  EXPECT_EQ(errorFor(R"({"kind": "mrt"})"),
            "scene.json: key 'kind' is \"mrt\", allowed one of {bgk, trt}");
  EXPECT_EQ(errorFor(R"({"wheels": [{"radius": 1}]})"),
            "scene.json: key 'wheels[0].center' is required: centre (m), allowed any");
  EXPECT_NE(errorFor(R"({"wheels": [{"center": [0, 0], "radius": 0}]})")
                .find("key 'wheels[0].radius' is 0 m, outside the allowed range > 0 (radius)"),
            std::string::npos)
      << errorFor(R"({"wheels": [{"center": [0, 0], "radius": 0}]})");
}

TEST(ParamVisitors, SyntaxErrorsGiveLineAndColumn) {
  const std::string e = errorFor("{\n  \"resolution\": 64,\n  \"speed\": ,\n}");
  EXPECT_NE(e.find("scene.json: is not valid JSON at line 3, column 12"), std::string::npos) << e;
}

TEST(ParamVisitors, DeepNestingIsRefusedBeforeParsingFurther) {
  std::string deep(1000, '[');
  deep += std::string(1000, ']');
  EXPECT_NE(errorFor(deep).find("nesting deeper than 64 levels"), std::string::npos);
}

TEST(SceneOverrides, SetReplacesNestedValuesAndListElements) {
  json j = parseSceneText(R"({"wheels": [{"center": [0, 0], "radius": 1}]})", "s.json");
  applyOverride(j, "resolution=256", "s.json");
  applyOverride(j, "kind=trt", "s.json");
  applyOverride(j, "wheels.0.radius=0.25", "s.json");
  applyOverride(j, "wheels[0].center=[1,2]", "s.json");
  applyOverride(j, "inner.count=7", "s.json");
  Demo d = readScene<Demo>(j, "s.json");
  EXPECT_EQ(d.resolution, 256);
  EXPECT_EQ(d.kind, "trt");
  EXPECT_DOUBLE_EQ(d.wheels[0].radius, 0.25);
  EXPECT_DOUBLE_EQ(d.wheels[0].center[1], 2.0);
  EXPECT_EQ(d.inner.count, 7);
}

TEST(SceneOverrides, BadOverridesAreErrors) {
  json j = parseSceneText(R"({"wheels": []})", "s.json");
  EXPECT_THROW(applyOverride(j, "resolution", "s.json"), SceneError);
  try {
    applyOverride(j, "wheels.3.radius=1", "s.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "s.json: key 'wheels.3.radius' --set: '3' is not an index of a list of 0 elements");
  }
  // An override of an unknown key is caught by validation like any other unknown key.
  applyOverride(j, "spede=0.1", "s.json");
  EXPECT_THROW(readScene<Demo>(j, "s.json"), SceneError);
}

TEST(SceneFile, MissingFileIsNamed) {
  try {
    readSceneFile("/nonexistent/scene.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/scene.json: does not exist");
  }
}

TEST(ParamDocs, TableListsEveryKeyWithDefaultAndRange) {
  std::vector<DocRow> rows;
  documentParams<Demo>(rows, "");
  const std::string md = markdownTable(rows);
  EXPECT_NE(md.find("| `resolution` | integer | nodes | `64` | [8, 8192] | nodes along x |"),
            std::string::npos) << md;
  EXPECT_NE(md.find("| `wheels[].radius` | number | m | `1.0` | > 0 | radius |"),
            std::string::npos) << md;
  EXPECT_NE(md.find("| `inner.count` |"), std::string::npos);
  EXPECT_NE(md.find("| `kind` | string |  | `\"bgk\"` | one of {bgk, trt} |"), std::string::npos);
}

TEST(ParamWriter, RoundTripThroughJson) {
  Demo d;
  d.resolution = 100;
  d.reynolds = 50.0;
  d.wheels.push_back({{1, 2}, 0.5});
  const Demo back = readScene<Demo>(writeParams(d), "x");
  EXPECT_EQ(back.resolution, 100);
  EXPECT_DOUBLE_EQ(*back.reynolds, 50.0);
  EXPECT_DOUBLE_EQ(back.wheels[0].radius, 0.5);
}

namespace {
// A list of points (lbm.sketch.strokes[].points): each point a list of 2 numbers in range.
struct PointListDemo {
  std::vector<std::array<double, 2>> points;
  template <class V>
  static void describe(V& v) {
    v(&PointListDemo::points,
      {.key = "points", .unit = "m", .description = "the points", .min = 0, .max = 10});
  }
};

std::string pointListError(const std::string& text) {
  try {
    readScene<PointListDemo>(parseSceneText(text, "scene.json"), "scene.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(ParamVisitors, PointListsReadWriteDocumentAndCheckEveryNumber) {
  const PointListDemo d = readScene<PointListDemo>(
      parseSceneText(R"({"points": [[1, 2], [3.5, 4]]})", "s.json"), "s.json");
  ASSERT_EQ(d.points.size(), 2u);
  EXPECT_EQ(d.points[1][0], 3.5);
  EXPECT_EQ(writeParams(d).dump(), R"({"points":[[1.0,2.0],[3.5,4.0]]})");
  EXPECT_EQ(pointListError(R"({"points": 3})"),
            "scene.json: key 'points' must be a list of points [2 numbers], got the number 3 "
            "(allowed [0, 10])");
  EXPECT_EQ(pointListError(R"({"points": [[1, 2], [3]]})"),
            "scene.json: key 'points[1]' must be a list of 2 numbers, got a list (allowed [0, 10])");
  EXPECT_NE(pointListError(R"({"points": [[1, 20]]})")
                .find("key 'points[0][1]' is 20 m, outside the allowed range [0, 10]"),
            std::string::npos)
      << pointListError(R"({"points": [[1, 20]]})");
  std::vector<DocRow> rows;
  documentParams<PointListDemo>(rows, "");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].type, "list of [2 numbers]");
  EXPECT_EQ(rows[0].allowed, "[0, 10]");
  PointListDemo set;
  set.points = {{1, 2}, {-1, 2}};
  try {
    params::checkRanges(set);
    ADD_FAILURE() << "a point outside the range passed";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.key(), "points[1][0]");
  }
}
