// Legacy .vtk files of every dataset type, written by VTK's own vtkDataSetWriter (ASCII and
// BINARY), read through readImageData: structured points as they are, the other types resampled
// onto an image by vtkResampleToImage. The field is linear, which trilinear and linear cell
// interpolation reproduce exactly, so every valid node must carry the analytic value (to float
// round-off); nodes outside the input's cells are flagged by vtkValidPointMask.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>

#include <pthread.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataSetWriter.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredPoints.h>
#include <vtkUnstructuredGrid.h>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkLegacyReader.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "tests/fieldviz/io/IoTestSupport.h"
#include "tests/support/TextFiles.h"

using namespace fluidviz;
using fluidviz::testing::TestFolder;

namespace {

Vec3 linearVelocity(const double* x) {
  return {1.0 + 2.0 * x[0] - x[1], 3.0 + x[0] + 0.5 * x[1] - x[2], 0.25 * x[2]};
}

// Adds "velocity" (linear, above) and "pressure" = x + y + z at every point.
void addLinearArrays(vtkDataSet* data) {
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> p;
  p->SetName("pressure");
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double x[3];
    data->GetPoint(i, x);
    const Vec3 u = linearVelocity(x);
    v->InsertNextTuple3(u.x(), u.y(), u.z());
    p->InsertNextValue(x[0] + x[1] + x[2]);
  }
  data->GetPointData()->AddArray(v);
  data->GetPointData()->AddArray(p);
  data->GetPointData()->SetActiveVectors("velocity");
}

// A structured grid of nx x ny x nz points, sheared in x by y (a curvilinear grid).
vtkSmartPointer<vtkStructuredGrid> shearedGrid(int nx, int ny, int nz) {
  auto g = vtkSmartPointer<vtkStructuredGrid>::New();
  g->SetDimensions(nx, ny, nz);
  vtkNew<vtkPoints> pts;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) pts->InsertNextPoint(0.1 * i + 0.02 * j, 0.1 * j, 0.1 * k);
  g->SetPoints(pts);
  addLinearArrays(g);
  return g;
}

vtkSmartPointer<vtkRectilinearGrid> stretchedRectilinear(int nx, int ny, int nz) {
  auto g = vtkSmartPointer<vtkRectilinearGrid>::New();
  g->SetDimensions(nx, ny, nz);
  auto coords = [](int n, double growth) {
    vtkNew<vtkDoubleArray> c;
    double x = 0, h = 0.05;
    for (int i = 0; i < n; ++i, x += h, h *= growth) c->InsertNextValue(x);
    return vtkSmartPointer<vtkDoubleArray>(c);
  };
  g->SetXCoordinates(coords(nx, 1.2));
  g->SetYCoordinates(coords(ny, 1.1));
  g->SetZCoordinates(coords(nz, 1.0));
  addLinearArrays(g);
  return g;
}

// An L-shaped unstructured grid of hexahedra: the unit square minus its upper-right quarter,
// one layer thick.
vtkSmartPointer<vtkUnstructuredGrid> lShapedHexes(int n) {
  auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  const double h = 1.0 / n;
  auto id = [n](int i, int j, int k) { return vtkIdType((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) pts->InsertNextPoint(i * h, j * h, k * h);
  g->SetPoints(pts);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i >= n / 2 && j >= n / 2) continue;
      const vtkIdType hex[8] = {id(i, j, 0),     id(i + 1, j, 0),     id(i + 1, j + 1, 0),
                                id(i, j + 1, 0), id(i, j, 1),         id(i + 1, j, 1),
                                id(i + 1, j + 1, 1), id(i, j + 1, 1)};
      g->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
    }
  addLinearArrays(g);
  return g;
}

// A flat triangulated square in z = 0 (poly data).
vtkSmartPointer<vtkPolyData> triangulatedSquare(int n) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> tris;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) pts->InsertNextPoint(double(i) / n, double(j) / n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const vtkIdType a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      const vtkIdType t1[3] = {a, b, d}, t2[3] = {a, d, c};
      tris->InsertNextCell(3, t1);
      tris->InsertNextCell(3, t2);
    }
  poly->SetPoints(pts);
  poly->SetPolys(tris);
  addLinearArrays(poly);
  return poly;
}

void writeLegacy(vtkDataObject* data, const std::filesystem::path& path, bool binary) {
  vtkNew<vtkDataSetWriter> w;
  w->SetInputData(data);
  w->SetFileName(path.c_str());
  if (binary) w->SetFileTypeToBinary();
  else w->SetFileTypeToASCII();
  ASSERT_EQ(w->Write(), 1) << path;
}

struct Agreement {
  int valid = 0, invalid = 0;
  double maxError = 0;
};

