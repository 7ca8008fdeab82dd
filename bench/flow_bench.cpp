// FastLIC (Stalling & Hege 1995) against reference LIC (Cabral & Leedom 1993), measured in the
// same run on the same field, noise and kernel: 1024 x 1024 px, L = 30 px, box kernel.
// Prints both wall times, the speed-up (target >= 5) and how far the fast image is from the
// reference.
// Then the streamline integrator against VTK's vtkStreamTracer: 1000 seeds on a 512 x 512 field,
// classical RK4 at the same fixed step (0.25 cell), both directions, 500 cells per direction (or
// to the boundary), no loop detection (VTK has none). Both run in parallel (OpenMP here, VTK's
// SMP tools there); for one thread each: OMP_NUM_THREADS=1 VTK_SMP_MAX_THREADS=1 flow_bench.
// (vtkSMPTools.h does not compile as C++20, so the thread count is set from the environment.)
// Then the same in 3D (issue 15): the ABC flow on 64^3 nodes, 500 random seeds, RK4 at 0.25 cell
// both ways, <= 200 cells each. Accuracy is matched by construction: the same trilinear field,
// seeds, integrator and step in cells (VTK's step is h / sqrt(3) of its voxel-diagonal unit), so
// both make the same truncation error; StreamTracerAgreement3D_test.cpp checks that their
// endpoints agree within 1 cell, and the point counts printed here show equal arc lengths.
// Usage: flow_bench [size=1024] [length=30] [streamline_nodes=512] [seeds=1000] [nodes_3d=64]
//                   [seeds_3d=500]
#include <omp.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <string>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStreamTracer.h>

#include <cstdlib>
#include <random>

#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/lic/LineIntegralConvolution.h"
#include "filters/streamlines/Streamline.h"
#include "tests/support/AnalyticFields.h"
#include "tests/support/VtkStreamTracerPeer.h"

using namespace fluidviz;

namespace {

// The mixing-like test field of the streamline tests (four Lamb-Oseen vortices in a stream).
VectorField vortexStreet(int nodes) { return testing::fourLambOseenVortices(nodes, 0.08); }

struct Seconds {
  double wall, cpu;  // cpu: all threads of the process, robust when other jobs share the cores
};
Seconds secondsOf(const auto& f) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  f();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          double(std::clock() - c0) / CLOCKS_PER_SEC};
}

// Seeds uniformly at random over the field's domain (fixed seed: same seeds every run).
std::vector<Vec3> randomSeeds(const Grid& g, int n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec3 hi = g.upperCorner();
  std::vector<Vec3> seeds;
  for (int i = 0; i < n; ++i) {
    const double x = g.origin[0] + u(rng) * (hi.x() - g.origin[0]);
    const double y = g.origin[1] + u(rng) * (hi.y() - g.origin[1]);
    seeds.emplace_back(x, y, g.is2D() ? 0.0 : g.origin[2] + u(rng) * (hi.z() - g.origin[2]));
  }
  return seeds;
}

struct TracerRun {
  Seconds time;
  long points;
};

TracerRun runOurs(const VectorField& field, const std::vector<Vec3>& seeds, double step,
                  double maxLength) {
  streamlines::StreamlineParams p;
  p.integrator = fluidviz::streamlines::Integrator::rk4;
  p.step = step;
  p.max_length = maxLength;
  p.max_steps = 1000000;
  p.loop_detection = false;
  p.stagnation_speed = 0.0;
  std::vector<streamlines::Streamline> lines;
  const Seconds t = secondsOf([&] { lines = streamlines::traceStreamlines(field, seeds, p); });
  long points = 0;
  for (const auto& l : lines) points += static_cast<long>(l.points.size());
  return {t, points};
}

TracerRun runVtk(vtkImageData* image, const std::vector<Vec3>& seeds, double step,
                 double maxLength) {
  vtkSmartPointer<vtkStreamTracer> tracer = testing::fixedStepRk4Tracer(image, seeds, step, maxLength);
  tracer->SetIntegrationDirectionToBoth();
  const Seconds t = secondsOf([&] { tracer->Update(); });
  return {t, static_cast<long>(tracer->GetOutput()->GetNumberOfPoints())};
}

