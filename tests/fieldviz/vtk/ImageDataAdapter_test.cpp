#include "fieldviz/vtk/ImageDataAdapter.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkNew.h>

#include "fieldviz/vtk/VtkMessageCollector.h"

using namespace fluidviz;

namespace {

::testing::AssertionResult contains(const std::string& text, const std::string& piece) {
  if (text.find(piece) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << piece << "\"";
}

// Runs `f`, expects it to throw E, and returns the exception's message.
template <class E, class F>
std::string messageOf(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception thrown";
  return {};
}

Grid grid3D() {
  Grid g;
  g.dims = {4, 3, 2};
  g.origin = {-0.1, 1.0 / 3.0, 2.5};
  g.spacing = {0.25, 1.0 / 7.0, 0.5};
  return g;
}

FieldSet sampleSet() {
  FieldSet set;
  set.grid = grid3D();
  VectorField v{"velocity", set.grid, {}};
  ScalarField s{"density", set.grid, {}};
  for (std::size_t n = 0; n < set.grid.nodeCount(); ++n) {
    v.values.push_back(Vec3(0.1 * n, -1.0 / (n + 1.0), 3.0 + n));
    s.values.push_back(1.0 + n / 3.0);
  }
  set.add(v);
  set.add(s);
  return set;
}

// A 3x2x1 image with arrays of several types and shapes, as other tools write them.
vtkSmartPointer<vtkImageData> mixedImage() {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(3, 2, 1);
  image->SetSpacing(0.5, 0.5, 1.0);
  vtkNew<vtkFloatArray> velocity2;  // 2-component float vectors
  velocity2->SetName("velocity");
  velocity2->SetNumberOfComponents(2);
  vtkNew<vtkIntArray> label;  // integer scalars
  label->SetName("label");
  vtkNew<vtkDoubleArray> tensor;  // 9 components: not a field fluidviz knows
  tensor->SetName("stress");
  tensor->SetNumberOfComponents(9);
  for (int n = 0; n < 6; ++n) {
    velocity2->InsertNextTuple2(0.1f * n, -0.2f * n);
    label->InsertNextValue(100 * n - 7);
    double t[9] = {};
    tensor->InsertNextTuple(t);
  }
  image->GetPointData()->AddArray(velocity2);
  image->GetPointData()->AddArray(label);
  image->GetPointData()->AddArray(tensor);
  return image;
}

}  // namespace

TEST(ImageDataAdapter, FieldSetBecomesImageWithExactGridAndDoubleArrays) {
  const FieldSet set = sampleSet();
  vtkSmartPointer<vtkImageData> image = toImageData(set);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 4);
  EXPECT_EQ(dims[1], 3);
  EXPECT_EQ(dims[2], 2);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(image->GetOrigin()[a], set.grid.origin[a]) << "axis " << a;
    EXPECT_EQ(image->GetSpacing()[a], set.grid.spacing[a]) << "axis " << a;
  }
  vtkPointData* pd = image->GetPointData();
  ASSERT_EQ(pd->GetNumberOfArrays(), 2);
  EXPECT_STREQ(pd->GetArrayName(0), "velocity");  // vectors first, as FieldSet::arrayNames
  EXPECT_STREQ(pd->GetArrayName(1), "density");
  auto* v = vtkDoubleArray::SafeDownCast(pd->GetArray("velocity"));
  auto* s = vtkDoubleArray::SafeDownCast(pd->GetArray("density"));
  ASSERT_NE(v, nullptr);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(v->GetNumberOfComponents(), 3);
  const std::size_t n = set.grid.index(3, 1, 1);  // point id == Grid::index (x fastest)
  for (int c = 0; c < 3; ++c) EXPECT_EQ(v->GetComponent(n, c), set.vectors[0].values[n][c]);
  EXPECT_EQ(s->GetValue(n), set.scalars[0].values[n]);
  EXPECT_EQ(image->GetPoint(n)[1], set.grid.position(3, 1, 1).y());
}

TEST(ImageDataAdapter, TwoDimensionalVectorsGetThreeComponents) {
  FieldSet set;
  set.grid.dims = {3, 2, 1};
  set.add(VectorField{"v", set.grid, std::vector<Vec3>(6, Vec3(1.5, -2.0, 0.0))});
  vtkSmartPointer<vtkImageData> image = toImageData(set);
  EXPECT_EQ(image->GetDimensions()[2], 1);
  EXPECT_EQ(image->GetPointData()->GetArray("v")->GetNumberOfComponents(), 3);
  EXPECT_EQ(image->GetPointData()->GetArray("v")->GetComponent(5, 1), -2.0);
}

