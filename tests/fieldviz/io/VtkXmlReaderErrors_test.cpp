// Bad input raises FileError naming the file (and the array) and says what was expected;
// VTK itself prints nothing (its messages are caught and folded into the exception).
#include <cmath>

#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "IoTestSupport.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"

using namespace fluidviz;
using fluidviz::testing::contains;
using fluidviz::testing::readText;
using fluidviz::testing::TestFolder;
using fluidviz::testing::VtkOutputCounter;
using fluidviz::testing::writeText;

namespace {

template <class F>
FileError fileErrorOf(F&& f) {
  try {
    f();
  } catch (const FileError& e) {
    return e;
  }
  ADD_FAILURE() << "no FileError thrown";
  return FileError("", "");
}

FieldSet velocityAndDensity(int nx, int ny, int nz) {
  FieldSet set;
  set.grid.dims = {nx, ny, nz};
  // Varied values keep the compressed arrays large, so cutting the file in half cuts the data.
  VectorField velocity{"velocity", set.grid, {}};
  ScalarField density{"density", set.grid, {}};
  for (std::size_t n = 0; n < set.grid.nodeCount(); ++n) {
    velocity.values.push_back(Vec3(std::sin(0.37 * n), std::cos(1.3 * n), 1e-3 * n));
    density.values.push_back(1.0 + 0.01 * std::sin(0.11 * n));
  }
  set.add(velocity);
  set.add(density);
  return set;
}

// An ASCII .vti as a user might write by hand or by script.
std::string asciiVti(const std::string& wholeExtent, const std::string& spacing,
                     const std::string& pressureValues) {
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
         "  <ImageData WholeExtent=\"" + wholeExtent + "\" Origin=\"0 0 0\" Spacing=\"" + spacing + "\">\n"
         "    <Piece Extent=\"" + wholeExtent + "\">\n"
         "      <PointData Scalars=\"pressure\">\n"
         "        <DataArray type=\"Float32\" Name=\"pressure\" format=\"ascii\">" + pressureValues + "</DataArray>\n"
         "      </PointData>\n"
         "      <CellData/>\n"
         "    </Piece>\n"
         "  </ImageData>\n"
         "</VTKFile>\n";
}

class ReaderErrors : public ::testing::Test {
 protected:
  TestFolder dir;
  VtkOutputCounter vtkOutput;  // every test also checks VTK printed nothing
  void TearDown() override { EXPECT_EQ(vtkOutput.count(), 0) << "VTK printed: " << vtkOutput.last(); }
};

}  // namespace

TEST_F(ReaderErrors, MissingFile) {
  const auto path = dir / "nothing.vti";
  const FileError e = fileErrorOf([&] { readVti(path); });
  EXPECT_EQ(std::string(e.what()), "file " + path.string() + " does not exist");
  EXPECT_EQ(e.path(), path);
  EXPECT_TRUE(e.arrayName().empty());
}

TEST_F(ReaderErrors, FolderGivenAsFile) {
  const FileError e = fileErrorOf([&] { readVti(dir.path()); });
  EXPECT_TRUE(contains(e.what(), "is a folder"));
}

TEST_F(ReaderErrors, TextFileNamedVti) {
  const auto path = dir / "notes.vti";
  writeText(path, "velocity = 3 m/s\nthis is not VTK\n");
  const FileError e = fileErrorOf([&] { readVti(path); });
  EXPECT_TRUE(contains(e.what(), "file " + path.string() + " is not a VTK XML file"));
  EXPECT_TRUE(contains(e.what(), "<VTKFile type=\"ImageData\">"));
}

TEST_F(ReaderErrors, EmptyFileNamedVti) {
  const auto path = dir / "empty.vti";
  writeText(path, "");
  EXPECT_TRUE(contains(fileErrorOf([&] { readVti(path); }).what(), "is not a VTK XML file"));
}

TEST_F(ReaderErrors, PolyDataFileNamedVti) {
  const auto path = dir / "points.vti";
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  poly->SetPoints(points);
  writeVtp(poly, dir / "points.vtp");
  std::filesystem::rename(dir / "points.vtp", path);
  const FileError e = fileErrorOf([&] { readVti(path); });
  EXPECT_TRUE(contains(e.what(), "holds VTK XML PolyData, expected ImageData (.vti)"));
}

TEST_F(ReaderErrors, TruncatedFile) {
  const auto path = dir / "cut.vti";
  writeVti(velocityAndDensity(20, 20, 5), path);
  const std::string full = readText(path);
  ASSERT_LT(full.find("<AppendedData"), full.size() / 4) << "the cut should fall into the data";
  writeText(path, full.substr(0, full.size() / 2));
  const FileError e = fileErrorOf([&] { readVti(path); });
  EXPECT_TRUE(contains(e.what(), "file " + path.string() + " is corrupt or truncated"));
  EXPECT_TRUE(contains(e.what(), "Cannot read point data array"));
}