// Every node of the image where vtkValidPointMask is 1 against the analytic field.
Agreement compareWithLinearField(vtkImageData* image) {
  Agreement a;
  vtkDataArray* v = image->GetPointData()->GetArray("velocity");
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  EXPECT_NE(v, nullptr);
  if (!v) return a;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    if (mask && mask->GetTuple1(i) == 0) {
      ++a.invalid;
      continue;
    }
    ++a.valid;
    double x[3], u[3];
    image->GetPoint(i, x);
    v->GetTuple(i, u);
    a.maxError = std::max(a.maxError, (Vec3(u[0], u[1], u[2]) - linearVelocity(x)).norm());
  }
  return a;
}

class LegacyEncodings : public ::testing::TestWithParam<bool> {};

}  // namespace

TEST_P(LegacyEncodings, StructuredPointsAreReadAsTheImageTheyAre) {
  TestFolder folder;
  vtkNew<vtkStructuredPoints> sp;
  sp->SetDimensions(5, 4, 3);
  sp->SetOrigin(-1, 0.5, 0);
  sp->SetSpacing(0.25, 0.5, 1.0);
  addLinearArrays(sp);
  writeLegacy(sp, folder / "points.vtk", GetParam());
  vtkSmartPointer<vtkImageData> image = readImageData(folder / "points.vtk");
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 5);
  EXPECT_EQ(dims[1], 4);
  EXPECT_EQ(dims[2], 3);
  EXPECT_EQ(image->GetPointData()->GetArray("vtkValidPointMask"), nullptr);
  const Agreement a = compareWithLinearField(image);
  EXPECT_EQ(a.valid, 60);
  EXPECT_LT(a.maxError, 1e-6);
  const VectorField v = readVectorField(folder / "points.vtk", "velocity");
  EXPECT_EQ(v.grid.dims[0], 5);
  EXPECT_DOUBLE_EQ(v.grid.spacing[1], 0.5);
}

TEST_P(LegacyEncodings, EveryOtherDatasetTypeIsResampledExactlyForALinearField) {
  TestFolder folder;
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkDataSet>>> cases = {
      {"structured_grid", shearedGrid(11, 9, 3)},
      {"rectilinear_grid", stretchedRectilinear(10, 9, 2)},
      {"unstructured_grid", lShapedHexes(8)},
      {"polydata", triangulatedSquare(6)}};
  for (const auto& [name, data] : cases) {
    const auto file = folder / (name + ".vtk");
    writeLegacy(data, file, GetParam());
    vtkSmartPointer<vtkImageData> image = readImageData(file);
    const Agreement a = compareWithLinearField(image);
    EXPECT_GT(a.valid, 0.5 * image->GetNumberOfPoints()) << name;
    // float32 values: 1e-5 relative on |v| <= ~6.
    EXPECT_LT(a.maxError, 1e-5) << name;
    double b[6], ib[6];
    data->GetBounds(b);
    image->GetBounds(ib);
    // The image starts at the lower bounds and stops less than one (equal) spacing short of the
    // upper ones.
    double h[3];
    image->GetSpacing(h);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(ib[2 * a], b[2 * a], 1e-9) << name << " axis " << a;
      EXPECT_LE(ib[2 * a + 1], b[2 * a + 1] + 1e-9) << name << " axis " << a;
      // (An axis shorter than the spacing gets its extent as its spacing.)
      if (b[2 * a + 1] - b[2 * a] >= h[0]) {
        EXPECT_GT(ib[2 * a + 1], b[2 * a + 1] - h[a] - 1e-9) << name << " axis " << a;
        EXPECT_NEAR(h[a], h[0], 1e-12) << name << " axis " << a;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AsciiAndBinary, LegacyEncodings, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "binary" : "ascii"; });

// The L-shaped grid leaves the upper-right quarter empty: those nodes are invalid, the others
// valid. Nodes exactly on the re-entrant edges may go either way.
TEST(VtkLegacyReader, NodesOutsideTheCellsAreMaskedInvalid) {
  TestFolder folder;
  writeLegacy(lShapedHexes(8), folder / "l.vtk", true);
  ImageSampling sampling;
  sampling.spacing = 0.05;
  vtkSmartPointer<vtkImageData> image = readImageData(folder / "l.vtk", sampling);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 21);
  EXPECT_EQ(dims[1], 21);
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  ASSERT_NE(mask, nullptr);
  int wrong = 0;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    double x[3];
    image->GetPoint(i, x);
    const bool onEdge = std::abs(x[0] - 0.5) < 1e-9 || std::abs(x[1] - 0.5) < 1e-9;
    if (onEdge) continue;
    const bool inside = !(x[0] > 0.5 && x[1] > 0.5);
    if ((mask->GetTuple1(i) != 0) != inside) ++wrong;
  }
  EXPECT_EQ(wrong, 0);
}

