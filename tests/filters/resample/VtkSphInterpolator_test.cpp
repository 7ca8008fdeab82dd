// Agreement with VTK's vtkSPHInterpolator on the same particles, grid, kernel and volumes.
//
// Matching the two: VTK's kernels take the smoothing length h as SpatialStep and cut off at
// CutoffFactor h, 2h for vtkSPHCubicKernel (the M4 cubic spline, sigma 10/(7 pi), 1/pi) and for
// vtkWendlandQuinticKernel (Wendland C2 in VTK's naming, sigma 7/(4 pi), 21/(16 pi)): the same
// functions as solvers/sph's KernelCubicSpline and KernelWendlandC2. With mass and density
// arrays named, VTK uses V_j = m_j / rho_j; without, V_j = h^d (its DefaultVolume). With
// ShepardNormalization on it divides every interpolated array by its "Shepard Summation"
// sum_j V_j W_j, our eq. (2); the summation itself is our colour field (1). VTK stores that sum
// as float, so the two agree to ~6e-8 relative; the issue asks for 1e-6 where both have support
// (both sums > 0).
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSPHCubicKernel.h>
#include <vtkSPHInterpolator.h>
#include <vtkWendlandQuinticKernel.h>

#include <cmath>

#include "filters/resample/ParticleResampler.h"
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "tests/filters/resample/ParticleClouds.h"

using namespace fluidviz;
using namespace fluidviz::resample;
using fluidviz::testing::addScalar;

namespace {

struct Agreement {
  double value = 0.0, vector = 0.0, shepard = 0.0;  // largest relative differences
  long comparedNodes = 0, nodes = 0;
};

vtkSmartPointer<vtkSPHKernel> vtkKernel(const std::string& name, double h, int dimension) {
  vtkSmartPointer<vtkSPHKernel> k;
  if (name == "cubic_spline") k = vtkSmartPointer<vtkSPHCubicKernel>::New();
  else k = vtkSmartPointer<vtkWendlandQuinticKernel>::New();
  k->SetSpatialStep(h);
  k->SetDimension(dimension);
  return k;
}

vtkSmartPointer<vtkDataSet> runVtk(const particles::ParticleSet& ps, const Grid& g, const std::string& kernel,
                                   double h, int dimension, bool volumesFromArrays) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(g.dims.data());
  image->SetOrigin(g.origin.data());
  image->SetSpacing(g.spacing.data());
  vtkNew<vtkSPHInterpolator> interp;
  interp->SetInputData(image);
  interp->SetSourceData(toPolyData(ps));
  interp->SetKernel(vtkKernel(kernel, h, dimension));
  interp->SetMassArrayName(volumesFromArrays ? "mass" : "");
  interp->SetDensityArrayName(volumesFromArrays ? "density" : "");
  interp->SetShepardNormalization(true);
  interp->Update();
  return interp->GetOutput();
}

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

Agreement compare(const ResampleResult& mine, vtkDataSet* vtk) {
  const auto& f = mine.fields.findScalar("f")->values;
  const auto& u = mine.fields.findVector("u")->values;
  const auto& c = mine.fields.findScalar("color")->values;
  vtkDataArray* vf = vtk->GetPointData()->GetArray("f");
  vtkDataArray* vu = vtk->GetPointData()->GetArray("u");
  vtkDataArray* vc = vtk->GetPointData()->GetArray("Shepard Summation");
  Agreement a;
  a.nodes = vtk->GetNumberOfPoints();
  for (vtkIdType n = 0; n < vtk->GetNumberOfPoints(); ++n) {
    if (!(c[n] > 0.0) || !(vc->GetComponent(n, 0) > 0.0)) continue;
    ++a.comparedNodes;
    a.value = std::max(a.value, relative(f[n], vf->GetComponent(n, 0)));
    a.shepard = std::max(a.shepard, relative(c[n], vc->GetComponent(n, 0)));
    for (int k = 0; k < 3; ++k)
      a.vector = std::max(a.vector, relative(u[n][k], vu->GetComponent(n, k)));
  }
  return a;
}

