// Property values -> parameter structs (PropertyValues.h): the scene reader's own checks, and
// errors that name the ParaView property and the scene key.
#include "paraview/properties/PropertyValues.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "filters/lic/LicParams.h"
#include "filters/topology/TopologyParams.h"
#include "paraview/properties/LicProxyParams.h"
#include "paraview/properties/StreamlineProxyParams.h"

using namespace fluidviz;
namespace pv = fluidviz::paraview;

namespace {

pv::PropertyValues licValues() { return pv::PropertyValues(scene::paramTable<lic::LicParams>()); }

TEST(PropertyValues, NothingSetGivesTheDeclaredDefaults) {
  const lic::LicParams p = licValues().read<lic::LicParams>();
  const lic::LicParams defaults;
  EXPECT_EQ(scene::writeParams(p), scene::writeParams(defaults));
}

TEST(PropertyValues, EachKindReachesItsMember) {
  pv::PropertyValues v = licValues();
  v.setNumber("length", 31.5);
  v.setInteger("noise_seed", 7);
  v.setChoice("kernel", 1);
  v.setFlag("contrast", 0);
  v.setNumber("slice_height", 0.25);
  v.setGiven("slice_height", true);
  const lic::LicParams p = v.read<lic::LicParams>();
  EXPECT_EQ(p.length, 31.5);
  EXPECT_EQ(p.noise_seed, 7);
  EXPECT_EQ(p.kernel, lic::KernelShape::hann);
  EXPECT_FALSE(p.contrast);
  ASSERT_TRUE(p.slice_height.has_value());
  EXPECT_EQ(*p.slice_height, 0.25);
}

TEST(PropertyValues, AnOptionalNumberCountsOnlyWhileGiven) {
  pv::PropertyValues v = licValues();
  v.setGiven("slice_height", true);
  v.setNumber("slice_height", 0.5);  // value after the flag
  EXPECT_EQ(v.read<lic::LicParams>().slice_height, 0.5);
  v.setGiven("slice_height", false);
  EXPECT_FALSE(v.read<lic::LicParams>().slice_height.has_value());
}

TEST(PropertyValues, NestedKeysReachTheNestedStruct) {
  pv::PropertyValues v(scene::paramTable<topology::TopologyParams>());
  v.setNumber("separatrix_integration.step", 0.125);
  v.setChoice("separatrix_integration.integrator", 0);
  const topology::TopologyParams p = v.read<topology::TopologyParams>();
  EXPECT_EQ(p.separatrix_integration.step, 0.125);
  EXPECT_EQ(p.separatrix_integration.integrator, streamlines::Integrator::rk2);  // entry 0
}

// An array property (SetNumbers3Parameter) fills the std::array; each element is range-checked
// as the scene key is, and a count other than the declaration's is an error naming the key.
TEST(PropertyValues, ArraysOfNumbersReachTheArrayWithTheirRangeChecked) {
  pv::PropertyValues v(scene::paramTable<pv::StreamlineProxyParams>());
  v.setNumbers("seeding.grid_counts", {4, 6, 1});
  v.setNumbers("seeding.line_start", {0.25, -1.5, 0});
  const pv::StreamlineProxyParams p = v.read<pv::StreamlineProxyParams>();
  EXPECT_EQ(p.seeding.grid_counts, (std::array<double, 3>{4, 6, 1}));
  EXPECT_EQ(p.seeding.line_start, (std::array<double, 3>{0.25, -1.5, 0}));
  v.setNumbers("seeding.grid_counts", {0, 6, 1});  // min 1
  std::string error;
  pv::StreamlineProxyParams q;
  EXPECT_FALSE(v.tryRead(q, error));
  EXPECT_NE(error.find("property SeedingGridCounts[0] (scene key seeding.grid_counts[0]) is 0, "
                       "outside the allowed range [1, 10000]"),
            std::string::npos) << error;
  pv::PropertyValues w(scene::paramTable<pv::StreamlineProxyParams>());
  w.setNumbers("seeding.grid_counts", {4, 6});
  EXPECT_FALSE(w.tryRead(q, error));
  EXPECT_NE(error.find("has 3 numbers, got 2"), std::string::npos) << error;
}

TEST(PropertyValues, OutOfRangeNamesThePropertyTheKeyAndTheRange) {
  pv::PropertyValues v = licValues();
  v.setNumber("length", 5000);
  std::string error;
  lic::LicParams p;
  ASSERT_FALSE(v.tryRead(p, error));
  EXPECT_NE(error.find("property Length (scene key length)"), std::string::npos) << error;
  EXPECT_NE(error.find("[1, 1000]"), std::string::npos) << error;
  EXPECT_NE(error.find("5000"), std::string::npos) << error;
}

TEST(PropertyValues, NanIsRefusedNotTakenForUnset) {
  pv::PropertyValues v = licValues();
  v.setNumber("step", std::nan(""));
  std::string error;
  lic::LicParams p;
  ASSERT_FALSE(v.tryRead(p, error));
  EXPECT_NE(error.find("property Step (scene key step)"), std::string::npos) << error;
}

TEST(PropertyValues, UnknownKeyWrongKindAndChoiceOutOfRangeAreErrors) {
  const std::vector<std::pair<std::function<void(pv::PropertyValues&)>, std::string>> cases = {
      {[](pv::PropertyValues& v) { v.setNumber("lenght", 1); }, "is not a parameter"},
      {[](pv::PropertyValues& v) { v.setInteger("length", 1); }, "wrong kind of property"},
      {[](pv::PropertyValues& v) { v.setChoice("kernel", 2); },
       "choice number 2 does not exist; allowed: 0 to 1 (box, hann)"}};
  for (const auto& [set, words] : cases) {
    pv::PropertyValues v = licValues();
    set(v);
    std::string error;
    lic::LicParams p;
    ASSERT_FALSE(v.tryRead(p, error)) << words;
    EXPECT_NE(error.find(words), std::string::npos) << error;
  }
}

// The LIC proxy's keys: the texture's, the blend's and three of the picture's, each once (the
// picture's width and height would shadow the texture's), defaults as declared, except Color By
// (none: the proxy's output is the texture unless a scalar is named).
TEST(LicProxyParams, TextureBlendAndColourKeysEachOnce) {
  std::vector<std::string> keys;
  for (const scene::ParamRow& row : scene::paramTable<pv::LicProxyParams>()) keys.push_back(row.key);
  std::vector<std::string> expected;
  for (const scene::ParamRow& row : scene::paramTable<lic::LicParams>()) expected.push_back(row.key);
  for (const char* k : {"color_by", "lic_weight", "mask_color", "colormap", "range_min",
                        "range_max"})
    expected.push_back(k);
  EXPECT_EQ(keys, expected);
  pv::PropertyValues v(scene::paramTable<pv::LicProxyParams>());
  v.setText("color_by", "density");
  v.setNumber("lic_weight", 0.25);
  v.setText("colormap", "inferno");
  v.setNumber("range_max", 2.5);
  v.setGiven("range_max", true);
  const auto p = v.read<pv::LicProxyParams>();
  EXPECT_EQ(p.color_by, "density");
  EXPECT_EQ(p.lic_weight, 0.25);
  EXPECT_EQ(p.colormap, "inferno");
  EXPECT_EQ(p.range_max, 2.5);
  EXPECT_FALSE(p.range_min.has_value());
  EXPECT_EQ(pv::LicProxyParams{}.color_by, "");
  EXPECT_EQ(static_cast<const lic::LicParams&>(pv::LicProxyParams{}).width, lic::LicParams{}.width);
}

}  // namespace
