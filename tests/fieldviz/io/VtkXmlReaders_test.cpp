// The grid kinds besides .vti (.vtr .vts .vtu .vtp .pvti .pvtu .vtm): read through VTK's own
// readers, resampled onto an image, and refused clearly when hostile (docs/reliability.md,
// "Grids that are not images"). Each refusal is a FileError naming the file (and the piece of a
// summary file), with VTK printing nothing.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <vtkAppendFilter.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "IoTestSupport.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlReaders.h"

using namespace fluidviz;
using fluidviz::testing::contains;
using fluidviz::testing::readText;
using fluidviz::testing::TestFolder;
using fluidviz::testing::VtkOutputCounter;
using fluidviz::testing::writeText;

namespace {

// The FileError of reading `path` as an image; fails the test if none is thrown or VTK printed.
FileError refusal(const std::filesystem::path& path, ImageSampling sampling = {}) {
  VtkOutputCounter vtkOutput;
  try {
    readImageData(path, sampling);
  } catch (const FileError& e) {
    EXPECT_EQ(vtkOutput.count(), 0) << vtkOutput.last();
    return e;
  }
  ADD_FAILURE() << "no FileError for " << path;
  return FileError("", "");
}

// Node (i, j, 0) of a 5 x 4 x 1 grid 0.5 apart carries v = (x, 2y, 0) (linear: resampling at
// the same nodes gives it back exactly).
constexpr int kNx = 5, kNy = 4;
constexpr double kH = 0.5;

vtkNew<vtkDoubleArray> velocityAt(vtkDataSet* data) {
  vtkNew<vtkDoubleArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  for (vtkIdType n = 0; n < data->GetNumberOfPoints(); ++n) {
    double p[3];
    data->GetPoint(n, p);
    v->InsertNextTuple3(p[0], 2 * p[1], 0);
  }
  return v;
}

// Adds array `name` with `tuples` copies of `value` to point or cell data.
void addConstant(vtkDataSetAttributes* data, const char* name, vtkIdType tuples, double value) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  for (vtkIdType n = 0; n < tuples; ++n) a->InsertNextValue(value);
  data->AddArray(a);
}

vtkNew<vtkPoints> gridPoints() {
  vtkNew<vtkPoints> points;
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i) points->InsertNextPoint(i * kH, j * kH, 0);
  return points;
}

vtkSmartPointer<vtkStructuredGrid> structuredGrid() {
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(kNx, kNy, 1);
  grid->SetPoints(gridPoints());
  grid->GetPointData()->AddArray(velocityAt(grid));
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> unstructuredGrid() {
  vtkNew<vtkAppendFilter> append;
  append->AddInputData(structuredGrid());
  append->Update();
  return append->GetOutput();
}

template <class Writer>
void writeAscii(vtkDataObject* data, const std::filesystem::path& path) {
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetDataModeToAscii();
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1) << path;
}

void expectVelocityOnTheGrid(vtkImageData* image) {
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], kNx);
  ASSERT_EQ(dims[1], kNy);
  vtkDataArray* v = image->GetPointData()->GetArray("v");
  ASSERT_NE(v, nullptr);
  ASSERT_NE(image->GetPointData()->GetArray("vtkValidPointMask"), nullptr);
  for (vtkIdType n = 0; n < image->GetNumberOfPoints(); ++n) {
    double p[3];
    image->GetPoint(n, p);
    EXPECT_NEAR(v->GetComponent(n, 0), p[0], 1e-9) << n;
    EXPECT_NEAR(v->GetComponent(n, 1), 2 * p[1], 1e-9) << n;
  }
}

TEST(VtkXmlReaders, StructuredAndUnstructuredGridsAreResampledAtTheGivenSpacing) {
  TestFolder dir;
  writeAscii<vtkXMLStructuredGridWriter>(structuredGrid(), dir / "g.vts");
  writeAscii<vtkXMLUnstructuredGridWriter>(unstructuredGrid(), dir / "g.vtu");
  for (const char* name : {"g.vts", "g.vtu"}) {
    SCOPED_TRACE(name);
    expectVelocityOnTheGrid(readImageData(dir / name, {.spacing = kH}));
  }
}

TEST(VtkXmlReaders, RectilinearGridIsResampled) {
  TestFolder dir;
  vtkNew<vtkRectilinearGrid> grid;
  grid->SetDimensions(kNx, kNy, 1);
  vtkNew<vtkDoubleArray> x, y, z;
  for (int i = 0; i < kNx; ++i) x->InsertNextValue(i * kH);
  for (int j = 0; j < kNy; ++j) y->InsertNextValue(j * kH);
  z->InsertNextValue(0);
  grid->SetXCoordinates(x);
  grid->SetYCoordinates(y);
  grid->SetZCoordinates(z);
  grid->GetPointData()->AddArray(velocityAt(grid));
  writeAscii<vtkXMLRectilinearGridWriter>(grid, dir / "g.vtr");
  expectVelocityOnTheGrid(readImageData(dir / "g.vtr", {.spacing = kH}));
}

