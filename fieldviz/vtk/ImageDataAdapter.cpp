#include "fieldviz/vtk/ImageDataAdapter.h"

#include <vtkDataObject.h>

#include <vtkInformation.h>

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

namespace fluidviz {

namespace {

// ---- FieldSet -> vtkImageData ---------------------------------------------------------------

void checkFieldSize(const std::string& name, std::size_t size, const Grid& grid) {
  if (size != grid.nodeCount())
    throw std::invalid_argument("field '" + name + "' has " + std::to_string(size) +
                                " values; its grid " + grid.describe() + " has " +
                                std::to_string(grid.nodeCount()) + " nodes");
}

vtkSmartPointer<vtkDoubleArray> toArray(const ScalarField& f) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(f.name.c_str());
  a->SetNumberOfComponents(1);
  a->SetNumberOfTuples(static_cast<vtkIdType>(f.values.size()));
  std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
  return a;
}

vtkSmartPointer<vtkDoubleArray> toArray(const VectorField& f) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(f.name.c_str());
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(static_cast<vtkIdType>(f.values.size()));
  double* out = a->GetPointer(0);
  for (const Vec3& v : f.values) {
    *out++ = v.x();
    *out++ = v.y();
    *out++ = v.z();
  }
  return a;
}

// ---- vtkImageData -> FieldSet ---------------------------------------------------------------

std::string componentWord(int n) { return n == 1 ? " component" : " components"; }

bool isIdentity(vtkMatrix3x3* m) {
  if (!m) return true;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (m->GetElement(r, c) != (r == c ? 1.0 : 0.0)) return false;
  return true;
}

vtkDataArray* numericPointArray(vtkImageData* image, const std::string& name,
                                const std::string& source) {
  vtkPointData* pd = image->GetPointData();
  vtkAbstractArray* abstract = pd->GetAbstractArray(name.c_str());
  if (!abstract) {
    std::string message = source + ": no point-data array '" + name +
                          "'; arrays present: " + describePointArrays(image);
    if (image->GetCellData()->GetAbstractArray(name.c_str()))
      message += " ('" + name + "' is a cell-data array; fluidviz reads point data)";
    throw DataArrayError(message, name);
  }
  auto* numeric = vtkDataArray::SafeDownCast(abstract);
  if (!numeric)
    throw DataArrayError(source + ": array '" + name + "' is a " + abstract->GetClassName() +
                             ", not a numeric array",
                         name);
  return numeric;
}

void checkTupleCount(vtkImageData* image, vtkDataArray* a, const std::string& source) {
  if (a->GetNumberOfTuples() != image->GetNumberOfPoints())
    throw DataArrayError(source + ": array '" + a->GetName() + "' has " +
                             std::to_string(a->GetNumberOfTuples()) + " tuples; the grid " +
                             gridOf(image, source).describe() + " has " +
                             std::to_string(image->GetNumberOfPoints()) + " points",
                         a->GetName());
}

ScalarField toScalarField(vtkDataArray* a, const Grid& grid) {
  ScalarField f{a->GetName(), grid, std::vector<double>(grid.nodeCount())};
  for (vtkIdType n = 0; n < a->GetNumberOfTuples(); ++n) f.values[n] = a->GetComponent(n, 0);
  return f;
}

VectorField toVectorField(vtkDataArray* a, const Grid& grid) {
  VectorField f{a->GetName(), grid, std::vector<Vec3>(grid.nodeCount())};
  const int nc = a->GetNumberOfComponents();
  for (vtkIdType n = 0; n < a->GetNumberOfTuples(); ++n)
    f.values[n] = Vec3(a->GetComponent(n, 0), a->GetComponent(n, 1),
                       nc == 3 ? a->GetComponent(n, 2) : 0.0);
  return f;
}

}  // namespace

vtkSmartPointer<vtkImageData> toImageData(const FieldSet& set) {
  set.grid.validate();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(set.grid.dims.data());
  image->SetOrigin(set.grid.origin.data());
  image->SetSpacing(set.grid.spacing.data());
  vtkPointData* pd = image->GetPointData();
  for (const VectorField& v : set.vectors) {
    checkFieldSize(v.name, v.values.size(), set.grid);
    pd->AddArray(toArray(v));
  }
  for (const ScalarField& s : set.scalars) {
    checkFieldSize(s.name, s.values.size(), set.grid);
    pd->AddArray(toArray(s));
  }
  // Active attributes are what ParaView colours and glyphs by default.
  if (!set.vectors.empty()) pd->SetActiveVectors(set.vectors.front().name.c_str());
  if (!set.scalars.empty()) pd->SetActiveScalars(set.scalars.front().name.c_str());
  return image;
}

