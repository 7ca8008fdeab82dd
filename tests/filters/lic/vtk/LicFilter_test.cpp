// fvLicFilter in a VTK pipeline: the output geometry is announced before the convolution runs,
// the texture equals the core's exactly, and bad input is reported with the array's name.
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

TEST_F(LicFilterErrors, NaNAndScalarArraysAreReportedWithTheArrayName) {
  VectorField v = vortex();
  v.values[40] = Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  vtkNew<fvLicFilter> filter;
  filter->SetInputData(imageOf(v));
  filter->SetParams(params());
  filter->Update();
  EXPECT_NE(filter->GetLastError().find("vector field 'velocity' has a NaN or infinite value at "
                                        "node (7, 1, 0)"),
            std::string::npos)
      << filter->GetLastError();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "density");
  filter->Update();
  EXPECT_NE(filter->GetLastError().find("array 'density' has 1 component"), std::string::npos)
      << filter->GetLastError();
}

}  // namespace
}  // namespace fluidviz::lic