// Cell data without a point array of that name becomes point data (vtkCellDataToPointData): a
// constant cell array stays that constant at every node.
TEST(VtkXmlReaders, CellArraysBecomePointArrays) {
  TestFolder dir;
  vtkSmartPointer<vtkUnstructuredGrid> grid = unstructuredGrid();
  addConstant(grid->GetCellData(), "p", grid->GetNumberOfCells(), 2.5);
  writeAscii<vtkXMLUnstructuredGridWriter>(grid, dir / "g.vtu");
  const ScalarField s = readScalarField(dir / "g.vtu", "p");
  ASSERT_FALSE(s.values.empty());
  for (double value : s.values) EXPECT_NEAR(value, 2.5, 1e-12);
}

TEST(VtkXmlReaders, MultiBlockOfDifferentKindsIsMergedThenResampled) {
  TestFolder dir;
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, structuredGrid());
  blocks->SetBlock(1, unstructuredGrid());
  writeAscii<vtkXMLMultiBlockDataWriter>(blocks, dir / "b.vtm");
  expectVelocityOnTheGrid(readImageData(dir / "b.vtm", {.spacing = kH}));
}

std::string pvtu(const std::string& source) {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\">\n"
         "<PUnstructuredGrid GhostLevel=\"0\"><PPointData><PDataArray type=\"Float64\" "
         "Name=\"v\" NumberOfComponents=\"3\"/></PPointData>\n<PPoints><PDataArray "
         "type=\"Float32\" NumberOfComponents=\"3\"/></PPoints>\n<Piece Source=\"" +
         source + "\"/>\n</PUnstructuredGrid>\n</VTKFile>\n";
}

TEST(VtkXmlReaders, ParallelUnstructuredGridIsReadFromItsPiece) {
  TestFolder dir;
  writeAscii<vtkXMLUnstructuredGridWriter>(unstructuredGrid(), dir / "g_0.vtu");
  writeText(dir / "s.pvtu", pvtu("g_0.vtu"));
  expectVelocityOnTheGrid(readImageData(dir / "s.pvtu", {.spacing = kH}));
}

TEST(VtkXmlReaders, SummaryDeclaringAnotherTypeThanItsPieceIsRefused) {
  TestFolder dir;
  writeAscii<vtkXMLUnstructuredGridWriter>(unstructuredGrid(), dir / "g_0.vtu");
  std::string summary = pvtu("g_0.vtu");
  summary.replace(summary.find("Float64"), 7, "Float32");
  writeText(dir / "s.pvtu", summary);
  const FileError e = refusal(dir / "s.pvtu");
  EXPECT_TRUE(contains(e.what(), "array 'v' of <PPointData> is Float32 x 3, in piece g_0.vtu it "
                                 "is Float64 x 3; they must agree"));
  EXPECT_EQ(e.arrayName(), "v");
}

TEST(VtkXmlReaders, SummaryNamingAMissingPieceNamesBothFiles) {
  TestFolder dir;
  writeText(dir / "s.pvtu", pvtu("gone_0.vtu"));
  const FileError e = refusal(dir / "s.pvtu");
  EXPECT_TRUE(contains(e.what(), "file " + (dir / "s.pvtu").string() + ", piece gone_0.vtu"));
  EXPECT_TRUE(contains(e.what(), (dir / "gone_0.vtu").string() + " does not exist"));
}

TEST(VtkXmlReaders, SummaryPieceOutsideItsFolderIsRefused) {
  TestFolder dir;
  for (const std::string source : {"../g.vtu", "/etc/passwd", "a/../../g.vtu"}) {
    writeText(dir / "s.pvtu", pvtu(source));
    const FileError e = refusal(dir / "s.pvtu");
    EXPECT_TRUE(contains(e.what(), "names piece '" + source + "', outside its folder")) << source;
  }
}

TEST(VtkXmlReaders, PieceOfTheWrongKindIsRefused) {
  TestFolder dir;
  writeAscii<vtkXMLStructuredGridWriter>(structuredGrid(), dir / "g_0.vtu");
  writeText(dir / "s.pvtu", pvtu("g_0.vtu"));
  EXPECT_TRUE(contains(refusal(dir / "s.pvtu").what(),
                       "piece g_0.vtu: file " + (dir / "g_0.vtu").string() +
                           " holds VTK XML StructuredGrid, expected UnstructuredGrid (.vtu)"));
}