TEST_F(ReaderErrors, FileCutInsideTheXmlHeader) {
  const auto path = dir / "cut_header.vti";
  writeVti(velocityAndDensity(4, 4, 1), path);
  writeText(path, readText(path).substr(0, 300));
  EXPECT_TRUE(contains(fileErrorOf([&] { readVti(path); }).what(), "is corrupt or truncated"));
}

TEST_F(ReaderErrors, CorruptCompressedData) {
  const auto path = dir / "garbled.vti";
  writeVti(velocityAndDensity(20, 20, 5), path);
  std::string bytes = readText(path);
  const std::size_t data = bytes.find("<AppendedData encoding=\"raw\">");
  ASSERT_NE(data, std::string::npos);
  // Overwrite the middle of the compressed block (past the block headers) with junk.
  for (std::size_t n = data + 200; n < data + 400 && n < bytes.size(); ++n) bytes[n] = char(n * 37);
  writeText(path, bytes);
  EXPECT_TRUE(contains(fileErrorOf([&] { readVti(path); }).what(), "is corrupt or truncated"));
}

TEST_F(ReaderErrors, MissingArrayListsTheArraysPresent) {
  const auto path = dir / "flow.vti";
  writeVti(velocityAndDensity(3, 3, 1), path);
  const FileError e = fileErrorOf([&] { readVectorField(path, "foo"); });
  EXPECT_EQ(std::string(e.what()), "file " + path.string() +
                                       ": no point-data array 'foo'; arrays present: velocity(3), density(1)");
  EXPECT_EQ(e.arrayName(), "foo");
  EXPECT_EQ(e.path(), path);
}

TEST_F(ReaderErrors, ScalarArrayAskedAsVector) {
  const auto path = dir / "flow.vti";
  writeVti(velocityAndDensity(3, 3, 1), path);
  const FileError e = fileErrorOf([&] { readVectorField(path, "density"); });
  EXPECT_EQ(std::string(e.what()),
            "file " + path.string() + ": array 'density' has 1 component; a vector field needs 2 or 3");
  EXPECT_EQ(e.arrayName(), "density");
}

TEST_F(ReaderErrors, VectorArrayAskedAsScalar) {
  const auto path = dir / "flow.vti";
  writeVti(velocityAndDensity(3, 3, 1), path);
  EXPECT_TRUE(contains(fileErrorOf([&] { readScalarField(path, "velocity"); }).what(),
                       "array 'velocity' has 3 components; a scalar field needs 1"));
}

TEST_F(ReaderErrors, ArrayShorterThanTheExtent) {
  const auto path = dir / "short.vti";
  writeText(path, asciiVti("0 2 0 1 0 0", "1 1 1", "1 2 3 4"));  // 6 points, 4 values
  const FileError e = fileErrorOf([&] { readScalarField(path, "pressure"); });
  EXPECT_TRUE(contains(e.what(), "file " + path.string()));
  EXPECT_TRUE(contains(e.what(), "pressure")) << e.what();
}

TEST_F(ReaderErrors, ZeroSpacingIsRejectedNamingTheFile) {
  const auto path = dir / "flat.vti";
  writeText(path, asciiVti("0 2 0 1 0 0", "1 0 1", "1 2 3 4 5 6"));
  const FileError e = fileErrorOf([&] { readVti(path); });
  EXPECT_EQ(std::string(e.what()),
            "file " + path.string() + ": grid spacing along y is 0.000000; allowed: finite and > 0");
}

TEST_F(ReaderErrors, HandWrittenAsciiFileReads) {
  // The counterpart of the two tests above: the same file with consistent content is accepted.
  const auto path = dir / "good.vti";
  writeText(path, asciiVti("0 2 0 1 0 0", "0.5 2 1", "1 2 3 4 5 6.25"));
  const ScalarField p = readScalarField(path, "pressure");
  EXPECT_EQ(p.grid.dims, (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(p.grid.spacing[1], 2.0);
  EXPECT_EQ(p.values[p.grid.index(2, 1)], 6.25);
}

TEST_F(ReaderErrors, VtpReaderReportsTheSameProblems) {
  EXPECT_TRUE(contains(fileErrorOf([&] { readVtp(dir / "none.vtp"); }).what(), "does not exist"));
  writeVti(velocityAndDensity(3, 3, 1), dir / "image.vtp");
  EXPECT_TRUE(contains(fileErrorOf([&] { readVtp(dir / "image.vtp"); }).what(),
                       "holds VTK XML ImageData, expected PolyData (.vtp)"));
}
