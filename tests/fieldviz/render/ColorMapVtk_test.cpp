// The vtkLookupTable adapter reproduces the colour map.
#include "fieldviz/render/ColorMapVtk.h"

#include <gtest/gtest.h>
#include <vtkLookupTable.h>

#include <cmath>
#include <limits>

namespace fluidviz {
namespace {

// vtkLookupTable stores 8-bit colours, so each entry is the map's colour rounded: <= 0.5/255.
constexpr double kRounding = 0.5 / 255 + 1e-9;

TEST(ColorMapVtk, TableEntriesAreTheMapSampledEvenlyAndSpanTheRange) {
  const ColorMap& viridis = ColorMap::byName("viridis");
  auto table = makeLookupTable(viridis, -2.0, 6.0);
  ASSERT_EQ(table->GetNumberOfTableValues(), 256);
  EXPECT_DOUBLE_EQ(table->GetRange()[0], -2.0);
  EXPECT_DOUBLE_EQ(table->GetRange()[1], 6.0);
  for (int i : {0, 17, 128, 255}) {
    double rgba[4];
    table->GetTableValue(i, rgba);
    const ColorMap::Color expected = viridis.map(i / 255.0);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(rgba[k], expected[k], kRounding) << "entry " << i;
  }
  // Mapping a value: the end values give the end colours, the middle value the middle colour
  // within rounding plus the table's quantisation (half an entry: < 1/255 for viridis).
  double rgb[3];
  table->GetColor(-2.0, rgb);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(rgb[k], viridis.map(0.0)[k], kRounding);
  table->GetColor(6.0, rgb);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(rgb[k], viridis.map(1.0)[k], kRounding);
  table->GetColor(2.0, rgb);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(rgb[k], viridis.map(0.5)[k], 1.0 / 255 + kRounding);
  table->GetColor(std::numeric_limits<double>::quiet_NaN(), rgb);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(rgb[k], 0.5, kRounding);
}

TEST(ColorMapVtk, RejectsEmptyOrNonFiniteRangesAndBadSizes) {
  const ColorMap& gray = ColorMap::byName("grayscale");
  EXPECT_THROW(makeLookupTable(gray, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(makeLookupTable(gray, 0.0, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  EXPECT_THROW(makeLookupTable(gray, 0.0, 1.0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace fluidviz