TEST(VtkXmlReaders, CorruptPieceIsRefusedWithTheSummaryNamed) {
  TestFolder dir;
  writeAscii<vtkXMLUnstructuredGridWriter>(unstructuredGrid(), dir / "g_0.vtu");
  std::string text = readText(dir / "g_0.vtu");
  text.replace(text.find("NumberOfPoints=\"20\""), 19, "NumberOfPoints=\"2000000000000\"");
  writeText(dir / "g_0.vtu", text);
  writeText(dir / "s.pvtu", pvtu("g_0.vtu"));
  const FileError e = refusal(dir / "s.pvtu");
  EXPECT_TRUE(contains(e.what(), "piece g_0.vtu: file " + (dir / "g_0.vtu").string()));
}

// Binary appended data cut short: the size check (VtkXmlSizeCheck.h) refuses it before VTK
// reads past the end.
TEST(VtkXmlReaders, TruncatedAppendedDataIsRefused) {
  TestFolder dir;
  vtkNew<vtkXMLStructuredGridWriter> writer;
  writer->SetInputData(structuredGrid());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToNone();
  writer->SetFileName((dir / "g.vts").c_str());
  ASSERT_EQ(writer->Write(), 1);
  const std::string text = readText(dir / "g.vts");
  writeText(dir / "g.vts", text.substr(0, text.size() - 200));
  const FileError e = refusal(dir / "g.vts");
  EXPECT_TRUE(contains(e.what(), "file " + (dir / "g.vts").string() + " is corrupt: array"));
  EXPECT_TRUE(contains(e.what(), "the file is truncated"));
}

TEST(VtkXmlReaders, PointsWithTwoComponentsAreRefused) {
  TestFolder dir;
  writeAscii<vtkXMLUnstructuredGridWriter>(unstructuredGrid(), dir / "g.vtu");
  std::string text = readText(dir / "g.vtu");
  const std::size_t points = text.find("<Points>");
  const std::size_t three = text.find("NumberOfComponents=\"3\"", points);
  text.replace(three, 22, "NumberOfComponents=\"2\"");
  writeText(dir / "g.vtu", text);
  EXPECT_TRUE(contains(refusal(dir / "g.vtu").what(),
                       "have 2 component(s); allowed: NumberOfComponents=\"3\""));
}

TEST(VtkXmlReaders, ScalarArrayAskedForAsVectorsIsRefusedNamingTheArray) {
  TestFolder dir;
  vtkSmartPointer<vtkStructuredGrid> grid = structuredGrid();
  addConstant(grid->GetPointData(), "p", grid->GetNumberOfPoints(), 1.0);
  writeAscii<vtkXMLStructuredGridWriter>(grid, dir / "g.vts");
  try {
    readVectorField(dir / "g.vts", "p");
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& e) {
    EXPECT_EQ(e.arrayName(), "p");
    EXPECT_TRUE(contains(e.what(), "file " + (dir / "g.vts").string()));
    EXPECT_TRUE(contains(e.what(), "component"));
  }
}

TEST(VtkXmlReaders, DeclaredSizesLargerThanTheFileAreRefused) {
  TestFolder dir;
  writeAscii<vtkXMLStructuredGridWriter>(structuredGrid(), dir / "g.vts");
  std::string text = readText(dir / "g.vts");
  for (const char* extent : {"WholeExtent=\"0 4 0 3 0 0\"", "Extent=\"0 4 0 3 0 0\""}) {
    const std::size_t at = text.find(extent);
    ASSERT_NE(at, std::string::npos) << extent;
    text.replace(at, std::strlen(extent),
                 std::string(extent).replace(std::string(extent).find("0 4"), 3, "0 400000"));
  }
  writeText(dir / "g.vts", text);
  EXPECT_TRUE(contains(refusal(dir / "g.vts").what(), "file " + (dir / "g.vts").string()));
}

TEST(VtkXmlReaders, NanCoordinatesAreRefused) {
  TestFolder dir;
  vtkSmartPointer<vtkStructuredGrid> grid = structuredGrid();
  grid->GetPoints()->SetPoint(7, std::nan(""), 0, 0);
  writeAscii<vtkXMLStructuredGridWriter>(grid, dir / "g.vts");
  EXPECT_TRUE(contains(refusal(dir / "g.vts").what(),
                       "file " + (dir / "g.vts").string() + ": point 7 has nan as a coordinate"));
}