// VTK's legacy reader runs in a program of its own, started by posix_spawn: a fork of this
// process (which has OpenMP's and Mesa's threads) could inherit a lock another thread holds and
// hang, as one did in a sanitizer build. glibc runs pthread_atfork handlers on fork(), not on
// posix_spawn, so the count says which one was used.
int forksSeen = 0;

TEST(VtkLegacyReader, ReadsInAnotherProgramWithoutForkingThisProcess) {
  static const bool registered = pthread_atfork(nullptr, [] { ++forksSeen; }, nullptr) == 0;
  ASSERT_TRUE(registered);
  TestFolder folder;
  writeLegacy(lShapedHexes(4), folder / "l.vtk", true);
  const int before = forksSeen;
  ImageSampling sampling;
  sampling.spacing = 0.25;
  vtkSmartPointer<vtkImageData> image = readImageData(folder / "l.vtk", sampling);
  EXPECT_EQ(image->GetNumberOfPoints(), 5 * 5 * 2);  // one layer of hexes, 0.25 m thick
  EXPECT_EQ(forksSeen, before);
}

TEST(VtkLegacyReader, CellDataOfStructuredPointsBecomesPointData) {
  TestFolder folder;
  vtkNew<vtkStructuredPoints> sp;
  sp->SetDimensions(4, 3, 1);
  vtkNew<vtkDoubleArray> c;
  c->SetName("temperature");
  for (int i = 0; i < 6; ++i) c->InsertNextValue(10.0);
  sp->GetCellData()->AddArray(c);
  writeLegacy(sp, folder / "cells.vtk", false);
  const ScalarField t = readScalarField(folder / "cells.vtk", "temperature");
  ASSERT_EQ(t.values.size(), 12u);
  for (double x : t.values) EXPECT_DOUBLE_EQ(x, 10.0);  // the average of equal cells
}

