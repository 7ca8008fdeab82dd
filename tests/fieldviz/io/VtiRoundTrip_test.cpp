// .vti files written by fluidviz read back bit for bit; .vti files written by plain VTK (float32,
// every data mode and compressor ParaView offers) read back within float precision.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include "IoTestSupport.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "fieldviz/io/VtkXmlWriters.h"

using namespace fluidviz;
using fluidviz::testing::TestFolder;

namespace {

// Values chosen to catch any text round trip or float narrowing: thirds, sevenths, signed zero,
// a subnormal, huge and tiny magnitudes.
double awkwardValue(std::size_t n, int component) {
  switch ((n + component) % 6) {
    case 0: return 1.0 / (3.0 + n);
    case 1: return -0.0;
    case 2: return std::numeric_limits<double>::denorm_min() * (n + 1);
    case 3: return 1e300 / (n + 1);
    case 4: return -std::sqrt(2.0) * n;
    default: return 0.1 * component + 1e-17 * n;
  }
}

FieldSet awkwardSet(const Grid& grid) {
  FieldSet set;
  set.grid = grid;
  VectorField velocity{"velocity", grid, {}};
  VectorField vorticity{"vorticity", grid, {}};
  ScalarField density{"density", grid, {}};
  ScalarField speed{"speed", grid, {}};
  for (std::size_t n = 0; n < grid.nodeCount(); ++n) {
    velocity.values.push_back({awkwardValue(n, 0), awkwardValue(n, 1), grid.is2D() ? 0.0 : awkwardValue(n, 2)});
    vorticity.values.push_back({0.0, 0.0, awkwardValue(n, 5)});
    density.values.push_back(awkwardValue(n, 3));
    speed.values.push_back(awkwardValue(n, 4));
  }
  set.add(velocity);
  set.add(density);
  set.add(vorticity);
  set.add(speed);
  return set;
}

bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

void expectBitwiseEqual(const FieldSet& expected, const FieldSet& actual) {
  EXPECT_EQ(actual.grid.dims, expected.grid.dims);
  for (int a = 0; a < 3; ++a) {
    EXPECT_TRUE(sameBits(actual.grid.origin[a], expected.grid.origin[a]))
        << "origin " << a << ": " << actual.grid.origin[a] << " vs " << expected.grid.origin[a];
    EXPECT_TRUE(sameBits(actual.grid.spacing[a], expected.grid.spacing[a]))
        << "spacing " << a << ": " << actual.grid.spacing[a] << " vs " << expected.grid.spacing[a];
  }
  EXPECT_EQ(actual.arrayNames(), expected.arrayNames());
  ASSERT_EQ(actual.vectors.size(), expected.vectors.size());
  ASSERT_EQ(actual.scalars.size(), expected.scalars.size());
  int mismatches = 0;
  for (std::size_t f = 0; f < expected.vectors.size(); ++f) {
    ASSERT_EQ(actual.vectors[f].values.size(), expected.vectors[f].values.size());
    for (std::size_t n = 0; n < expected.vectors[f].values.size(); ++n)
      for (int c = 0; c < 3; ++c)
        mismatches += !sameBits(actual.vectors[f].values[n][c], expected.vectors[f].values[n][c]);
  }
  for (std::size_t f = 0; f < expected.scalars.size(); ++f) {
    ASSERT_EQ(actual.scalars[f].values.size(), expected.scalars[f].values.size());
    for (std::size_t n = 0; n < expected.scalars[f].values.size(); ++n)
      mismatches += !sameBits(actual.scalars[f].values[n], expected.scalars[f].values[n]);
  }
  EXPECT_EQ(mismatches, 0);
}

Grid awkwardGrid(std::array<int, 3> dims) {
  Grid g;
  g.dims = dims;
  g.origin = {-0.1, 1.0 / 3.0, 2.5e-7};
  g.spacing = {1.0 / 7.0, 0.3, 1e-3 / 3.0};
  return g;
}

}  // namespace

TEST(VtiRoundTrip, TwoDimensionalSetIsBitwiseExact) {
  TestFolder dir;
  const FieldSet written = awkwardSet(awkwardGrid({17, 9, 1}));
  writeVti(written, dir / "flow2d.vti");
  expectBitwiseEqual(written, readVti(dir / "flow2d.vti"));
}

TEST(VtiRoundTrip, ThreeDimensionalSetIsBitwiseExact) {
  TestFolder dir;
  const FieldSet written = awkwardSet(awkwardGrid({6, 5, 4}));
  writeVti(written, dir / "flow3d.vti");
  expectBitwiseEqual(written, readVti(dir / "flow3d.vti"));
}

TEST(VtiRoundTrip, NamedFieldsReadBackExactly) {
  TestFolder dir;
  const FieldSet written = awkwardSet(awkwardGrid({5, 4, 3}));
  writeVti(written, dir / "f.vti");
  const VectorField v = readVectorField(dir / "f.vti", "vorticity");
  const ScalarField s = readScalarField(dir / "f.vti", "speed");
  EXPECT_EQ(v.name, "vorticity");
  EXPECT_TRUE(v.grid.sameShape(written.grid));
  ASSERT_EQ(v.values.size(), 60u);
  ASSERT_EQ(s.values.size(), 60u);
  for (std::size_t n = 0; n < 60; ++n) {
    EXPECT_TRUE(sameBits(v.values[n].z(), written.vectors[1].values[n].z())) << n;
    EXPECT_TRUE(sameBits(s.values[n], written.scalars[1].values[n])) << n;
  }
}

