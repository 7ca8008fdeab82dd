#include "fieldviz/core/TextTemplate.h"

#include <gtest/gtest.h>

#include <map>

namespace fluidviz {
namespace {

PlaceholderLookup mapLookup(std::map<std::string, std::string> values) {
  return [values](std::string_view name) -> std::optional<std::string> {
    const auto it = values.find(std::string(name));
    if (it == values.end()) return std::nullopt;
    return it->second;
  };
}

TEST(TextTemplate, ReplacesEveryPlaceholderAndKeepsTheRest) {
  EXPECT_EQ(expandPlaceholders("{name} Re {reynolds}, t = {time} s ({name})",
                               mapLookup({{"name", "cavity"}, {"reynolds", "1000"}, {"time", "2.5"}})),
            "cavity Re 1000, t = 2.5 s (cavity)");
  EXPECT_EQ(expandPlaceholders("no placeholder", mapLookup({})), "no placeholder");
  EXPECT_EQ(expandPlaceholders("", mapLookup({})), "");
}

TEST(TextTemplate, DoubledBracesAreLiteral) {
  EXPECT_EQ(expandPlaceholders("{{x}} = {x}", mapLookup({{"x", "1"}})), "{x} = 1");
  EXPECT_EQ(placeholderNames("{{a}} {b} {c}{b}"), (std::vector<std::string>{"b", "c", "b"}));
}

TEST(TextTemplate, UnknownPlaceholderIsNamed) {
  try {
    expandPlaceholders("t = {tme} s", mapLookup({{"time", "1"}}));
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown placeholder {tme}");
  }
}

TEST(TextTemplate, MalformedBracesAreRefusedWithTheirPosition) {
  for (const char* bad : {"t = {time s", "a } b", "{}", "{a{b}"})
    EXPECT_THROW(placeholderNames(bad), std::invalid_argument) << bad;
  try {
    placeholderNames("ab {c");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("character 4"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fluidviz
