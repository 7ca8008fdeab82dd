// SPH benchmarks, each against a peer measured in the same run.
//
// 1. Neighbour search for one SPH step: bin/sort the particles and find the neighbours of every
//    particle within the kernel support 2h (h = 1.3 dx), on a jittered lattice (n^3 in 3D,
//    (8n)^2 in 2D). Ours: UniformGridNeighborSearch::build + neighborLists (compressed rows),
//    cells of edge = radius (what the solver uses). Peer: vtkStaticPointLocator (VTK 9.1)
//    BuildLocator (itself SMP-threaded) + FindPointsWithinRadius for every particle, the same
//    points and radius; VTK's queries are serial, so the peer runs them in an OpenMP loop with
//    one vtkIdList per thread, as many threads as ours. Both objects are made once and rebuilt
//    for every repetition (points marked modified), as a solver would each step. The peer
//    gets its fastest bucket size of VTK's default (NumberOfPointsPerBucket) and buckets of
//    about the radius. Both results are checked to hold the same pair count. Printed: best-of-5
//    wall times and the speed-up (target >= 10), and the best-of-5 CPU times of the process
//    with their ratio (on a machine shared with other jobs the wall time mostly measures the
//    waits for a core; with 2 threads the CPU time includes OpenMP's spinning at barriers).
// 2. A whole 3D model B step (neighbours, two continuity passes, forces, integration, checks)
//    on a dam-break column (cubic spline, h = 1.3 dx, alpha = 0.1, delta-SPH): particle
//    updates per second, for 1 and 2 threads. Its peer is the neighbour search of part 1 on the
//    same particle count (a step costs a few searches).
//
// Usage: sph_bench [lattice_side=50] [step_particles_side=24]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>

#include "solvers/sph/SphSolver.h"
#include "fieldviz/particles/UniformGridNeighborSearch.h"

namespace {

using Clock = std::chrono::steady_clock;
using fluidviz::Vec3;
namespace sph = fluidviz::sph;
namespace particles = fluidviz::particles;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// CPU time of the process (all threads): on a machine shared with other jobs it shows the work
// done, which the wall time mixes with the waits for a core.
double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// n^dim points (dim = 2: z = 0) on a lattice of spacing dx, each moved by up to 0.2 dx.
std::vector<Vec3> jitteredLattice(int dim, int n, double dx) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2 * dx, 0.2 * dx);
  std::vector<Vec3> p;
  for (int k = 0; k < (dim == 3 ? n : 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        p.emplace_back((i + 0.5) * dx + u(rng), (j + 0.5) * dx + u(rng),
                       dim == 3 ? (k + 0.5) * dx + u(rng) : 0.0);
  return p;
}

struct Timing {
  double seconds = 1e30;     // best wall time
  double cpuSeconds = 1e30;  // best CPU time (all threads)
  long long pairs = 0;  // neighbour pairs found (self excluded)
};

Timing ours(int dim, const std::vector<Vec3>& p, double side, double radius, int repeats) {
  Timing t;
  particles::NeighborLists lists;
  particles::UniformGridNeighborSearch search(dim, Vec3::Zero(), Vec3::Constant(side), radius);
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    const double c0 = cpuSeconds();
    search.build(p);
    search.neighborLists(p.size(), radius, lists);
    t.cpuSeconds = std::min(t.cpuSeconds, cpuSeconds() - c0);
    t.seconds = std::min(t.seconds, seconds(t0, Clock::now()));
  }
  t.pairs = static_cast<long long>(lists.pairs);
  return t;
}

// pointsPerBucket 0: VTK's default.
Timing vtkPeer(const std::vector<Vec3>& p, double radius, int pointsPerBucket, int repeats) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) points->SetPoint(i, p[i].data());
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(poly);
  if (pointsPerBucket > 0) locator->SetNumberOfPointsPerBucket(pointsPerBucket);
  Timing t;
  for (int r = 0; r < repeats; ++r) {
    long long pairs = 0;
    points->Modified();  // the particles moved: BuildLocator rebuilds
    const auto t0 = Clock::now();
    const double c0 = cpuSeconds();
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
    t.cpuSeconds = std::min(t.cpuSeconds, cpuSeconds() - c0);
    t.seconds = std::min(t.seconds, seconds(t0, Clock::now()));
    t.pairs = pairs;
  }
  return t;
}

void neighbourSearchBenchmark(int dim, int n) {
  const double dx = 1.0, radius = 2.0 * 1.3 * dx;
  const std::vector<Vec3> p = jitteredLattice(dim, n, dx);
  const int radiusBucket = static_cast<int>(std::lround(std::pow(radius / dx, dim)));
  std::printf("1. neighbour search, %dD: %zu particles (jittered %d^%d lattice), radius 2h = "
              "2.6 dx\n", dim, p.size(), n, dim);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const Timing a = ours(dim, p, n * dx, radius, 5);
    Timing b;
    int bestBucket = 0;
    for (int bucket : {0, radiusBucket}) {
      const Timing v = vtkPeer(p, radius, bucket, 5);
      if (v.seconds < b.seconds) b = v, bestBucket = bucket;
    }
    std::printf("   %d thread(s): ours %.2f ms, vtkStaticPointLocator %.2f ms (%s), speed-up "
                "%.1fx; CPU time %.2f vs %.2f ms, %.1fx (pairs %lld vs %lld%s)\n",
                threads, 1e3 * a.seconds, 1e3 * b.seconds,
                bestBucket == 0 ? "default buckets" : "buckets of ~radius", b.seconds / a.seconds,
                1e3 * a.cpuSeconds, 1e3 * b.cpuSeconds, b.cpuSeconds / a.cpuSeconds, a.pairs,
                b.pairs, a.pairs == b.pairs ? ", equal" : ", MISMATCH");
  }
}

sph::SphParams damBreak3D(int side) {
  sph::SphParams p;
  p.dimension = 3;
  p.particle_spacing = 0.4 / side;
  p.domain_lower = {0, 0, 0};
  p.domain_upper = {1.6, 1.2, 0.4};
  p.walls.y_max = fluidviz::sph::SphSide::open;
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
  neighbourSearchBenchmark(3, lattice);
  neighbourSearchBenchmark(2, 8 * lattice);
  if (column > 0) stepBenchmark(column);
  return 0;
}
