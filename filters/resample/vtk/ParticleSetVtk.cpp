#include "filters/resample/vtk/ParticleSetVtk.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace fluidviz::resample {

namespace {

// Adds one point-data array to the set, or records why it cannot be a particle array.
void addArray(vtkDataArray* a, vtkIdType n, const std::string& source, particles::ParticleSet& ps,
              std::vector<SkippedArray>* skipped) {
  const int c = a->GetNumberOfComponents();
  const std::string name = a->GetName() ? a->GetName() : "";
  if (name.empty() || c < 1 || c > 3) {
    if (skipped)
      skipped->push_back({name, c, name.empty() ? "unnamed" : "needs 1, 2 or 3 components"});
    return;
  }
  if (a->GetNumberOfTuples() != n)
    throw DataArrayError(source + ": point array '" + name + "' has " +
                             std::to_string(a->GetNumberOfTuples()) + " tuples for " +
                             std::to_string(n) + " points",
                         name);
  if (c == 1) {
    particles::ParticleScalars s{name, std::vector<double>(n)};
    for (vtkIdType i = 0; i < n; ++i) s.values[i] = a->GetComponent(i, 0);
    ps.scalars.push_back(std::move(s));
    return;
  }
  particles::ParticleVectors v{name, std::vector<Vec3>(n, Vec3::Zero())};
  for (vtkIdType i = 0; i < n; ++i)
    for (int k = 0; k < c; ++k) v.values[i][k] = a->GetComponent(i, k);
  ps.vectors.push_back(std::move(v));
}

}  // namespace

particles::ParticleSet particleSetFromPolyData(vtkPolyData* poly, const std::string& source,
                                         std::vector<SkippedArray>* skipped) {
  particles::ParticleSet ps;
  const vtkIdType n = poly->GetNumberOfPoints();
  ps.positions.resize(n);
  for (vtkIdType i = 0; i < n; ++i) poly->GetPoint(i, ps.positions[i].data());
  bool flat = true;
  for (vtkIdType i = 1; i < n && flat; ++i) flat = ps.positions[i].z() == ps.positions[0].z();
  ps.dimension = flat ? 2 : 3;
  vtkPointData* pd = poly->GetPointData();
  for (int k = 0; k < pd->GetNumberOfArrays(); ++k) {
    vtkDataArray* a = pd->GetArray(k);
    if (a == nullptr) {  // not numeric (e.g. strings)
      vtkAbstractArray* any = pd->GetAbstractArray(k);
      if (skipped && any)
        skipped->push_back({any->GetName() ? any->GetName() : "",
                            any->GetNumberOfComponents(), "not numeric"});
      continue;
    }
    addArray(a, n, source, ps, skipped);
  }
  return ps;
}

vtkSmartPointer<vtkPolyData> toPolyData(const particles::ParticleSet& ps) {
  const vtkIdType n = static_cast<vtkIdType>(ps.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i) points->SetPoint(i, ps.positions[i].data());
  vtkNew<vtkCellArray> verts;
  for (vtkIdType i = 0; i < n; ++i) verts->InsertNextCell(1, &i);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  for (const auto& s : ps.scalars) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(s.name.c_str());
    a->SetNumberOfValues(n);
    for (vtkIdType i = 0; i < n; ++i) a->SetValue(i, s.values[i]);
    poly->GetPointData()->AddArray(a);
  }
  for (const auto& v : ps.vectors) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(v.name.c_str());
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i) a->SetTuple(i, v.values[i].data());
    poly->GetPointData()->AddArray(a);
  }
  return poly;
}

}  // namespace fluidviz::resample