TEST(VtkXmlReaders, AllPointsAtOnePlaceAreRefused) {
  TestFolder dir;
  vtkSmartPointer<vtkStructuredGrid> grid = structuredGrid();
  for (vtkIdType n = 0; n < grid->GetNumberOfPoints(); ++n) grid->GetPoints()->SetPoint(n, 1, 2, 3);
  writeAscii<vtkXMLStructuredGridWriter>(grid, dir / "g.vts");
  EXPECT_TRUE(contains(refusal(dir / "g.vts").what(), "has all its points at one place"));
}

TEST(VtkXmlReaders, SpacingGivingTooManyNodesIsRefused) {
  TestFolder dir;
  writeAscii<vtkXMLUnstructuredGridWriter>(unstructuredGrid(), dir / "g.vtu");
  EXPECT_TRUE(contains(refusal(dir / "g.vtu", {.spacing = 1e-5}).what(),
                       "nodes, more than the limit 2e+08; give a larger --spacing"));
}

// A fuzz finding (fuzz_vtk_xml_grids, a 42 s timeout in vtkProbeFilter): cells that overlap make
// the probe test every image node against every cell. 400 quads each spanning the whole grid
// would cost 400 x 4 cell points per node; refused before the probe starts.
TEST(VtkXmlReaders, OverlappingCellsAreRefusedBeforeTheProbe) {
  TestFolder dir;
  vtkSmartPointer<vtkUnstructuredGrid> grid = unstructuredGrid();
  const vtkIdType corners[4] = {0, kNx - 1, kNx * kNy - 1, kNx * (kNy - 1)};
  for (int copy = 0; copy < 400; ++copy) grid->InsertNextCell(VTK_QUAD, 4, corners);
  writeAscii<vtkXMLUnstructuredGridWriter>(grid, dir / "g.vtu");
  const std::string message = refusal(dir / "g.vtu").what();
  EXPECT_TRUE(contains(message, "file " + (dir / "g.vtu").string() + ": its cells overlap"))
      << message;
  EXPECT_TRUE(contains(message, "at most 512 are allowed")) << message;
}

// The 5 x 4 grid cut into two triangles per quad.
vtkSmartPointer<vtkUnstructuredGrid> triangulatedGrid() {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(gridPoints());
  for (int j = 0; j + 1 < kNy; ++j)
    for (int i = 0; i + 1 < kNx; ++i) {
      const vtkIdType a = j * kNx + i;
      const vtkIdType lower[3] = {a, a + 1, a + kNx + 1}, upper[3] = {a, a + kNx + 1, a + kNx};
      grid->InsertNextCell(VTK_TRIANGLE, 3, lower);
      grid->InsertNextCell(VTK_TRIANGLE, 3, upper);
    }
  grid->GetPointData()->AddArray(velocityAt(grid));
  return grid;
}

// An n x n x n block of nodes kH apart, each cube cut into the six tetrahedra along its main
// diagonal (Kuhn's triangulation: long thin ones among them).
vtkSmartPointer<vtkUnstructuredGrid> tetrahedralBlock(int n) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) points->InsertNextPoint(i * kH, j * kH, k * kH);
  grid->SetPoints(points);
  const int step[3] = {1, n, n * n};
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i)
        for (const auto& order : orders) {
          vtkIdType ids[4] = {i + j * n + k * n * n};
          for (int m = 0; m < 3; ++m) ids[m + 1] = ids[m] + step[order[m]];
          grid->InsertNextCell(VTK_TETRA, 4, ids);
        }
  grid->GetPointData()->AddArray(velocityAt(grid));
  return grid;
}

// Cells that tile the domain pass however they are cut: the 5 x 4 grid as triangles and a 3D
// block as tetrahedra resample as before, the linear field exactly.
TEST(VtkXmlReaders, TrianglesAndTetrahedraThatTileTheDomainAreResampled) {
  TestFolder dir;
  writeAscii<vtkXMLUnstructuredGridWriter>(triangulatedGrid(), dir / "triangles.vtu");
  expectVelocityOnTheGrid(readImageData(dir / "triangles.vtu", {.spacing = kH}));

  constexpr int n = 12;
  writeAscii<vtkXMLUnstructuredGridWriter>(tetrahedralBlock(n), dir / "tetrahedra.vtu");
  vtkSmartPointer<vtkImageData> image = readImageData(dir / "tetrahedra.vtu", {.spacing = kH});
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0] * dims[1] * dims[2], n * n * n);
  vtkDataArray* v = image->GetPointData()->GetArray("v");
  ASSERT_NE(v, nullptr);
  for (vtkIdType m = 0; m < image->GetNumberOfPoints(); ++m) {
    double p[3];
    image->GetPoint(m, p);
    EXPECT_NEAR(v->GetComponent(m, 1), 2 * p[1], 1e-9) << m;
  }
}

}  // namespace
