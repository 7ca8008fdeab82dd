// fvLicFilter in a VTK pipeline: the output geometry is announced before the convolution runs,
// the texture equals the core's exactly, masked nodes are those the CLI masks, and bad input is
// reported with the array's name.
#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <limits>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "filters/lic/vtk/LicImageData.h"
#include "filters/lic/vtk/fvLicFilter.h"

namespace fluidviz::lic {
namespace {

// Rotation about (0.5, 0.25) on a 33 x 17 grid over [0, 1] x [0, 0.5].
VectorField vortex() {
  VectorField v{"velocity", {}, {}};
  v.grid.dims = {33, 17, 1};
  v.grid.spacing = {1.0 / 32, 0.5 / 16, 1.0};
  for (int j = 0; j < 17; ++j)
    for (int i = 0; i < 33; ++i) {
      const Vec3 p = v.grid.position(i, j);
      v.values.emplace_back(-(p.y() - 0.25), p.x() - 0.5, 0.0);
    }
  return v;
}

vtkSmartPointer<vtkImageData> imageOf(const VectorField& v) {
  FieldSet set;
  set.grid = v.grid;
  set.add(v);
  set.add(ScalarField{"density", v.grid, std::vector<double>(v.values.size(), 1.0)});
  return toImageData(set);
}

LicParams params() {
  LicParams p;
  p.width = 120;  // height from the aspect ratio: 60
  p.length = 8;
  p.mask_speed = 0.1;
  return p;
}

TEST(LicFilter, GeometryIsKnownBeforeTheConvolutionAndMatchesTheCore) {
  vtkNew<fvLicFilter> filter;
  filter->SetInputData(imageOf(vortex()));
  filter->SetParams(params());
  filter->UpdateInformation();
  vtkInformation* info = filter->GetOutputInformation(0);
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  EXPECT_EQ(std::vector<int>(extent, extent + 6), (std::vector<int>{0, 119, 0, 59, 0, 0}));
  double spacing[3], origin[3];
  info->Get(vtkDataObject::SPACING(), spacing);
  info->Get(vtkDataObject::ORIGIN(), origin);
  // Pixel centres: 1/120 m apart, the first half a pixel from the corner.
  EXPECT_DOUBLE_EQ(spacing[0], 1.0 / 120);
  EXPECT_DOUBLE_EQ(spacing[1], 0.5 / 60);
  EXPECT_DOUBLE_EQ(origin[0], 0.5 / 120);
  EXPECT_DOUBLE_EQ(origin[1], 0.25 / 60);

  filter->Update();
  vtkImageData* out = filter->GetOutput();
  const LicImage expected = computeLic(vortex(), params());
  const Grid grid = gridOf(out);
  EXPECT_TRUE(grid.sameShape(expected.texture.grid));
  auto* lic = out->GetPointData()->GetArray("lic");
  auto* mask = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("lic_mask"));
  ASSERT_NE(lic, nullptr);
  ASSERT_NE(mask, nullptr);
  ASSERT_EQ(lic->GetNumberOfTuples(), 120 * 60);
  int masked = 0;
  for (vtkIdType n = 0; n < lic->GetNumberOfTuples(); ++n) {
    ASSERT_EQ(lic->GetTuple1(n), expected.texture.values[n]) << "pixel " << n;
    ASSERT_EQ(mask->GetValue(n), expected.mask[n]) << "pixel " << n;
    masked += mask->GetValue(n);
  }
  // |v| = r <= 0.1 max|v| (max at the corners, r = 0.559): a disc of radius 0.0559 m around the
  // centre, pi (0.0559 * 120)^2 = 141 px.
  EXPECT_NEAR(masked, 141, 15);
}

class LicFilterErrors : public ::testing::Test {
 protected:
  void SetUp() override { vtkObject::GlobalWarningDisplayOff(); }
  void TearDown() override { vtkObject::GlobalWarningDisplayOn(); }
};

// Pixels of `image`'s lic_mask that are set.
int maskedPixels(vtkImageData* image) {
  auto* mask = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetArray("lic_mask"));
  int count = 0;
  for (vtkIdType n = 0; n < mask->GetNumberOfTuples(); ++n) count += mask->GetValue(n);
  return count;
}

