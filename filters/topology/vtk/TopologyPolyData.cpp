#include "filters/topology/vtk/TopologyPolyData.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <cmath>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/VectorFieldTopology.h"
#include "filters/topology/VolumeTopology.h"

namespace fluidviz::topology {

namespace {

constexpr CriticalPointType kAllTypes[] = {
    CriticalPointType::Saddle,       CriticalPointType::Source,     CriticalPointType::Sink,
    CriticalPointType::SpiralSource, CriticalPointType::SpiralSink, CriticalPointType::Centre,
    CriticalPointType::MonkeySaddle, CriticalPointType::SaddleNode, CriticalPointType::Cusp,
    CriticalPointType::Dipole,       CriticalPointType::Degenerate, CriticalPointType::Unknown,
    CriticalPointType::Attachment,   CriticalPointType::Separation};

constexpr CriticalPointType3D kAllTypes3D[] = {
    CriticalPointType3D::Source,        CriticalPointType3D::Sink,
    CriticalPointType3D::Saddle1,       CriticalPointType3D::Saddle2,
    CriticalPointType3D::SpiralSource,  CriticalPointType3D::SpiralSink,
    CriticalPointType3D::SpiralSaddle1, CriticalPointType3D::SpiralSaddle2,
    CriticalPointType3D::Centre,        CriticalPointType3D::Degenerate,
    CriticalPointType3D::Unknown};

constexpr SeparatrixEnd kAllEnds[] = {SeparatrixEnd::CriticalPoint, SeparatrixEnd::Boundary,
                                      SeparatrixEnd::Length, SeparatrixEnd::Stagnation,
                                      SeparatrixEnd::Other, SeparatrixEnd::Mask};

constexpr SurfaceEnd kAllSurfaceEnds[] = {SurfaceEnd::front_ended, SurfaceEnd::max_length,
                                          SurfaceEnd::max_triangles};

template <class A>
vtkSmartPointer<A> namedArray(const char* name) {
  auto a = vtkSmartPointer<A>::New();
  a->SetName(name);
  return a;
}

// The legend of an enum's integer codes, so that ParaView users can read them.
template <class E, std::size_t N>
vtkSmartPointer<vtkStringArray> codeNames(const char* name, const E (&all)[N]) {
  auto names = namedArray<vtkStringArray>(name);
  for (E e : all) names->InsertValue(static_cast<vtkIdType>(e), toString(e));
  return names;
}

}  // namespace

vtkSmartPointer<vtkPolyData> criticalPointsToPolyData(const std::vector<CriticalPoint>& points) {
  vtkNew<vtkPoints> xyz;
  xyz->SetDataTypeToDouble();
  vtkNew<vtkCellArray> verts;
  auto type = namedArray<vtkStringArray>("type");
  auto typeCode = namedArray<vtkIntArray>("type_code"), index = namedArray<vtkIntArray>("index"),
       morse = namedArray<vtkIntArray>("morse"), hyperbolic = namedArray<vtkIntArray>("hyperbolic"),
       elliptic = namedArray<vtkIntArray>("elliptic"),
       parabolic = namedArray<vtkIntArray>("parabolic"),
       measured = namedArray<vtkIntArray>("index_measured"),
       cluster = namedArray<vtkIntArray>("cluster_size");
  auto det = namedArray<vtkDoubleArray>("det"), trace = namedArray<vtkDoubleArray>("trace"),
       normalizedDet = namedArray<vtkDoubleArray>("normalized_det");
  for (const CriticalPoint& p : points) {
    const vtkIdType id = xyz->InsertNextPoint(p.position.data());
    verts->InsertNextCell(1, &id);
    type->InsertNextValue(p.typeName());
    typeCode->InsertNextValue(static_cast<int>(p.type));
    index->InsertNextValue(p.index);
    morse->InsertNextValue(p.morse ? 1 : 0);
    det->InsertNextValue(p.det);
    trace->InsertNextValue(p.trace);
    normalizedDet->InsertNextValue(p.normalized_det);
    hyperbolic->InsertNextValue(p.sectors.hyperbolic);
    elliptic->InsertNextValue(p.sectors.elliptic);
    parabolic->InsertNextValue(p.sectors.parabolic);
    measured->InsertNextValue(p.index_measured ? 1 : 0);
    cluster->InsertNextValue(p.cluster_size);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(xyz);
  out->SetVerts(verts);
  vtkPointData* pd = out->GetPointData();
  for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{
           type, typeCode, index, morse, det, trace, normalizedDet, hyperbolic, elliptic,
           parabolic, measured, cluster})
    pd->AddArray(a);
  out->GetFieldData()->AddArray(codeNames("type_names", kAllTypes));
  return out;
}

vtkSmartPointer<vtkPolyData> criticalPoints3DToPolyData(const std::vector<CriticalPoint3D>& points) {
  vtkNew<vtkPoints> xyz;
  xyz->SetDataTypeToDouble();
  vtkNew<vtkCellArray> verts;
  auto type = namedArray<vtkStringArray>("type");
  auto typeCode = namedArray<vtkIntArray>("type_code"), index = namedArray<vtkIntArray>("index"),
       morse = namedArray<vtkIntArray>("morse"), measured = namedArray<vtkIntArray>("index_measured"),
       cluster = namedArray<vtkIntArray>("cluster_size");
  auto det = namedArray<vtkDoubleArray>("det"), trace = namedArray<vtkDoubleArray>("trace"),
       normalizedDet = namedArray<vtkDoubleArray>("normalized_det"),
       eigenReal = namedArray<vtkDoubleArray>("eigenvalues_real"),
       eigenImag = namedArray<vtkDoubleArray>("eigenvalues_imag"),
       jacobian = namedArray<vtkDoubleArray>("jacobian"),
       sphere = namedArray<vtkDoubleArray>("sphere_radius");
  eigenReal->SetNumberOfComponents(3);
  eigenImag->SetNumberOfComponents(3);
  jacobian->SetNumberOfComponents(9);
  for (const CriticalPoint3D& p : points) {
    const vtkIdType id = xyz->InsertNextPoint(p.position.data());
    verts->InsertNextCell(1, &id);
    type->InsertNextValue(p.typeName());
    typeCode->InsertNextValue(static_cast<int>(p.type));
    index->InsertNextValue(p.index);
    morse->InsertNextValue(p.morse ? 1 : 0);
    det->InsertNextValue(p.det);
    trace->InsertNextValue(p.trace);
    normalizedDet->InsertNextValue(p.normalized_det);
    measured->InsertNextValue(p.index_measured ? 1 : 0);
    cluster->InsertNextValue(p.cluster_size);
    sphere->InsertNextValue(p.sphere_radius);
    const double re[3] = {p.eigenvalues[0].real(), p.eigenvalues[1].real(), p.eigenvalues[2].real()};
    const double im[3] = {p.eigenvalues[0].imag(), p.eigenvalues[1].imag(), p.eigenvalues[2].imag()};
    eigenReal->InsertNextTuple(re);
    eigenImag->InsertNextTuple(im);
    double j[9];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) j[3 * r + c] = p.jacobian(r, c);
    jacobian->InsertNextTuple(j);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(xyz);
  out->SetVerts(verts);
  vtkPointData* pd = out->GetPointData();
  for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{
           type, typeCode, index, morse, det, trace, normalizedDet, measured, cluster,
           eigenReal, eigenImag, jacobian, sphere})
    pd->AddArray(a);
  out->GetFieldData()->AddArray(codeNames("type_names", kAllTypes3D));
  return out;
}

