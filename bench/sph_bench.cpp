// SPH benchmarks, each against a peer measured in the same run.
//
// 1. Neighbour search for one SPH step: bin/sort the particles and find the neighbours of every
//    particle within the kernel support 2h (h = 1.3 dx), on a jittered 3D lattice of n^3
//    particles. Ours: UniformGridNeighborSearch::build + neighborLists (compressed rows).
//    Peer: vtkStaticPointLocator (VTK 9.1) BuildLocator + FindPointsWithinRadius for every
//    particle, the same points and radius, with the same number of threads (OpenMP over the
//    queries, one vtkIdList per thread). Both results are checked to hold the same pair count.
//    Printed: best-of-5 times and the speed-up (target >= 10), for cells of edge = radius (what
//    the solver uses) and radius / 2.
// 2. A whole 3D model B step (neighbours, two continuity passes, forces, integration, checks)
//    on a dam-break column (cubic spline, h = 1.3 dx, alpha = 0.1, delta-SPH): particle
//    updates per second, for 1 and 2 threads. Its peer is the neighbour search of part 1 on the
//    same particle count (a step costs a few searches).
//
// Usage: sph_bench [lattice_side=50] [step_particles_side=24]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>

#include "solvers/sph/SphSolver.h"
#include "solvers/sph/UniformGridNeighborSearch.h"

namespace {

using Clock = std::chrono::steady_clock;
using fluidviz::Vec3;
namespace sph = fluidviz::sph;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

std::vector<Vec3> jitteredLattice(int n, double dx) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2 * dx, 0.2 * dx);
  std::vector<Vec3> p;
  p.reserve(static_cast<std::size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        p.emplace_back((i + 0.5) * dx + u(rng), (j + 0.5) * dx + u(rng), (k + 0.5) * dx + u(rng));
  return p;
}

struct Timing {
  double seconds = 1e30;
  long long pairs = 0;  // neighbour pairs found (self excluded)
};

Timing ours(const std::vector<Vec3>& p, double side, double radius, double cell, int repeats) {
  Timing t;
  sph::NeighborLists lists;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    sph::UniformGridNeighborSearch search(3, Vec3::Zero(), Vec3::Constant(side), cell);
    search.build(p);
    search.neighborLists(p.size(), radius, lists);
    t.seconds = std::min(t.seconds, seconds(t0, Clock::now()));
  }
  t.pairs = static_cast<long long>(lists.indices.size());
  return t;
}

Timing vtkPeer(const std::vector<Vec3>& p, double radius, int repeats) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) points->SetPoint(i, p[i].data());
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  Timing t;
  for (int r = 0; r < repeats; ++r) {
    long long pairs = 0;
    const auto t0 = Clock::now();
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(poly);
    locator->BuildLocator();
#pragma omp parallel reduction(+ : pairs)
    {
      vtkNew<vtkIdList> ids;
#pragma omp for schedule(static)
      for (std::int64_t i = 0; i < static_cast<std::int64_t>(p.size()); ++i) {
        double x[3] = {p[i][0], p[i][1], p[i][2]};
        locator->FindPointsWithinRadius(radius, x, ids);
        pairs += ids->GetNumberOfIds() - 1;  // minus the point itself
      }
    }
    t.seconds = std::min(t.seconds, seconds(t0, Clock::now()));
    t.pairs = pairs;
  }
  return t;
}

void neighbourSearchBenchmark(int n) {
  const double dx = 1.0, radius = 2.0 * 1.3 * dx;
  const std::vector<Vec3> p = jitteredLattice(n, dx);
  std::printf("1. neighbour search: %zu particles (jittered %d^3 lattice), radius 2h = 2.6 dx\n",
              p.size(), n);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const Timing b = vtkPeer(p, radius, 5);
    for (double cell : {radius, 0.5 * radius}) {
      const Timing a = ours(p, n * dx, radius, cell, 5);
      std::printf("   %d thread(s), cells %.2g x radius: ours %.4f s, vtkStaticPointLocator "
                  "%.4f s, speed-up %.1fx (pairs %lld vs %lld%s)\n",
                  threads, cell / radius, a.seconds, b.seconds, b.seconds / a.seconds, a.pairs,
                  b.pairs, a.pairs == b.pairs ? ", equal" : ", MISMATCH");
    }
  }
}

sph::SphParams damBreak3D(int side) {
  sph::SphParams p;
  p.dimension = 3;
  p.particle_spacing = 0.4 / side;
  p.domain_lower = {0, 0, 0};
  p.domain_upper = {1.6, 1.2, 0.4};
  p.walls.y_max = "open";
  p.fluid_blocks = {{{0, 0, 0}, {0.4, 0.8, 0.4}}};
  p.speed_of_sound = 10 * std::sqrt(2 * 9.81 * 0.4);
  p.alpha = 0.1;
  p.end_time = 100;
  return p;
}

void stepBenchmark(int side) {
  const sph::SphParams params = damBreak3D(side);
  std::printf("2. whole 3D model B step, dam-break column %d x %d x %d\n", side, 2 * side, side);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    sph::SphSolver solver(params);
    for (int k = 0; k < 3; ++k) solver.step();  // warm up (allocations, first evaluation)
    const int steps = 20;
    const auto t0 = Clock::now();
    for (int k = 0; k < steps; ++k) solver.step();
    const double s = seconds(t0, Clock::now());
    const double n = static_cast<double>(solver.fluidCount());
    std::printf("   %d thread(s): %zu fluid + %zu boundary particles, %.1f ms/step, %.2f M "
                "particle-updates/s\n",
                threads, solver.fluidCount(), solver.boundaryParticles().size(), 1e3 * s / steps,
                n * steps / s / 1e6);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int lattice = argc > 1 ? std::atoi(argv[1]) : 50;
  const int column = argc > 2 ? std::atoi(argv[2]) : 24;
  neighbourSearchBenchmark(lattice);
  stepBenchmark(column);
  return 0;
}