// Both tracers on `field` from `seedCount` random seeds; prints times, points and the ratio.
void compareTracers(const VectorField& field, int seedCount, double step, double maxLength) {
  vtkSmartPointer<vtkImageData> image = testing::peerImageOf(field);
  const std::vector<Vec3> seeds = randomSeeds(field.grid, seedCount);
  const char* vtkThreads = std::getenv("VTK_SMP_MAX_THREADS");
  const TracerRun ours = runOurs(field, seeds, step, maxLength);
  const TracerRun vtk = runVtk(image, seeds, step, maxLength);
  std::printf("                                      wall s     cpu s    points  threads\n");
  std::printf("  fluidviz StreamlineTracer:       %9.3f %9.3f %9ld  %d (OpenMP)\n", ours.time.wall,
              ours.time.cpu, ours.points, omp_get_max_threads());
  std::printf("  vtkStreamTracer (VTK 9.1):       %9.3f %9.3f %9ld  %s (VTK SMP)\n", vtk.time.wall,
              vtk.time.cpu, vtk.points, vtkThreads ? vtkThreads : "default");
  std::printf("  speed-up vtk / fluidviz:         %9.2f %9.2f            (target >= 5)\n",
              vtk.time.wall / ours.time.wall, vtk.time.cpu / ours.time.cpu);
}

void streamlineBench(int nodes, int seedCount) {
  const double step = 0.25, maxLength = 500.0;
  std::printf("\nStreamlines, %d x %d nodes, %d seeds, RK4 step %.2f cell, both directions, <= %.0f "
              "cells each\n", nodes, nodes, seedCount, step, maxLength);
  compareTracers(vortexStreet(nodes), seedCount, step, maxLength);
}

void streamlineBench3D(int nodes, int seedCount) {
  const double step = 0.25, maxLength = 200.0;
  std::printf("\n3D streamlines, ABC flow on %d^3 nodes, %d seeds, RK4 step %.2f cell, both "
              "directions, <= %.0f cells each\n", nodes, seedCount, step, maxLength);
  compareTracers(testing::abcFlow(nodes), seedCount, step, maxLength);
}

}  // namespace

int main(int argc, char** argv) {
  const int size = argc > 1 ? std::stoi(argv[1]) : 1024;
  const double length = argc > 2 ? std::stod(argv[2]) : 30.0;
  const VectorField field = vortexStreet(257);
  lic::LicParams p;
  p.width = p.height = size;
  p.length = length;
  p.contrast = false;

  lic::LicImage ref, fast;
  p.method = fluidviz::lic::LicMethod::reference;
  const Seconds tRef = secondsOf([&] { ref = lic::computeLic(field, p); });
  p.method = fluidviz::lic::LicMethod::fast;
  const Seconds tFast = secondsOf([&] { fast = lic::computeLic(field, p); });

  double meanAbs = 0;
  for (std::size_t i = 0; i < ref.texture.values.size(); ++i)
    meanAbs += std::abs(ref.texture.values[i] - fast.texture.values[i]);
  meanAbs /= ref.texture.values.size();

  std::printf("LIC %d x %d px, L = %.0f px, step %.2f px, box kernel, %d threads\n", size, size,
              length, p.step, omp_get_max_threads());
  std::printf("                                      wall s     cpu s\n");
  std::printf("  reference (Cabral & Leedom 1993): %8.3f  %8.3f\n", tRef.wall, tRef.cpu);
  std::printf("  fast      (Stalling & Hege 1995): %8.3f  %8.3f  (fast_min_hits %d, line %.0f L)\n",
              tFast.wall, tFast.cpu, p.fast_min_hits, p.fast_line_factor);
  std::printf("  speed-up fast / reference:        %8.2f  %8.2f  (target >= 5)\n",
              tRef.wall / tFast.wall, tRef.cpu / tFast.cpu);
  std::printf("  mean |fast - reference|:          %8.4f            (raw values in [0, 1])\n",
              meanAbs);
  streamlineBench(argc > 3 ? std::stoi(argv[3]) : 512, argc > 4 ? std::stoi(argv[4]) : 1000);
  streamlineBench3D(argc > 5 ? std::stoi(argv[5]) : 64, argc > 6 ? std::stoi(argv[6]) : 500);
  return 0;
}