TEST(ImageDataAdapter, FieldOfWrongSizeIsRejected) {
  FieldSet set;
  set.grid.dims = {3, 2, 1};
  set.scalars.push_back(ScalarField{"p", set.grid, std::vector<double>(5, 0.0)});
  const std::string message = messageOf<std::invalid_argument>([&] { toImageData(set); });
  EXPECT_TRUE(contains(message, "field 'p' has 5 values"));
  EXPECT_TRUE(contains(message, "has 6 nodes"));
}

TEST(ImageDataAdapter, ImageBecomesFieldSetWithTypesConvertedAndShapesSorted) {
  vtkSmartPointer<vtkImageData> image = mixedImage();
  ImageDataFields result = fromImageData(image, "file m.vti");
  const FieldSet& set = result.fields;
  EXPECT_EQ(set.grid.dims, (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(set.grid.spacing, (std::array<double, 3>{0.5, 0.5, 1.0}));
  ASSERT_EQ(set.vectors.size(), 1u);
  ASSERT_EQ(set.scalars.size(), 1u);
  const VectorField& v = set.vectors[0];
  EXPECT_EQ(v.name, "velocity");
  // 2 components -> z = 0; float -> double within float precision.
  EXPECT_NEAR(v.values[5].x(), 0.5, 1e-7);
  EXPECT_NEAR(v.values[5].y(), -1.0, 1e-7);
  EXPECT_EQ(v.values[5].z(), 0.0);
  EXPECT_EQ(set.scalars[0].name, "label");
  EXPECT_EQ(set.scalars[0].values[4], 393.0);  // ints are exact
  ASSERT_EQ(result.skipped.size(), 1u);
  EXPECT_EQ(result.skipped[0].name, "stress");
  EXPECT_EQ(result.skipped[0].components, 9);
  EXPECT_TRUE(contains(result.skipped[0].reason, "9 components"));
}

TEST(ImageDataAdapter, ExtentNotStartingAtZeroShiftsTheOrigin) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(2, 4, -1, 0, 0, 0);
  image->SetOrigin(1.0, 0.0, 0.0);
  image->SetSpacing(0.5, 2.0, 1.0);
  const Grid g = gridOf(image);
  EXPECT_EQ(g.dims, (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(g.origin[0], 2.0);   // 1 + 2 * 0.5
  EXPECT_EQ(g.origin[1], -2.0);  // 0 - 1 * 2
  EXPECT_EQ(Vec3(image->GetPoint(0)[0], image->GetPoint(0)[1], 0.0), g.position(0, 0));
}

TEST(ImageDataAdapter, RotatedImageIsRejected) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(2, 2, 1);
  image->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1);
  const std::string message = messageOf<std::invalid_argument>([&] { gridOf(image, "file r.vti"); });
  EXPECT_TRUE(contains(message, "file r.vti: the image is rotated"));
}

TEST(ImageDataAdapter, InvalidSpacingIsRejectedNamingTheSource) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(2, 2, 1);
  image->SetSpacing(1.0, 0.0, 1.0);
  const std::string message = messageOf<std::invalid_argument>([&] { gridOf(image, "file s.vti"); });
  EXPECT_TRUE(contains(message, "file s.vti: grid spacing along y is 0"));
}

TEST(ImageDataAdapter, MissingArrayErrorListsTheArraysPresent) {
  vtkSmartPointer<vtkImageData> image = toImageData(sampleSet());
  try {
    vectorFieldFrom(image, "foo", "file X");
    FAIL() << "expected DataArrayError";
  } catch (const DataArrayError& e) {
    EXPECT_EQ(std::string(e.what()),
              "file X: no point-data array 'foo'; arrays present: velocity(3), density(1)");
    EXPECT_EQ(e.arrayName(), "foo");
  }
}

TEST(ImageDataAdapter, CellArrayIsPointedOutWhenPointArrayIsMissing) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(2, 2, 1);
  vtkNew<vtkDoubleArray> p;
  p->SetName("pressure");
  p->InsertNextValue(1.0);
  image->GetCellData()->AddArray(p);
  const std::string message = messageOf<DataArrayError>([&] { scalarFieldFrom(image, "pressure"); });
  EXPECT_TRUE(contains(message, "arrays present: none"));
  EXPECT_TRUE(contains(message, "'pressure' is a cell-data array"));
}