namespace {
bool outgoingOf(const Separatrix& s) { return s.start.outflow; }
bool outgoingOf(const Separatrix3D& s) { return s.outgoing; }

template <class Line>
vtkSmartPointer<vtkPolyData> linesToPolyData(const std::vector<Line>& separatrices) {
  vtkNew<vtkPoints> xyz;
  xyz->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  auto origin = namedArray<vtkIntArray>("origin"), outgoing = namedArray<vtkIntArray>("outgoing"),
       end = namedArray<vtkIntArray>("end"), endPoint = namedArray<vtkIntArray>("end_point");
  for (const Line& s : separatrices) {
    if (s.points.size() < 2) continue;
    lines->InsertNextCell(static_cast<vtkIdType>(s.points.size()));
    for (const Vec3& p : s.points) lines->InsertCellPoint(xyz->InsertNextPoint(p.data()));
    origin->InsertNextValue(s.origin);
    outgoing->InsertNextValue(outgoingOf(s) ? 1 : 0);
    end->InsertNextValue(static_cast<int>(s.end));
    endPoint->InsertNextValue(s.end == SeparatrixEnd::CriticalPoint ? s.end_point : -1);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(xyz);
  out->SetLines(lines);
  for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{origin, outgoing, end, endPoint})
    out->GetCellData()->AddArray(a);
  out->GetFieldData()->AddArray(codeNames("end_names", kAllEnds));
  return out;
}
}  // namespace

vtkSmartPointer<vtkPolyData> separatricesToPolyData(const std::vector<Separatrix>& separatrices) {
  return linesToPolyData(separatrices);
}

