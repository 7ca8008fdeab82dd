#include "filters/isosurface/vtk/Isosurface.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges2D.h>
#include <vtkFlyingEdges3D.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkTriangleFilter.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <sstream>

#include "fieldviz/vtk/ImageDataAdapter.h"

namespace fluidviz::isosurface {

namespace {

// The array to contour, checked: present, one component, no NaN, value inside its range.
vtkDataArray* contourArray(vtkImageData* image, const IsosurfaceParams& p,
                           const std::string& source) {
  vtkDataArray* a = image->GetPointData()->GetArray(p.array.c_str());
  if (a == nullptr)
    throw DataArrayError(source + ": no point-data array '" + p.array + "'; arrays present: " +
                             describePointArrays(image),
                         p.array);
  if (a->GetNumberOfComponents() != 1)
    throw DataArrayError(source + ": array '" + p.array + "' has " +
                             std::to_string(a->GetNumberOfComponents()) +
                             " components; an isosurface needs a 1-component array",
                         p.array);
  double lo = INFINITY, hi = -INFINITY;
  vtkIdType nans = 0, infinities = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
    const double v = a->GetComponent(i, 0);
    if (std::isnan(v)) ++nans;
    else if (std::isinf(v)) ++infinities;
    else lo = std::min(lo, v), hi = std::max(hi, v);
  }
  if (nans > 0)
    throw DataArrayError(source + ": array '" + p.array + "' has " + std::to_string(nans) +
                             " NaN values (for resampled particles: nodes without particle "
                             "support, mask = 0); contour 'color' or resample with an empty value",
                         p.array);
  // An infinite node puts the surface on the node itself: t = (value - a) / (inf - a) = 0.
  if (infinities > 0)
    throw DataArrayError(source + ": array '" + p.array + "' has " + std::to_string(infinities) +
                             (infinities == 1 ? " infinite value" : " infinite values") +
                             "; an isosurface needs finite values",
                         p.array);
  if (!(p.value >= lo && p.value <= hi)) {
    std::ostringstream s;
    s.precision(8);
    s << "is " << p.value << ", outside the range [" << lo << ", " << hi << "] of array '"
      << p.array << "' in " << source << ": the surface would be empty";
    throw ParamError("value", s.str());
  }
  return a;
}

// The grid edge a contour point lies on: nodes n0 and n1 (= n0 + 1 along `axis`) and the
// fraction t of the way from n0 to n1. Flying Edges puts every point on an edge, so all but one
// continuous index are whole numbers (up to the float precision of the output points).
struct EdgePoint {
  vtkIdType n0 = 0, n1 = 0;
  double t = 0.0;
};

EdgePoint edgeOf(const double x[3], vtkImageData* image) {
  int dims[3];
  double origin[3], spacing[3];
  image->GetDimensions(dims);
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  int ijk[3], axis = 0;
  double q[3], worst = -1.0;
  for (int a = 0; a < 3; ++a) {
    q[a] = dims[a] > 1 ? (x[a] - origin[a]) / spacing[a] : 0.0;
    ijk[a] = std::clamp(static_cast<int>(std::lround(q[a])), 0, dims[a] - 1);
    if (std::abs(q[a] - ijk[a]) > worst) worst = std::abs(q[a] - ijk[a]), axis = a;
  }
  ijk[axis] = std::clamp(static_cast<int>(std::floor(q[axis])), 0, std::max(0, dims[axis] - 2));
  EdgePoint e;
  e.t = dims[axis] > 1 ? std::clamp(q[axis] - ijk[axis], 0.0, 1.0) : 0.0;
  e.n0 = image->ComputePointId(ijk);
  if (dims[axis] > 1) ++ijk[axis];
  e.n1 = image->ComputePointId(ijk);
  return e;
}

// Linear along the edge; where one end is NaN the other end's value (resampled free surfaces:
// the outer node may lack particle support), NaN only if both are.
double alongEdge(double v0, double v1, double t) {
  if (std::isnan(v0)) return v1;
  if (std::isnan(v1)) return v0;
  return (1.0 - t) * v0 + t * v1;
}

// Every numeric point array of the grid (except the contoured one, which the contour carries
// already), interpolated onto the contour's points along their edges. Done here because VTK
// 9.1's vtkFlyingEdges3D::InterpolateAttributes returns wrong values for 3-component arrays
// (errors of the order of the array's range; checked by the tests) and vtkFlyingEdges2D has no
// such option.
void interpolateGridArrays(vtkPolyData* contour, vtkImageData* image, const std::string& skip) {
  const vtkIdType n = contour->GetNumberOfPoints();
  std::vector<EdgePoint> edges(n);
  for (vtkIdType i = 0; i < n; ++i) edges[i] = edgeOf(contour->GetPoint(i), image);
  vtkPointData* in = image->GetPointData();
  for (int k = 0; k < in->GetNumberOfArrays(); ++k) {
    vtkDataArray* a = in->GetArray(k);
    if (a == nullptr || a->GetName() == nullptr || skip == a->GetName()) continue;
    vtkNew<vtkDoubleArray> out;
    out->SetName(a->GetName());
    out->SetNumberOfComponents(a->GetNumberOfComponents());
    out->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        out->SetComponent(i, c, alongEdge(a->GetComponent(edges[i].n0, c),
                                          a->GetComponent(edges[i].n1, c), edges[i].t));
    contour->GetPointData()->AddArray(out);
  }
}

// vtkFlyingEdges2D (VTK 9.1) asks the image for its active scalars' component count and logs
// "No Scalar Field has been specified" when there are none, though it contours the requested
// array correctly. A shallow copy whose active scalars are that array keeps stderr clean without
// touching the caller's image.
vtkSmartPointer<vtkImageData> withActiveScalars(vtkImageData* image, const std::string& array) {
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(image);
  copy->GetPointData()->SetActiveScalars(array.c_str());
  return copy;
}

vtkSmartPointer<vtkPolyData> contour2D(vtkImageData* image, const IsosurfaceParams& p) {
  vtkNew<vtkFlyingEdges2D> fe;
  fe->SetInputData(withActiveScalars(image, p.array));
  fe->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, p.array.c_str());
  fe->SetValue(0, p.value);
  fe->SetComputeScalars(true);
  fe->Update();
  vtkSmartPointer<vtkPolyData> lines = fe->GetOutput();
  if (p.interpolate_arrays) interpolateGridArrays(lines, image, p.array);
  return lines;
}

