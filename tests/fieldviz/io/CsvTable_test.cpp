// Numeric CSV tables: reading (comments, header, columns by name with or without their unit),
// the errors a user's file gets (file, line number, the columns there are), and writing with
// the shortest round-trip numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "fieldviz/io/CsvTable.h"
#include "fieldviz/io/FileError.h"

namespace fluidviz {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseCsv(text, "t.csv");
  } catch (const FileError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CsvTable, ReadsCommentsHeaderAndColumns) {
  const CsvTable t = parseCsv("# source\n\ny (m), u (m/s)\n0.5,-0.2\n 1e-3 , 4\n", "t.csv");
  ASSERT_EQ(t.comments.size(), 1u);
  EXPECT_EQ(t.comments[0], "source");
  ASSERT_EQ(t.rowCount(), 2u);
  EXPECT_EQ(t.find("y (m)"), 0);
  EXPECT_EQ(t.find("u"), 1);  // the name before the unit
  EXPECT_EQ(t.find("v"), -1);
  EXPECT_DOUBLE_EQ(t.column("y", "t.csv")[1], 1e-3);
  EXPECT_DOUBLE_EQ(t.column("u", "t.csv")[0], -0.2);
}

TEST(CsvTable, ErrorsNameLineAndColumns) {
  EXPECT_EQ(errorOf("x,y\n1,2\n3,abc\n"), "t.csv line 3: 'abc' in column 'y' is not a finite number (or nan)");
  EXPECT_EQ(errorOf("x,y\n1,2,3\n"), "t.csv line 2: 3 fields, the header names 2 columns");
  EXPECT_EQ(errorOf("x,y\n1,inf\n"), "t.csv line 2: 'inf' in column 'y' is not a finite number (or nan)");
  EXPECT_EQ(errorOf("x,y\n1,\n"), "t.csv line 2: '' in column 'y' is not a finite number (or nan)");
  EXPECT_EQ(errorOf("# only comments\n"), "t.csv has no header line naming its columns");
  EXPECT_EQ(errorOf("x,,y\n"), "t.csv line 1: the header has an empty column name");
  EXPECT_TRUE(std::isnan(parseCsv("x,y\n1,nan\n", "t.csv").columns[1][0]));  // no value
  const CsvTable t = parseCsv("x,y\n", "t.csv");
  try {
    t.column("z", "t.csv");
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_STREQ(e.what(), "t.csv has no column 'z'; its columns: x, y");
  }
  EXPECT_THROW(readCsv("/nonexistent/t.csv"), FileError);
}

TEST(CsvTable, WritesShortestRoundTripNumbers) {
  EXPECT_EQ(formatShortest(5.0), "5");
  EXPECT_EQ(formatShortest(0.1), "0.1");
  EXPECT_EQ(formatShortest(1e-7), "1e-07");
  EXPECT_EQ(formatShortest(std::nan("")), "nan");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::stod(formatShortest(third)), third);
  CsvTable t;
  t.comments = {"made by a test"};
  t.names = {"t (s)", "E (J)"};
  t.columns = {{0.0, 0.5}, {1.0, third}};
  const std::string text = formatCsv(t);
  EXPECT_EQ(text, "# made by a test\nt (s),E (J)\n0,1\n0.5," + formatShortest(third) + "\n");
  EXPECT_EQ(parseCsv(text, "t.csv").column("E", "t.csv")[1], third);  // reads back exactly
}

}  // namespace
}  // namespace fluidviz

namespace fluidviz {
namespace {

// The fuzz target's seeds (tests/fuzz/corpus/csv_table, fuzz_csv_table.cpp) are valid tables:
// replayed here in the Release build as well.
TEST(CsvTable, FuzzSeedsParse) {
  const std::filesystem::path seeds =
      std::filesystem::path(FLUIDVIZ_SOURCE_DIR) / "tests/fuzz/corpus/csv_table";
  int count = 0;
  for (const auto& e : std::filesystem::directory_iterator(seeds)) {
    const CsvTable t = readCsv(e.path());
    EXPECT_GE(t.names.size(), 2u) << e.path();
    EXPECT_GE(t.rowCount(), 2u) << e.path();
    ++count;
  }
  EXPECT_EQ(count, 3);
}

}  // namespace
}  // namespace fluidviz
