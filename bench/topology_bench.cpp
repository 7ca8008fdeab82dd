// Topology core on a 1024 x 1024 field: detection + index + classification of all critical
// points (findCriticalPoints), the stream function with its critical points, and separatrices,
// with a machine-normalising baseline measured in the same run: one pass computing |v| over the
// field (fieldviz::magnitude).
// Peer: VTK 9.1's vtkVectorFieldTopology on the same field, critical points only. VTK 9.1 has
// no switch that turns its separatrices off, so they are cut to one integration step
// (SetMaxNumSteps(1)); its time is then triangulation + per-triangle zeros + gradient-based
// classification (+ a negligible stub of separatrix seeding). Printed: the speed-up of
// findCriticalPoints (detection + index loops + sectors + classification, all threads) over it,
// target >= 10, and the point counts of both (VTK's are first-order zeros of the triangle-linear
// interpolant, no clustering).
// 3D: the volume core (findCriticalPoints3D: tetrahedron zeros, clusters, index spheres,
// classification) against vtkVectorFieldTopology on a 3D image of the ABC flow with
// A = B = C = 1 (Dombre et al. 1986, stagnation points in the periodic box), 64^3 cells; the
// speed-up is printed with the same target.
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkVectorFieldTopology.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "filters/topology/ScalarCriticalPoints.h"
#include "filters/topology/Separatrices.h"
#include "filters/topology/StreamFunction.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/topology/VectorFieldTopology.h"
#include "filters/topology/VolumeTopology.h"
#include "tests/support/AnalyticFields.h"

using namespace fluidviz;
using namespace fluidviz::topology;

namespace {
using Clock = std::chrono::steady_clock;

template <class F>
double bestSeconds(int repeats, F&& f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

// Incompressible test flow on [0, 1]^2: two superposed cellular flows (about 600 critical points).
VectorField benchField(int n) {
  Grid g;
  g.dims = {n, n, 1};
  g.spacing = {1.0 / (n - 1), 1.0 / (n - 1), 1.0};
  VectorField v{"v", g, {}};
  v.values.reserve(g.nodeCount());
  const double a = 16 * std::numbers::pi, b = 11 * std::numbers::pi;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3 p = g.position(i, j);
      // psi = sin(a x) sin(a y) + 0.4 cos(b x + 0.3) sin(b y - 0.7); v = (psi_y, -psi_x)
      const double u = a * std::sin(a * p.x()) * std::cos(a * p.y()) +
                       0.4 * b * std::cos(b * p.x() + 0.3) * std::cos(b * p.y() - 0.7);
      const double w = -a * std::cos(a * p.x()) * std::sin(a * p.y()) +
                       0.4 * b * std::sin(b * p.x() + 0.3) * std::sin(b * p.y() - 0.7);
      v.values.emplace_back(u, w, 0.0);
    }
  return v;
}
// vtkVectorFieldTopology's critical points of `field` (separatrices cut to one step).
vtkIdType vtkCriticalPointCount(vtkImageData* image) {
  vtkNew<vtkVectorFieldTopology> vtk;
  vtk->SetInputData(image);
  vtk->SetMaxNumSteps(1);
  vtk->Update();
  return vtk->GetOutput(0)->GetNumberOfPoints();
}

void bench3D() {
  const VectorField field = fluidviz::testing::abcFlow(65, 1.0, 1.0, 1.0);
  const TopologyParams params;
  const double baseline = bestSeconds(5, [&] { volatile auto s = magnitude(field); (void)s; });
  std::vector<CriticalPoint3D> points;
  const double detect = bestSeconds(3, [&] { points = findCriticalPoints3D(field, params); });
  FieldSet set;
  set.grid = field.grid;
  set.add(field);
  vtkSmartPointer<vtkImageData> image = toImageData(set);
  image->GetPointData()->SetActiveVectors(field.name.c_str());
  vtkIdType vtkPoints = 0;
  const double vtkTime = bestSeconds(1, [&] { vtkPoints = vtkCriticalPointCount(image); });
  std::map<std::string, int> types;
  for (const auto& p : points) ++types[p.typeName()];
  std::printf("topology_bench 3D: ABC flow (A = B = C = 1), 65^3 nodes, %zu critical points (",
              points.size());
  for (const auto& [name, count] : types) std::printf(" %s=%d", name.c_str(), count);
  std::printf(" )\n");
  std::printf("  baseline |v| pass              %8.4f s\n", baseline);
  std::printf("  3D detection + classification  %8.4f s  (%6.1f x baseline)\n", detect,
              detect / baseline);
  std::printf("  vtkVectorFieldTopology (%lld pts) %8.4f s  (%6.1f x baseline)\n",
              static_cast<long long>(vtkPoints), vtkTime, vtkTime / baseline);
  std::printf("  speed-up of 3D detection + classification over vtkVectorFieldTopology: %.1f x "
              "(target >= 10)\n",
              vtkTime / detect);
}
}  // namespace

int main() {
  bench3D();
  const int n = 1024;
  const VectorField field = benchField(n);
  const TopologyParams params;

  const double baseline = bestSeconds(5, [&] { volatile auto s = magnitude(field); (void)s; });
  std::vector<CriticalPoint> points;
  const double detect = bestSeconds(3, [&] { points = findCriticalPoints(field, params); });
  StreamFunctionResult psi;
  const double streamFunction = bestSeconds(1, [&] { psi = computeStreamFunction(field, params); });
  std::vector<ScalarCriticalPoint> psiPoints;
  const double psiDetect =
      bestSeconds(3, [&] { psiPoints = findScalarCriticalPoints(psi.psi, params); });
  std::vector<Separatrix> separatrices;
  const double separatrixTime =
      bestSeconds(1, [&] { separatrices = computeSeparatrices(field, points, params); });

  FieldSet set;
  set.grid = field.grid;
  set.add(field);
  vtkSmartPointer<vtkImageData> image = toImageData(set);
  image->GetPointData()->SetActiveVectors(field.name.c_str());
  vtkIdType vtkPoints = 0;
  const double vtkTime = bestSeconds(1, [&] { vtkPoints = vtkCriticalPointCount(image); });

  std::map<std::string, int> types;
  for (const auto& p : points) ++types[p.typeName()];
  std::printf("topology_bench: %d x %d nodes, %zu critical points (", n, n, points.size());
  for (const auto& [name, count] : types) std::printf(" %s=%d", name.c_str(), count);
  std::printf(" )\n");
  std::printf("  baseline |v| pass              %8.4f s\n", baseline);
  std::printf("  detection + classification     %8.4f s  (%6.1f x baseline)\n", detect,
              detect / baseline);
  std::printf("  stream function (%s, %d it) %8.4f s  (%6.1f x baseline)\n",
              psi.iterations ? "cg" : "direct", psi.iterations, streamFunction,
              streamFunction / baseline);
  std::printf("  psi critical points (%zu)      %8.4f s  (%6.1f x baseline)\n", psiPoints.size(),
              psiDetect, psiDetect / baseline);
  std::printf("  separatrices (%zu)             %8.4f s  (%6.1f x baseline)\n",
              separatrices.size(), separatrixTime, separatrixTime / baseline);
  std::printf("  vtkVectorFieldTopology (%lld pts) %8.4f s  (%6.1f x baseline)\n",
              static_cast<long long>(vtkPoints), vtkTime, vtkTime / baseline);
  std::printf("  speed-up of detection + classification over vtkVectorFieldTopology: %.1f x "
              "(target >= 10)\n",
              vtkTime / detect);
  return 0;
}