vtkSmartPointer<vtkPolyData> contour3D(vtkImageData* image, const IsosurfaceParams& p) {
  vtkNew<vtkFlyingEdges3D> fe;
  fe->SetInputData(image);
  fe->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, p.array.c_str());
  fe->SetValue(0, p.value);
  fe->SetComputeNormals(p.normals && p.smoothing_iterations == 0);
  fe->SetComputeGradients(false);
  fe->SetComputeScalars(true);
  fe->SetInterpolateAttributes(false);  // wrong for 3-component arrays in VTK 9.1: see below
  fe->Update();
  vtkSmartPointer<vtkPolyData> surface = fe->GetOutput();
  if (p.interpolate_arrays) interpolateGridArrays(surface, image, p.array);  // before smoothing
  if (p.smoothing_iterations == 0) return surface;
  // Windowed-sinc low-pass (Taubin 1996) on normalised coordinates, then normals from triangles.
  vtkNew<vtkWindowedSincPolyDataFilter> smooth;
  smooth->SetInputData(surface);
  smooth->SetNumberOfIterations(p.smoothing_iterations);
  smooth->SetPassBand(p.smoothing_passband);
  smooth->NormalizeCoordinatesOn();
  smooth->BoundarySmoothingOff();
  smooth->FeatureEdgeSmoothingOff();
  smooth->NonManifoldSmoothingOn();
  smooth->Update();
  surface = smooth->GetOutput();
  if (!p.normals) return surface;
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(surface);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->Update();
  return normals->GetOutput();
}

}  // namespace

vtkSmartPointer<vtkPolyData> extractIsosurface(vtkImageData* image, const IsosurfaceParams& p,
                                               const std::string& source) {
  validateIsosurfaceParams(p);
  contourArray(image, p, source);
  int dims[3];
  image->GetDimensions(dims);
  return dims[2] == 1 ? contour2D(image, p) : contour3D(image, p);
}

vtkSmartPointer<vtkPolyData> extractIsosurface(const FieldSet& fields,
                                               const IsosurfaceParams& params) {
  vtkSmartPointer<vtkImageData> image = toImageData(fields);
  return extractIsosurface(image, params);
}

SurfaceMeasures measureSurface(vtkPolyData* surface) {
  SurfaceMeasures m;
  m.points = surface->GetNumberOfPoints();
  m.cells = surface->GetNumberOfCells();
  if (surface->GetNumberOfPolys() > 0) {
    vtkNew<vtkTriangleFilter> triangles;  // vtkMassProperties needs triangles only
    triangles->SetInputData(surface);
    vtkNew<vtkMassProperties> mass;
    mass->SetInputConnection(triangles->GetOutputPort());
    mass->Update();
    m.area = mass->GetSurfaceArea();
    m.volume = mass->GetVolume();
  }
  vtkCellArray* lines = surface->GetLines();
  vtkNew<vtkIdList> ids;
  for (lines->InitTraversal(); lines->GetNextCell(ids);)
    for (vtkIdType k = 1; k < ids->GetNumberOfIds(); ++k) {
      double a[3], b[3];
      surface->GetPoint(ids->GetId(k - 1), a);
      surface->GetPoint(ids->GetId(k), b);
      m.length += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                            (a[2] - b[2]) * (a[2] - b[2]));
    }
  return m;
}

}  // namespace fluidviz::isosurface
