// PvdSeries: the .pvd on disk always lists exactly the snapshots added so far, with their times
// and paths relative to the .pvd's folder; it is parsed here with VTK's own XML parser.
#include "fieldviz/io/PvdSeries.h"

#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include "IoTestSupport.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlWriters.h"

using namespace fluidviz;
using fluidviz::testing::TestFolder;

namespace {

struct ParsedDataSet {
  double timestep;
  std::string file;
};

// The DataSet entries of a .pvd as an independent XML parser sees them.
std::vector<ParsedDataSet> parsePvd(const std::filesystem::path& pvd) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.c_str());
  if (!parser->Parse()) {
    ADD_FAILURE() << pvd << " does not parse";
    return {};
  }
  vtkXMLDataElement* root = parser->GetRootElement();
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (!collection) {
    ADD_FAILURE() << pvd << " has no <Collection>";
    return {};
  }
  std::vector<ParsedDataSet> out;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    EXPECT_STREQ(e->GetName(), "DataSet");
    double t = -1;
    EXPECT_TRUE(e->GetScalarAttribute("timestep", t));
    out.push_back({t, e->GetAttribute("file") ? e->GetAttribute("file") : ""});
  }
  return out;
}

FieldSet tinySet(double value) {
  FieldSet set;
  set.grid.dims = {2, 2, 1};
  set.add(ScalarField{"density", set.grid, std::vector<double>(4, value)});
  return set;
}

}  // namespace

TEST(PvdSeries, ThreeSnapshotsAreListedWithTimesAndRelativeFiles) {
  TestFolder dir;
  std::filesystem::create_directory(dir / "snapshots");
  PvdSeries series(dir / "flow.pvd");
  // 0.1 + 0.2 = 0.30000000000000004, the round-off of an accumulated time: listed as 0.3
  // (issue 16, defect 10), while the series keeps the exact value.
  const double times[3] = {0.0, 0.1, 0.1 + 0.2};
  for (int n = 0; n < 3; ++n) {
    const std::string name = "snapshots/flow_000" + std::to_string(n) + ".vti";
    writeVti(tinySet(n), dir / name);
    // Absolute and relative paths are both stored relative to the .pvd's folder.
    series.add(times[n], n == 1 ? dir / name : std::filesystem::path(name));
  }
  const std::vector<ParsedDataSet> entries = parsePvd(dir / "flow.pvd");
  ASSERT_EQ(entries.size(), 3u);
  for (int n = 0; n < 3; ++n) {
    EXPECT_EQ(entries[n].timestep, n == 2 ? 0.3 : times[n]) << "entry " << n;
    EXPECT_EQ(entries[n].file, "snapshots/flow_000" + std::to_string(n) + ".vti");
    EXPECT_TRUE(std::filesystem::exists(dir / entries[n].file));
  }
  EXPECT_EQ(series.entries().size(), 3u);
  EXPECT_EQ(series.entries()[2].time, times[2]);
  EXPECT_NE(fluidviz::testing::readText(dir / "flow.pvd").find("timestep=\"0.3\""), std::string::npos);
  EXPECT_EQ(dir.names(), (std::set<std::string>{"flow.pvd", "snapshots"}));  // no temporaries
}

TEST(PvdSeries, FileOnDiskListsOnlyTheSnapshotsAddedSoFar) {
  TestFolder dir;
  PvdSeries series(dir / "run.pvd");
  EXPECT_EQ(parsePvd(dir / "run.pvd").size(), 0u);  // an empty collection right away
  writeVti(tinySet(1), dir / "s0.vti");
  series.add(0.5, "s0.vti");
  EXPECT_EQ(parsePvd(dir / "run.pvd").size(), 1u);
  writeVti(tinySet(2), dir / "s1.vti");
  series.add(1.0, "s1.vti");
  // A run killed now, while writing s2.vti, leaves this .pvd: both complete snapshots, no more.
  const std::vector<ParsedDataSet> entries = parsePvd(dir / "run.pvd");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[1].file, "s1.vti");
  EXPECT_EQ(entries[1].timestep, 1.0);
}

TEST(PvdSeries, SnapshotMustExistBeforeItIsAdded) {
  TestFolder dir;
  PvdSeries series(dir / "run.pvd");
  try {
    series.add(0.0, "later.vti");
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "later.vti").string() + " does not exist"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(series.entries().empty());
  EXPECT_EQ(parsePvd(dir / "run.pvd").size(), 0u);
}

TEST(PvdSeries, TimesMustIncreaseAndBeFinite) {
  TestFolder dir;
  writeVti(tinySet(0), dir / "s.vti");
  PvdSeries series(dir / "run.pvd");
  series.add(1.0, "s.vti");
  EXPECT_THROW(series.add(1.0, "s.vti"), std::invalid_argument);
  EXPECT_THROW(series.add(0.5, "s.vti"), std::invalid_argument);
  EXPECT_THROW(series.add(std::nan(""), "s.vti"), std::invalid_argument);
  EXPECT_EQ(parsePvd(dir / "run.pvd").size(), 1u);
}

TEST(PvdSeries, FileNamesAreEscaped) {
  TestFolder dir;
  writeVti(tinySet(0), dir / "a&b \"q\".vti");
  PvdSeries series(dir / "run.pvd");
  series.add(0.0, "a&b \"q\".vti");
  const std::vector<ParsedDataSet> entries = parsePvd(dir / "run.pvd");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].file, "a&b \"q\".vti");
}

TEST(PvdSeries, MissingFolderThrowsAtConstructionAndLeavesNothing) {
  TestFolder dir;
  const auto pvd = dir / "absent" / "run.pvd";
  try {
    PvdSeries series(pvd);
    FAIL() << "expected FileError";
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), pvd);
    EXPECT_NE(std::string(e.what()).find("does not exist (No such file or directory)"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(dir.names().empty());
}