TEST(ImageDataAdapter, WrongComponentCountsAreRejectedWhenAskedForByName) {
  vtkSmartPointer<vtkImageData> image = toImageData(sampleSet());
  EXPECT_EQ(messageOf<DataArrayError>([&] { vectorFieldFrom(image, "density", "file X"); }),
            "file X: array 'density' has 1 component; a vector field needs 2 or 3");
  EXPECT_EQ(messageOf<DataArrayError>([&] { scalarFieldFrom(image, "velocity", "file X"); }),
            "file X: array 'velocity' has 3 components; a scalar field needs 1");
  vtkSmartPointer<vtkImageData> mixed = mixedImage();
  EXPECT_EQ(messageOf<DataArrayError>([&] { vectorFieldFrom(mixed, "stress", "file X"); }),
            "file X: array 'stress' has 9 components; a vector field needs 2 or 3");
}

TEST(ImageDataAdapter, NamedFieldsAreConvertedExactly) {
  const FieldSet set = sampleSet();
  vtkSmartPointer<vtkImageData> image = toImageData(set);
  const VectorField v = vectorFieldFrom(image, "velocity");
  const ScalarField s = scalarFieldFrom(image, "density");
  EXPECT_TRUE(v.grid.sameShape(set.grid));
  ASSERT_EQ(v.values.size(), set.grid.nodeCount());
  for (std::size_t n = 0; n < v.values.size(); ++n) {
    EXPECT_EQ(v.values[n], set.vectors[0].values[n]) << "node " << n;
    EXPECT_EQ(s.values[n], set.scalars[0].values[n]) << "node " << n;
  }
  const VectorField planar = vectorFieldFrom(mixedImage(), "velocity");
  EXPECT_NEAR(planar.values[3].x(), 0.3, 1e-7);
  EXPECT_EQ(planar.values[3].z(), 0.0);
}

TEST(ImageDataAdapter, ArrayShorterThanTheGridIsRejected) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(3, 2, 1);
  vtkNew<vtkDoubleArray> short4;
  short4->SetName("p");
  for (int n = 0; n < 4; ++n) short4->InsertNextValue(n);
  image->GetPointData()->AddArray(short4);
  const std::string message = messageOf<DataArrayError>([&] { fromImageData(image, "file d.vti"); });
  EXPECT_TRUE(contains(message, "file d.vti: array 'p' has 4 tuples"));
  EXPECT_TRUE(contains(message, "has 6 points"));
}

TEST(VtkMessageCollector, VtkPrefixIsStrippedFromMessages) {
  EXPECT_EQ(conciseVtkMessage("vtkXMLImageDataReader (0x55d0a0): Error reading file\n\n"),
            "Error reading file");
  EXPECT_EQ(conciseVtkMessage("ERROR: In ./IO/Core/vtkZLibDataCompressor.cxx, line 69\n"
                              "vtkZLibDataCompressor (0x5605311c63c0): Zlib error\n\n"),
            "Zlib error");
  EXPECT_EQ(conciseVtkMessage("  plain text (not VTK): kept  "), "plain text (not VTK): kept");
}

namespace {

// ParaView sets the chosen array with an empty name while its array list is still empty (before
// the reader has run): that is no choice, and the active vectors are used.
TEST(ImageDataAdapter, AnEmptyChosenArrayNameMeansTheActiveVectors) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 1);
  for (const char* name : {"a", "b"}) {
    vtkNew<vtkDoubleArray> v;
    v->SetName(name);
    v->SetNumberOfComponents(3);
    v->SetNumberOfTuples(4);
    v->Fill(0);
    image->GetPointData()->AddArray(v);
  }
  image->GetPointData()->SetActiveVectors("b");
  vtkNew<vtkInformation> chosen;
  chosen->Set(vtkDataObject::FIELD_NAME(), "");
  EXPECT_EQ(chosenVectorArrayName(chosen, image, "test"), "b");
  chosen->Set(vtkDataObject::FIELD_NAME(), "a");
  EXPECT_EQ(chosenVectorArrayName(chosen, image, "test"), "a");
  EXPECT_EQ(chosenVectorArrayName(nullptr, image, "test"), "b");
}

}  // namespace
