// The flat parameter table (ParamTable.h): one row per leaf key, nested structs as dotted keys
// with the defaults their parent gives them, kinds and declared info unchanged.
#include "fieldviz/scene/ParamTable.h"

#include <gtest/gtest.h>

using namespace fluidviz;
using namespace fluidviz::scene;

namespace {

enum class Shape { round, square };
constexpr std::array<Choice<Shape>, 2> paramChoices(Shape) {
  return {{{Shape::round, "round"}, {Shape::square, "square"}}};
}
struct TableInner {
  double gap = 1.0;
  template <class V>
  static void describe(V& v) {
    v(&TableInner::gap, {.key = "gap", .unit = "m", .description = "gap", .min = 0});
  }
};
struct Item {
  int n = 1;
  template <class V>
  static void describe(V& v) {
    v(&Item::n, {.key = "n", .description = "n"});
  }
};
struct Outer {
  bool on = true;
  int count = 3;
  double speed = 0.5;
  std::optional<double> height;
  std::string name = "a";
  Shape shape = Shape::square;
  TableInner inner{.gap = 2.5};  // the parent's default, not TableInner's own
  std::vector<Item> items;
  std::array<double, 3> corner{1.0, 2.0, 3.0};
  template <class V>
  static void describe(V& v) {
    v(&Outer::on, {.key = "on", .description = "on"});
    v(&Outer::count, {.key = "count", .description = "count", .min = 1, .max = 9});
    v(&Outer::speed, {.key = "speed", .unit = "m/s", .description = "speed"});
    v(&Outer::height, {.key = "height", .unit = "m", .description = "height"});
    v(&Outer::name, {.key = "name", .description = "name"});
    v(&Outer::shape, {.key = "shape", .description = "shape"});
    v(&Outer::inner, {.key = "inner", .description = "inner"});
    v(&Outer::items, {.key = "items", .description = "items"});
    v(&Outer::corner, {.key = "corner", .unit = "m", .description = "corner", .min = 0});
  }
};

TEST(ParamTable, OneRowPerLeafWithKindDefaultAndDeclaredInfo) {
  const std::vector<ParamRow> rows = paramTable<Outer>();
  ASSERT_EQ(rows.size(), 9u);
  const std::vector<std::pair<std::string, ParamKind>> expected = {
      {"on", ParamKind::flag},       {"count", ParamKind::integer},
      {"speed", ParamKind::number},  {"height", ParamKind::optional_number},
      {"name", ParamKind::text},     {"shape", ParamKind::choice},
      {"inner.gap", ParamKind::number}, {"items", ParamKind::list},
      {"corner", ParamKind::numbers}};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].key, expected[i].first);
    EXPECT_EQ(rows[i].kind, expected[i].second) << rows[i].key;
  }
  EXPECT_EQ(rows[1].info.max, 9);
  EXPECT_EQ(rows[2].info.unit, "m/s");
  EXPECT_TRUE(rows[3].defaultValue.is_null());
  EXPECT_EQ(rows[5].defaultValue, "square");
  EXPECT_EQ(rows[5].info.choices, (std::vector<std::string>{"round", "square"}));
  EXPECT_EQ(rows[6].defaultValue, 2.5);
  EXPECT_EQ(findParamRow(rows, "inner.gap"), &rows[6]);
  EXPECT_EQ(findParamRow(rows, "gap"), nullptr);
  EXPECT_EQ(rows[8].defaultValue, (json{1.0, 2.0, 3.0}));  // its size is the array's
  EXPECT_EQ(rows[8].info.min, 0);
}

}  // namespace
