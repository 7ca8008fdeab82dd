// Particle sets <-> vtkPolyData and reading .vtp particle files: arrays kept exactly, arrays
// that cannot be particle arrays listed with the reason, errors naming file and array.
#include <gtest/gtest.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <filesystem>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "filters/resample/vtk/ParticleSetVtk.h"

using namespace fluidviz;
using namespace fluidviz::resample;
namespace fs = std::filesystem;

namespace {

particles::ParticleSet threeParticles() {
  particles::ParticleSet ps;
  ps.positions = {Vec3(0.1, 0.2, 0.3), Vec3(-1.5, 2.0, 0.3), Vec3(1e-3, 7.0, 0.3)};
  ps.scalars.push_back({"pressure", {1.5, -2.25, 1e5}});
  ps.vectors.push_back({"velocity", {Vec3(1, 2, 3), Vec3(-1, 0, 0.5), Vec3(0, 0, 1e-9)}});
  return ps;
}

}  // namespace

TEST(ParticleSetVtk, RoundTripKeepsPositionsAndArraysExactly) {
  const particles::ParticleSet ps = threeParticles();
  vtkSmartPointer<vtkPolyData> poly = toPolyData(ps);
  EXPECT_EQ(poly->GetNumberOfVerts(), 3);
  const particles::ParticleSet back = particleSetFromPolyData(poly, "test");
  EXPECT_EQ(back.positions, ps.positions);
  ASSERT_NE(back.findScalar("pressure"), nullptr);
  EXPECT_EQ(back.findScalar("pressure")->values, ps.scalars[0].values);
  ASSERT_NE(back.findVector("velocity"), nullptr);
  EXPECT_EQ(back.findVector("velocity")->values, ps.vectors[0].values);
  EXPECT_EQ(back.dimension, 2);  // all at z = 0.3
}

TEST(ParticleSetVtk, OddArraysAreSkippedWithTheReason) {
  vtkSmartPointer<vtkPolyData> poly = toPolyData(threeParticles());
  vtkNew<vtkFloatArray> uv;  // 2 components -> vector with z = 0
  uv->SetName("uv");
  uv->SetNumberOfComponents(2);
  for (int i = 0; i < 3; ++i) uv->InsertNextTuple2(i, -i);
  vtkNew<vtkDoubleArray> tensor;
  tensor->SetName("stress");
  tensor->SetNumberOfComponents(9);
  tensor->SetNumberOfTuples(3);
  vtkNew<vtkStringArray> label;
  label->SetName("label");
  for (const char* s : {"a", "b", "c"}) label->InsertNextValue(s);
  poly->GetPointData()->AddArray(uv);
  poly->GetPointData()->AddArray(tensor);
  poly->GetPointData()->AddArray(label);
  std::vector<SkippedArray> skipped;
  const particles::ParticleSet ps = particleSetFromPolyData(poly, "test", &skipped);
  ASSERT_NE(ps.findVector("uv"), nullptr);
  EXPECT_EQ(ps.findVector("uv")->values[2], Vec3(2, -2, 0));
  ASSERT_EQ(skipped.size(), 2u);
  EXPECT_EQ(skipped[0].name, "stress");
  EXPECT_EQ(skipped[0].reason, "needs 1, 2 or 3 components");
  EXPECT_EQ(skipped[1].name, "label");
  EXPECT_EQ(skipped[1].reason, "not numeric");
}

TEST(ParticleSetVtk, ArrayOfWrongLengthIsNamed) {
  vtkSmartPointer<vtkPolyData> poly = toPolyData(threeParticles());
  vtkNew<vtkDoubleArray> bad;
  bad->SetName("temperature");
  bad->SetNumberOfValues(2);
  poly->GetPointData()->AddArray(bad);
  try {
    particleSetFromPolyData(poly, "file x.vtp");
    ADD_FAILURE() << "no DataArrayError";
  } catch (const DataArrayError& e) {
    EXPECT_EQ(e.arrayName(), "temperature");
    EXPECT_STREQ(e.what(), "file x.vtp: point array 'temperature' has 2 tuples for 3 points");
  }
}

TEST(ParticleSetVtk, FilesWithoutParticlesAreFileErrors) {
  const fs::path dir = fs::temp_directory_path() / "fluidviz_particle_set_vtk";
  fs::create_directories(dir);
  EXPECT_THROW(readParticleVtp(dir / "missing.vtp"), FileError);
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkPoints> none;
  empty->SetPoints(none);
  writeVtp(empty, dir / "empty.vtp");
  try {
    readParticleVtp(dir / "empty.vtp");
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("empty.vtp: has no points (particles) to resample"),
              std::string::npos)
        << e.what();
  }
  fs::remove_all(dir);
}