vtkSmartPointer<vtkPolyData> separatrices3DToPolyData(
    const std::vector<Separatrix3D>& separatrices) {
  return linesToPolyData(separatrices);
}

vtkSmartPointer<vtkPolyData> separatingSurfacesToPolyData(
    const std::vector<SeparatingSurface>& surfaces) {
  vtkNew<vtkPoints> xyz;
  xyz->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  auto surface = namedArray<vtkIntArray>("surface"), origin = namedArray<vtkIntArray>("origin"),
       outgoing = namedArray<vtkIntArray>("outgoing"), end = namedArray<vtkIntArray>("surface_end");
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    const SeparatingSurface& s = surfaces[k];
    const vtkIdType first = xyz->GetNumberOfPoints();
    for (const Vec3& p : s.points) xyz->InsertNextPoint(p.data());
    for (const auto& t : s.triangles) {
      const vtkIdType ids[3] = {first + t[0], first + t[1], first + t[2]};
      polys->InsertNextCell(3, ids);
      surface->InsertNextValue(static_cast<int>(k));
      origin->InsertNextValue(s.origin);
      outgoing->InsertNextValue(s.outgoing ? 1 : 0);
    }
    end->InsertNextValue(static_cast<int>(s.end));
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(xyz);
  out->SetPolys(polys);
  for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{surface, origin, outgoing})
    out->GetCellData()->AddArray(a);
  out->GetFieldData()->AddArray(end);
  out->GetFieldData()->AddArray(codeNames("surface_end_names", kAllSurfaceEnds));
  return out;
}

void requireFiniteSlice(const VectorField& field, int slice, const std::string& source) {
  const Grid& g = field.grid;
  if (slice < 0 || slice >= g.dims[2]) return;  // PlanarField reports the slice itself
  for (int j = 0; j < g.dims[1]; ++j)
    for (int i = 0; i < g.dims[0]; ++i) {
      const Vec3& v = field.values[g.index(i, j, slice)];
      if (std::isfinite(v.x()) && std::isfinite(v.y())) continue;
      throw DataArrayError(source + ": array '" + field.name + "' has a non-finite value (" +
                               std::to_string(v.x()) + ", " + std::to_string(v.y()) +
                               ") at node (" + std::to_string(i) + ", " + std::to_string(j) +
                               ", " + std::to_string(slice) +
                               "); critical points need a finite field (fill or crop the "
                               "missing values first)",
                           field.name);
    }
}

TopologyResult computeTopology(vtkImageData* image, const std::string& arrayName,
                               const TopologyParams& params, bool withSeparatrices,
                               const std::string& source) {
  TopologyResult r;
  r.field = vectorFieldFrom(image, arrayName, source);
  const PointMask mask = defaultFlowMask(image, r.field, source);
  if (mask.empty()) requireFiniteSlice(r.field, params.slice_index, source);
  const VectorField analysed = mask.empty() ? r.field : withWallLayerContinued(r.field, mask);
  const RestingWalls walls = r.field.grid.is2D() ? restingWallsOf(image, r.field, mask, source)
                                                 : RestingWalls{};
  r.points = findCriticalPointsInFluid(analysed, mask, params, walls);
  if (withSeparatrices) r.separatrices = computeSeparatrices(analysed, r.points, params);
  r.pointsPolyData = criticalPointsToPolyData(r.points);
  r.separatricesPolyData = separatricesToPolyData(r.separatrices);
  return r;
}

Topology3DResult computeTopology3D(vtkImageData* image, const std::string& arrayName,
                                   const TopologyParams& params, bool withSeparatrices,
                                   const std::string& source, bool withSurfaces) {
  Topology3DResult r;
  r.field = vectorFieldFrom(image, arrayName, source);
  PointMask mask = nonFiniteNodes(r.field);
  if (image->GetPointData()->GetArray(kValidPointMaskArray))
    addMask(mask, zeroNodes(scalarFieldFrom(image, kValidPointMaskArray, source)));
  const VectorField analysed = maskedCount(mask) ? withMaskedNaN(r.field, mask) : r.field;
  r.points = findCriticalPoints3D(analysed, params);
  if (withSeparatrices) r.separatrices = computeSeparatrices3D(analysed, r.points, params);
  if (withSurfaces) r.surfaces = computeSeparatingSurfaces(analysed, r.points, params);
  r.pointsPolyData = criticalPoints3DToPolyData(r.points);
  r.separatricesPolyData = separatrices3DToPolyData(r.separatrices);
  r.surfacesPolyData = separatingSurfacesToPolyData(r.surfaces);
  return r;
}

}  // namespace fluidviz::topology