// A 25%-jittered block of particles with a scalar f > 0, a vector u (components > 0), and
// masses and densities that vary (so V_j = m_j / rho_j varies); grid spacing 0.7 dx, so nodes
// fall everywhere relative to the particles, and a 2h margin where support fades out.
particles::ParticleSet particles(int dimension, double dx) {
  particles::ParticleSet ps = fluidviz::testing::jitteredBox(dimension, 0.0, 1.0, dx, 0.25);
  addScalar(ps, "f", [](const Vec3& p) { return 2.0 + std::sin(3 * p.x()) + p.y() * p.z(); });
  addScalar(ps, "mass", [&](const Vec3& p) { return 1000 * std::pow(dx, dimension) * (1 + 0.2 * p.x()); });
  addScalar(ps, "density", [](const Vec3& p) { return 1000 * (1 + 0.05 * p.y()); });
  particles::ParticleVectors u{"u", {}};
  for (const Vec3& p : ps.positions) u.values.push_back(Vec3(1 + p.y(), 2 - p.x(), 1.5 + p.z()));
  ps.vectors.push_back(u);
  return ps;
}

Agreement agreement(int dimension, const std::string& kernel, bool volumesFromArrays) {
  const double dx = dimension == 3 ? 1.0 / 14 : 1.0 / 40, h = 1.3 * dx;
  const particles::ParticleSet ps = particles(dimension, dx);
  ParticleResampleParams p;
  p.kernel = fluidviz::choiceNamed<fluidviz::resample::ResampleKernel>(kernel);
  p.smoothing_length = h;
  p.spacing = 0.7 * dx;
  p.support_threshold = 0.0;
  if (!volumesFromArrays) {
    p.particle_volume = std::pow(h, dimension);  // VTK's DefaultVolume
    p.mass_array = p.density_array = "none";
  }
  const ResampleResult mine = resampleParticles(ps, p);
  return compare(mine, runVtk(ps, mine.fields.grid, kernel, h, dimension, volumesFromArrays));
}

}  // namespace

// Both have support at 16793 of the 28^3 = 21952 nodes in 3D, 3959 of 65^2 = 4225 in 2D (the
// rest lie in the margin beyond every particle's reach); the checks ask for more than half.
TEST(VtkSphInterpolator, CubicSplineAgreesWithin1e6In3D) {
  const Agreement a = agreement(3, "cubic_spline", true);
  EXPECT_GT(a.comparedNodes, 0.5 * a.nodes) << a.comparedNodes << " of " << a.nodes;
  EXPECT_LT(a.value, 1e-6);
  EXPECT_LT(a.vector, 1e-6);
  EXPECT_LT(a.shepard, 1e-6);
}

TEST(VtkSphInterpolator, WendlandAgreesWithin1e6In3D) {
  const Agreement a = agreement(3, "wendland_c2", true);
  EXPECT_GT(a.comparedNodes, 0.5 * a.nodes) << a.comparedNodes << " of " << a.nodes;
  EXPECT_LT(a.value, 1e-6);
  EXPECT_LT(a.vector, 1e-6);
  EXPECT_LT(a.shepard, 1e-6);
}

TEST(VtkSphInterpolator, CubicSplineAgreesWithin1e6In2D) {
  const Agreement a = agreement(2, "cubic_spline", true);
  EXPECT_GT(a.comparedNodes, 0.5 * a.nodes) << a.comparedNodes << " of " << a.nodes;
  EXPECT_LT(a.value, 1e-6);
  EXPECT_LT(a.shepard, 1e-6);
}

// Without mass and density VTK gives every particle h^d; so do we when told to: the colour
// field equals VTK's Shepard summation.
TEST(VtkSphInterpolator, UniformVolumesAgreeWithin1e6) {
  const Agreement a = agreement(3, "cubic_spline", false);
  EXPECT_GT(a.comparedNodes, 0.5 * a.nodes) << a.comparedNodes << " of " << a.nodes;
  EXPECT_LT(a.value, 1e-6);
  EXPECT_LT(a.shepard, 1e-6);
}
