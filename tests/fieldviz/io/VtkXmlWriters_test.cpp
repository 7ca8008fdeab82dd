// Writers: the files carry what ParaView expects, .vtp round trips, and every failure throws
// FileError naming the path and the reason while leaving no file (and no temporary) behind.
#include <unistd.h>

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "IoTestSupport.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"

using namespace fluidviz;
using fluidviz::testing::readText;
using fluidviz::testing::TestFolder;
using fluidviz::testing::VtkOutputCounter;

namespace {

using fluidviz::testing::contains;

template <class F>
std::string fileErrorMessage(F&& f) {
  try {
    f();
  } catch (const FileError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no FileError thrown";
  return {};
}

FieldSet smallSet() {
  FieldSet set;
  set.grid.dims = {4, 3, 1};
  set.grid.spacing = {0.5, 0.5, 1.0};
  VectorField v{"velocity", set.grid, {}};
  ScalarField d{"density", set.grid, {}};
  for (std::size_t n = 0; n < 12; ++n) {
    v.values.push_back(Vec3(0.01 * n, -0.02 * n, 0.0));
    d.values.push_back(1.0 + 1e-3 * n);
  }
  set.add(v);
  set.add(d);
  return set;
}

// Three particles joined by one polyline, with a speed per particle.
vtkSmartPointer<vtkPolyData> streamline() {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(0.1, 0.2, 0.0);
  points->InsertNextPoint(1.0 / 3.0, 0.25, 0.0);
  points->InsertNextPoint(0.5, 1e-9, 2.0);
  poly->SetPoints(points);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[3] = {0, 1, 2};
  lines->InsertNextCell(3, ids);
  poly->SetLines(lines);
  vtkNew<vtkDoubleArray> speed;
  speed->SetName("speed");
  for (double s : {1.5, 2.0 / 3.0, -0.0}) speed->InsertNextValue(s);
  poly->GetPointData()->AddArray(speed);
  return poly;
}

class Writers : public ::testing::Test {
 protected:
  TestFolder dir;
  VtkOutputCounter vtkOutput;
  void TearDown() override { EXPECT_EQ(vtkOutput.count(), 0) << "VTK printed: " << vtkOutput.last(); }
};

}  // namespace

TEST_F(Writers, VtiDeclaresTheLayoutParaViewReads) {
  writeVti(smallSet(), dir / "flow.vti");
  const std::string text = readText(dir / "flow.vti");
  EXPECT_TRUE(contains(text, "<VTKFile type=\"ImageData\""));
  EXPECT_TRUE(contains(text, "header_type=\"UInt64\""));
  EXPECT_TRUE(contains(text, "compressor=\"vtkZLibDataCompressor\""));
  EXPECT_TRUE(contains(text, "WholeExtent=\"0 3 0 2 0 0\""));
  EXPECT_TRUE(contains(text, "type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\""));
  EXPECT_TRUE(contains(text, "type=\"Float64\" Name=\"density\""));
  EXPECT_TRUE(contains(text, "<AppendedData encoding=\"raw\">"));
}

TEST_F(Writers, NoTemporaryFilesAreLeftAfterSuccessfulWrites) {
  writeVti(smallSet(), dir / "a.vti");
  writeVti(smallSet(), dir / "a.vti");  // overwrite
  writeVtp(streamline(), dir / "b.vtp");
  writeTextOutput(dir / "c.txt", "text");
  EXPECT_EQ(dir.names(), (std::set<std::string>{"a.vti", "b.vtp", "c.txt"}));
}

TEST_F(Writers, VtpRoundTripKeepsPointsLinesAndArrays) {
  vtkSmartPointer<vtkPolyData> written = streamline();
  writeVtp(written, dir / "line.vtp");
  vtkSmartPointer<vtkPolyData> read = readVtp(dir / "line.vtp");
  ASSERT_EQ(read->GetNumberOfPoints(), 3);
  ASSERT_EQ(read->GetNumberOfLines(), 1);
  for (vtkIdType p = 0; p < 3; ++p)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(read->GetPoint(p)[c], written->GetPoint(p)[c]) << "point " << p << " axis " << c;
  vtkDataArray* speed = read->GetPointData()->GetArray("speed");
  ASSERT_NE(speed, nullptr);
  EXPECT_EQ(speed->GetComponent(1, 0), 2.0 / 3.0);
  EXPECT_TRUE(std::signbit(speed->GetComponent(2, 0)));
}

TEST_F(Writers, MissingFolderThrowsNamingPathAndReasonAndLeavesNothing) {
  const auto target = dir / "no_such_folder" / "flow.vti";
  const std::string message = fileErrorMessage([&] { writeVti(smallSet(), target); });
  EXPECT_EQ(message, "cannot write " + target.string() + ": folder '" + (dir / "no_such_folder").string() +
                         "' does not exist (No such file or directory)");
  EXPECT_TRUE(dir.names().empty());
  const auto vtp = dir / "no_such_folder" / "line.vtp";
  EXPECT_TRUE(contains(fileErrorMessage([&] { writeVtp(streamline(), vtp); }), "cannot write " + vtp.string()));
  EXPECT_TRUE(dir.names().empty());
}

TEST_F(Writers, FileInPlaceOfTheFolderThrows) {
  fluidviz::testing::writeText(dir / "plain.txt", "x");
  const auto target = dir / "plain.txt" / "flow.vti";
  EXPECT_TRUE(contains(fileErrorMessage([&] { writeVti(smallSet(), target); }),
                       "'" + (dir / "plain.txt").string() + "' is not a folder"));
  EXPECT_EQ(dir.names(), (std::set<std::string>{"plain.txt"}));
}

TEST_F(Writers, FolderInPlaceOfTheFileThrows) {
  std::filesystem::create_directory(dir / "flow.vti");
  EXPECT_TRUE(contains(fileErrorMessage([&] { writeVti(smallSet(), dir / "flow.vti"); }),
                       "a folder of that name exists"));
  EXPECT_EQ(dir.names(), (std::set<std::string>{"flow.vti"}));
}

TEST_F(Writers, ReadOnlyFolderThrowsWithTheOsReason) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write into read-only folders";
  std::filesystem::create_directory(dir / "locked");
  std::filesystem::permissions(dir / "locked", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  const std::string message = fileErrorMessage([&] { writeVti(smallSet(), dir / "locked" / "f.vti"); });
  std::filesystem::permissions(dir / "locked", std::filesystem::perms::owner_all);
  EXPECT_TRUE(contains(message, "is not writable (Permission denied)"));
  EXPECT_TRUE(std::filesystem::is_empty(dir / "locked"));
}

TEST_F(Writers, VtkWriterFailureBecomesFileError) {
  // A name past the file system's 255-byte limit: the folder checks pass, VTK's open fails.
  const auto target = dir / (std::string(300, 'n') + ".vti");
  const std::string message = fileErrorMessage([&] { writeVti(smallSet(), target); });
  EXPECT_TRUE(contains(message, "cannot write " + target.string() + ": ")) << message;
  EXPECT_TRUE(contains(message, "File name too long")) << message;
  EXPECT_TRUE(dir.names().empty());
}

TEST_F(Writers, FailedWriteLeavesThePreviousFileIntactAndNoTemporary) {
  writeTextOutput(dir / "report.txt", "complete old report");
  const std::string message = fileErrorMessage([&] {
    writeOutputAtomically(dir / "report.txt", [](const std::filesystem::path& tmp) {
      fluidviz::testing::writeText(tmp, "half a new rep");
      throw std::runtime_error("disk full");
    });
  });
  EXPECT_EQ(message, "cannot write " + (dir / "report.txt").string() + ": disk full");
  EXPECT_EQ(readText(dir / "report.txt"), "complete old report");
  EXPECT_EQ(dir.names(), (std::set<std::string>{"report.txt"}));
}

TEST_F(Writers, InconsistentFieldSetIsRejectedBeforeAnyFileIsMade) {
  FieldSet set = smallSet();
  set.scalars[0].values.pop_back();
  EXPECT_THROW(writeVti(set, dir / "bad.vti"), std::invalid_argument);
  EXPECT_TRUE(dir.names().empty());
}