TEST(VtiRoundTrip, OverwritingAnExistingFileReplacesIt) {
  TestFolder dir;
  writeVti(awkwardSet(awkwardGrid({3, 3, 1})), dir / "f.vti");
  const FieldSet second = awkwardSet(awkwardGrid({4, 2, 2}));
  writeVti(second, dir / "f.vti");
  expectBitwiseEqual(second, readVti(dir / "f.vti"));
}

// ---- files written by plain VTK, as ParaView and other tools write them ---------------------

struct WriterMode {
  const char* name;
  int dataMode;     // vtkXMLWriter::Ascii / Binary / Appended
  int compressor;   // vtkXMLWriterBase::NONE / ZLIB / LZ4 / LZMA
  bool encodeAppended;
};

// Names the mode in test names (ctest shows "ReadsWithinFloatPrecision/AppendedRawZLib").
void PrintTo(const WriterMode& mode, std::ostream* os) { *os << mode.name; }

class PlainVtkFloatFile : public ::testing::TestWithParam<WriterMode> {};

// A 5x4x3 float32 image: velocity (3 floats) and pressure (1 float), origin (1, -2, 0.5),
// spacing (0.1, 0.2, 0.3). Values are analytic so the test knows them without the writer.
float velocityComponent(int i, int j, int k, int c) { return 0.1f * i - 0.37f * j + 1.0f / (1 + k + c); }
float pressure(int i, int j, int k) { return std::sin(0.3f * i) * std::exp(-0.1f * j) + 1e4f * k; }

void writePlainVtkFloatImage(const std::filesystem::path& path, const WriterMode& mode) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 4, 3);
  image->SetOrigin(1.0, -2.0, 0.5);
  image->SetSpacing(0.1, 0.2, 0.3);
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> p;
  p->SetName("pressure");
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i) {
        velocity->InsertNextTuple3(velocityComponent(i, j, k, 0), velocityComponent(i, j, k, 1),
                                   velocityComponent(i, j, k, 2));
        p->InsertNextValue(pressure(i, j, k));
      }
  image->GetPointData()->AddArray(velocity);
  image->GetPointData()->SetScalars(p);
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->SetDataMode(mode.dataMode);
  writer->SetCompressorType(mode.compressor);
  writer->SetEncodeAppendedData(mode.encodeAppended);
  ASSERT_EQ(writer->Write(), 1);
}

TEST_P(PlainVtkFloatFile, ReadsWithinFloatPrecision) {
  TestFolder dir;
  const auto path = dir / "plain.vti";
  writePlainVtkFloatImage(path, GetParam());
  const FieldSet set = readVti(path);
  EXPECT_EQ(set.grid.dims, (std::array<int, 3>{5, 4, 3}));
  EXPECT_EQ(set.grid.origin, (std::array<double, 3>{1.0, -2.0, 0.5}));
  // The file stores the double spacing; only array values are float32.
  EXPECT_EQ(set.grid.spacing, (std::array<double, 3>{0.1, 0.2, 0.3}));
  ASSERT_EQ(set.arrayNames(), (std::vector<std::string>{"velocity", "pressure"}));
  const VectorField& v = set.vectors[0];
  const ScalarField& s = set.scalars[0];
  double worstVelocity = 0.0, worstPressure = 0.0;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i) {
        const std::size_t n = set.grid.index(i, j, k);
        for (int c = 0; c < 3; ++c)
          worstVelocity = std::max(worstVelocity, std::abs(v.values[n][c] - velocityComponent(i, j, k, c)));
        worstPressure = std::max(worstPressure, std::abs(s.values[n] - pressure(i, j, k)) /
                                                    std::max(1.0, std::abs(double(pressure(i, j, k)))));
      }
  // Binary float32 is exact; ASCII is written with float's 9 significant digits (relative 6e-8).
  EXPECT_LE(worstVelocity, 2e-7);
  EXPECT_LE(worstPressure, 2e-7);
}

INSTANTIATE_TEST_SUITE_P(
    WriterModes, PlainVtkFloatFile,
    ::testing::Values(WriterMode{"AppendedRawZLib", vtkXMLWriter::Appended, vtkXMLWriterBase::ZLIB, false},
                      WriterMode{"AppendedBase64Uncompressed", vtkXMLWriter::Appended, vtkXMLWriterBase::NONE, true},
                      WriterMode{"InlineBinaryLZ4", vtkXMLWriter::Binary, vtkXMLWriterBase::LZ4, false},
                      WriterMode{"InlineBinaryLZMA", vtkXMLWriter::Binary, vtkXMLWriterBase::LZMA, false},
                      WriterMode{"Ascii", vtkXMLWriter::Ascii, vtkXMLWriterBase::NONE, false}));