Grid gridOf(vtkImageData* image, const std::string& source) {
  if (!isIdentity(image->GetDirectionMatrix()))
    throw std::invalid_argument(source + ": the image is rotated (its direction matrix is not the "
                                "identity); fluidviz grids are axis-aligned");
  const int* extent = image->GetExtent();
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  Grid grid;
  for (int a = 0; a < 3; ++a) {
    grid.dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
    // A whole extent need not start at 0; node (0,0,0) of the grid is the extent's first point.
    grid.origin[a] = origin[a] + extent[2 * a] * spacing[a];
    grid.spacing[a] = spacing[a];
  }
  try {
    grid.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
  return grid;
}

ImageDataFields fromImageData(vtkImageData* image, const std::string& source) {
  ImageDataFields out;
  out.fields.grid = gridOf(image, source);
  vtkPointData* pd = image->GetPointData();
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* abstract = pd->GetAbstractArray(i);
    const std::string name = abstract->GetName() ? abstract->GetName() : "";
    const int nc = abstract->GetNumberOfComponents();
    auto* a = vtkDataArray::SafeDownCast(abstract);
    if (name.empty()) {
      out.skipped.push_back({name, nc, "the array has no name"});
    } else if (name == "vtkGhostType") {
      out.skipped.push_back({name, nc, "VTK's ghost-cell bookkeeping, not a field"});
    } else if (!a) {
      out.skipped.push_back({name, nc, std::string("not numeric (") + abstract->GetClassName() + ")"});
    } else if (nc < 1 || nc > 3) {
      out.skipped.push_back({name, nc, "has " + std::to_string(nc) + componentWord(nc) +
                                           "; fields need 1 (scalar), 2 or 3 (vector)"});
    } else {
      checkTupleCount(image, a, source);
      if (nc == 1)
        out.fields.add(toScalarField(a, out.fields.grid));
      else
        out.fields.add(toVectorField(a, out.fields.grid));
    }
  }
  return out;
}

VectorField vectorFieldFrom(vtkImageData* image, const std::string& arrayName,
                            const std::string& source) {
  vtkDataArray* a = numericPointArray(image, arrayName, source);
  const int nc = a->GetNumberOfComponents();
  if (nc != 2 && nc != 3)
    throw DataArrayError(source + ": array '" + arrayName + "' has " + std::to_string(nc) +
                             componentWord(nc) + "; a vector field needs 2 or 3",
                         arrayName);
  checkTupleCount(image, a, source);
  return toVectorField(a, gridOf(image, source));
}

ScalarField scalarFieldFrom(vtkImageData* image, const std::string& arrayName,
                            const std::string& source) {
  vtkDataArray* a = numericPointArray(image, arrayName, source);
  const int nc = a->GetNumberOfComponents();
  if (nc != 1)
    throw DataArrayError(source + ": array '" + arrayName + "' has " + std::to_string(nc) +
                             componentWord(nc) + "; a scalar field needs 1",
                         arrayName);
  checkTupleCount(image, a, source);
  return toScalarField(a, gridOf(image, source));
}

PointMask defaultFlowMask(vtkImageData* image, const VectorField& velocity,
                          const std::string& source) {
  if (!velocity.grid.is2D()) return {};
  if (!image->GetPointData()->GetArray(kValidPointMaskArray)) return flowMask(velocity, nullptr);
  const ScalarField fluid = scalarFieldFrom(image, kValidPointMaskArray, source);
  return flowMask(velocity, &fluid);
}

void addValidPointMask(vtkImageData* image, const PointMask& masked) {
  const auto nodes = static_cast<std::size_t>(image->GetNumberOfPoints());
  const std::vector<std::uint8_t> valid = validPointFlags(masked, nodes);
  vtkNew<vtkUnsignedCharArray> flags;
  flags->SetName(kValidPointMaskArray);
  flags->SetNumberOfTuples(static_cast<vtkIdType>(valid.size()));
  for (std::size_t n = 0; n < valid.size(); ++n) flags->SetValue(static_cast<vtkIdType>(n), valid[n]);
  image->GetPointData()->AddArray(flags);
}

std::string describePointArrays(vtkImageData* image) {
  vtkPointData* pd = image->GetPointData();
  std::string list;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* a = pd->GetAbstractArray(i);
    list += (list.empty() ? "" : ", ") + std::string(a->GetName() ? a->GetName() : "(unnamed)") +
            "(" + std::to_string(a->GetNumberOfComponents()) + ")";
  }
  return list.empty() ? "none" : list;
}

void requestWholeInput(vtkInformation* in) {
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
          in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
}

std::string chosenVectorArrayName(vtkInformation* chosen, vtkImageData* image,
                                  const std::string& filter) {
  // An empty name is no choice: ParaView sends one while its array list is still empty.
  if (chosen && chosen->Has(vtkDataObject::FIELD_NAME()) &&
      *chosen->Get(vtkDataObject::FIELD_NAME()) != '\0')
    return chosen->Get(vtkDataObject::FIELD_NAME());
  vtkDataArray* vectors = image->GetPointData()->GetVectors();
  if (vectors && vectors->GetName()) return vectors->GetName();
  throw std::invalid_argument(
      filter + ": no vector array chosen (SetInputArrayToProcess) and the image has no active "
      "vectors; arrays present: " + describePointArrays(image));
}

std::string fieldDataString(vtkDataObject* data, const std::string& name) {
  vtkFieldData* fd = data == nullptr ? nullptr : data->GetFieldData();
  auto* strings = fd == nullptr ? nullptr
                                : vtkStringArray::SafeDownCast(fd->GetAbstractArray(name.c_str()));
  if (strings == nullptr || strings->GetNumberOfValues() == 0) return "";
  return strings->GetValue(0);
}

RestingWalls restingWallsOf(vtkImageData* image, const VectorField& velocity,
                            const PointMask& mask, const std::string& source) {
  RestingWalls walls;
  walls.solid = restingSolidNodes(velocity, mask);
  try {
    walls.sides = parseRestingSides(fieldDataString(image, kRestingSidesFieldData), source);
  } catch (const std::invalid_argument& e) {
    throw DataArrayError(e.what(), kRestingSidesFieldData);
  }
  return walls;
}

}  // namespace fluidviz