// Masked pixels of the filter's texture of the unchanged vortex (its slow centre).
int unmaskedFilterMaskedPixels() {
  vtkNew<fvLicFilter> filter;
  filter->SetInputData(imageOf(vortex()));
  filter->SetParams(params());
  filter->Update();
  return maskedPixels(filter->GetOutput());
}

// The filter masks what `fluidviz lic` masks (defaultFlowMask): the texture equals the core's
// with that mask, pixel for pixel.
void expectCoreTextureWithMask(vtkImageData* out, const VectorField& v, const PointMask& mask) {
  const LicImage expected = computeLic(v, params(), mask);
  auto* lic = out->GetPointData()->GetArray("lic");
  auto* licMask = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("lic_mask"));
  ASSERT_EQ(lic->GetNumberOfTuples(), static_cast<vtkIdType>(expected.texture.values.size()));
  for (vtkIdType n = 0; n < lic->GetNumberOfTuples(); ++n) {
    ASSERT_EQ(lic->GetTuple1(n), expected.texture.values[n]) << "pixel " << n;
    ASSERT_EQ(licMask->GetValue(n), expected.mask[n]) << "pixel " << n;
  }
}

TEST(LicFilter, NaNNodesAreMaskedAsTheCommandMasksThem) {
  VectorField v = vortex();
  v.values[40] = Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0);  // node (7, 1)
  vtkNew<fvLicFilter> filter;
  filter->SetInputData(imageOf(v));
  filter->SetParams(params());
  filter->Update();
  ASSERT_EQ(filter->GetLastError(), "");
  PointMask nan(v.values.size(), 0);
  nan[40] = 1;
  expectCoreTextureWithMask(filter->GetOutput(), v, nan);
  // Beyond the vortex's slow centre, the pixels where the bilinear mask is >= 1/2 around node
  // (7, 1): 4 (1 - ln 2) / 2 = 0.614 of a cell, of 3.75 x 3.75 px: 8.6 px.
  EXPECT_NEAR(maskedPixels(filter->GetOutput()) - unmaskedFilterMaskedPixels(), 8.6, 3);
}

TEST(LicFilter, TheImagesValidPointMaskMasksItsZeros) {
  const VectorField v = vortex();
  ScalarField valid{kValidPointMaskArray, v.grid, std::vector<double>(v.values.size(), 1.0)};
  PointMask block(v.values.size(), 0);
  for (int j = 2; j <= 5; ++j)
    for (int i = 2; i <= 9; ++i) valid.values[v.grid.index(i, j)] = 0.0, block[v.grid.index(i, j)] = 1;
  vtkSmartPointer<vtkImageData> image = imageOf(v);
  FieldSet extra;
  extra.grid = v.grid;
  extra.add(valid);
  image->GetPointData()->AddArray(toImageData(extra)->GetPointData()->GetArray(kValidPointMaskArray));
  vtkNew<fvLicFilter> filter;
  filter->SetInputData(image);
  filter->SetParams(params());
  filter->Update();
  ASSERT_EQ(filter->GetLastError(), "");
  expectCoreTextureWithMask(filter->GetOutput(), v, block);
  // Beyond the vortex's slow centre: a block of 8 x 4 nodes masks up to half a cell beyond its
  // nodes, 8 x 4 cells of 3.75 x 3.75 px = 450 px, less its rounded corners (0.25 - 0.153 of a
  // cell each, 5 px in all).
  EXPECT_NEAR(maskedPixels(filter->GetOutput()) - unmaskedFilterMaskedPixels(), 445, 8);
}

TEST_F(LicFilterErrors, ScalarArraysAreReportedWithTheArrayName) {
  vtkNew<fvLicFilter> filter;
  filter->SetInputData(imageOf(vortex()));
  filter->SetParams(params());
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "density");
  filter->Update();
  EXPECT_NE(filter->GetLastError().find("array 'density' has 1 component"), std::string::npos)
      << filter->GetLastError();
}

}  // namespace
}  // namespace fluidviz::lic