namespace {

using fluidviz::testing::writeText;

std::string errorOf(const std::filesystem::path& path) {
  try {
    readImageData(path);
  } catch (const FileError& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kHeader = "# vtk DataFile Version 3.0\nhostile\nASCII\n";

}  // namespace

TEST(VtkLegacyReaderErrors, DeclaredSizesBeyondTheFileAreRefusedBeforeVtkAllocates) {
  TestFolder folder;
  writeText(folder / "points.vtk", std::string(kHeader) +
                                      "DATASET POLYDATA\nPOINTS 100000000000 float\n0 0 0\n");
  EXPECT_NE(errorOf(folder / "points.vtk").find("line 5 (POINTS) declares 3e+11 values"),
            std::string::npos)
      << errorOf(folder / "points.vtk");
  writeText(folder / "dims.vtk", std::string(kHeader) +
                                    "DATASET STRUCTURED_POINTS\nDIMENSIONS 100000 100000 100000\n");
  EXPECT_NE(errorOf(folder / "dims.vtk").find("(DIMENSIONS)"), std::string::npos)
      << errorOf(folder / "dims.vtk");
  writeText(folder / "field.vtk", std::string(kHeader) +
                                     "DATASET STRUCTURED_POINTS\nDIMENSIONS 2 1 1\nPOINT_DATA 2\n"
                                     "FIELD f 1\nvelocity 3 99999999999 float\n");
  EXPECT_NE(errorOf(folder / "field.vtk").find("(field array velocity)"), std::string::npos);
  writeText(folder / "scalars.vtk", std::string(kHeader) +
                                       "DATASET STRUCTURED_POINTS\nDIMENSIONS 2 1 1\n"
                                       "POINT_DATA 2\nSCALARS s float 7\n");
  EXPECT_NE(errorOf(folder / "scalars.vtk").find("has 7 components; VTK allows 1 to 4"),
            std::string::npos);
  writeText(folder / "count.vtk", std::string(kHeader) + "DATASET POLYDATA\nPOINTS -4 float\n");
  EXPECT_NE(errorOf(folder / "count.vtk").find("is '-4', expected a whole number >= 0"),
            std::string::npos);
}

TEST(VtkLegacyReaderErrors, ArraysThatDoNotMatchThePointsAreRefused) {
  TestFolder folder;
  writeText(folder / "short.vtk", std::string(kHeader) +
                                     "DATASET STRUCTURED_POINTS\nDIMENSIONS 3 1 1\nORIGIN 0 0 0\n"
                                     "SPACING 1 1 1\nPOINT_DATA 2\nSCALARS s float 1\n"
                                     "LOOKUP_TABLE default\n1 2\n");
  const std::string e = errorOf(folder / "short.vtk");
  // VTK's own reader notices this one; the message is VTK's.
  EXPECT_NE(e.find("is corrupt or truncated: Number of points don't match data values"),
            std::string::npos)
      << e;
}

TEST(VtkLegacyReaderErrors, TruncatedAndForeignFilesSayWhatTheyAre) {
  TestFolder folder;
  writeText(folder / "trunc.vtk", std::string(kHeader) +
                                     "DATASET STRUCTURED_GRID\nDIMENSIONS 2 2 1\nPOINTS 4 float\n"
                                     "0 0 0 1 0 0\n");
  EXPECT_NE(errorOf(folder / "trunc.vtk").find("is corrupt or truncated"), std::string::npos)
      << errorOf(folder / "trunc.vtk");
  writeText(folder / "foreign.vtk", "<VTKFile type=\"ImageData\">\n");
  EXPECT_NE(errorOf(folder / "foreign.vtk").find("is not a legacy VTK file"), std::string::npos);
  EXPECT_NE(errorOf(folder / "missing.vtk").find("does not exist"), std::string::npos);
}

// The legacy reader trusts connectivity and coordinate counts; VTK's filters would then read
// past the points.
TEST(VtkLegacyReaderErrors, CellsAndCoordinatesThatDoNotFitTheGeometryAreRefused) {
  TestFolder folder;
  const std::string points = "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n";
  writeText(folder / "id.vtk", std::string(kHeader) + "DATASET UNSTRUCTURED_GRID\n" + points +
                                  "CELLS 1 5\n4 0 1 2 9\nCELL_TYPES 1\n9\n");
  EXPECT_NE(errorOf(folder / "id.vtk").find("cell 0 names point 9, outside [0, 3]"),
            std::string::npos)
      << errorOf(folder / "id.vtk");
  writeText(folder / "count.vtk", std::string(kHeader) + "DATASET UNSTRUCTURED_GRID\n" + points +
                                     "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n12\n");
  EXPECT_NE(errorOf(folder / "count.vtk").find("cell 0 (type 12) has 3 points, needs 8"),
            std::string::npos)
      << errorOf(folder / "count.vtk");
  writeText(folder / "type.vtk", std::string(kHeader) + "DATASET UNSTRUCTURED_GRID\n" + points +
                                    "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n77\n");
  EXPECT_NE(errorOf(folder / "type.vtk").find("has cell type 77"), std::string::npos)
      << errorOf(folder / "type.vtk");
  writeText(folder / "poly.vtk", std::string(kHeader) + "DATASET POLYDATA\n" + points +
                                    "POLYGONS 1 4\n3 0 1 4\n");
  EXPECT_NE(errorOf(folder / "poly.vtk").find("polygon 0 names point 4"), std::string::npos)
      << errorOf(folder / "poly.vtk");
  writeText(folder / "rect.vtk", std::string(kHeader) +
                                    "DATASET RECTILINEAR_GRID\nDIMENSIONS 3 2 1\n"
                                    "X_COORDINATES 2 float\n0 1\nY_COORDINATES 2 float\n0 1\n"
                                    "Z_COORDINATES 1 float\n0\n");
  EXPECT_NE(errorOf(folder / "rect.vtk").find("X_COORDINATES has 2 values, DIMENSIONS says 3"),
            std::string::npos)
      << errorOf(folder / "rect.vtk");
  writeText(folder / "sg.vtk", std::string(kHeader) + "DATASET STRUCTURED_GRID\n"
                                  "DIMENSIONS 3 2 1\n" + points);
  EXPECT_NE(errorOf(folder / "sg.vtk").find("need 6 points, POINTS has 4"), std::string::npos)
      << errorOf(folder / "sg.vtk");
}

// Before version 5 a cell list is counts and ids in one list, which VTK 9.1 copies without
// checking the counts (fuzzing: a count past the list's end read beyond it). A first line VTK
// cannot take a version from makes it guess the layout.
TEST(VtkLegacyReaderErrors, LegacyCellListsMustAddUpAndTheVersionMustBeReadable) {
  TestFolder folder;
  const std::string points = "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n";
  writeText(folder / "past.vtk", std::string(kHeader) + "DATASET POLYDATA\n" + points +
                                    "POLYGONS 1 5\n9 0 1 2 3\n");
  EXPECT_NE(errorOf(folder / "past.vtk").find("(POLYGONS) cell 0 has 9 points, past the list of 5"),
            std::string::npos)
      << errorOf(folder / "past.vtk");
  writeText(folder / "short.vtk", std::string(kHeader) + "DATASET POLYDATA\n" + points +
                                     "POLYGONS 1 6\n3 0 1 2\n");
  EXPECT_NE(errorOf(folder / "short.vtk").find("lists 1 cells in 4 integers, not the 6"),
            std::string::npos)
      << errorOf(folder / "short.vtk");
  writeText(folder / "version.vtk", "# vtk DataFile Version*5.1\nv\nASCII\nDATASET POLYDATA\n" +
                                       points);
  EXPECT_NE(errorOf(folder / "version.vtk").find("expected '# vtk DataFile Version M.m'"),
            std::string::npos)
      << errorOf(folder / "version.vtk");
}
