// D2Q9 BGK throughput against the memory-bandwidth roofline, both measured in this run.
//
// LBM on CPUs is memory bound: a fused two-array stream-collide step reads 9 and writes 9
// doubles per node, 144 bytes (write-allocate traffic NOT counted, as STREAM does not count it
// either). The roofline is MLUPS_max = bandwidth / 144 B with the bandwidth of the STREAM triad
// a[i] = b[i] + s c[i] (McCalpin 1995; 24 bytes per iteration, no write-allocate), arrays far
// larger than the last-level cache, OpenMP static schedule, best of several repetitions.
// Printed ratio: MLUPS * 144 B / triad bandwidth, for 1 and 2 threads. Target for later work 0.75.
//
// Usage: lbm_bench [nodes_per_side=1024] [steps=100]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "solvers/lbm/LbmSolverD2Q9.h"

namespace {

using Clock = std::chrono::steady_clock;
using fluidviz::Vec3;
namespace lbm = fluidviz::lbm;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// STREAM triad, best of `repeats`, in bytes/s (24 bytes per element).
double triadBandwidth(int threads, std::size_t n, int repeats) {
  omp_set_num_threads(threads);
  std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
  double* pa = a.get();
  double* pb = b.get();
  double* pc = c.get();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    pa[i] = 0.0;
    pb[i] = 1.0;
    pc[i] = 2.0;
  }
  const double s = 3.0;
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
    best = std::min(best, seconds(t0, Clock::now()));
  }
  if (pa[n / 2] != 7.0) std::fprintf(stderr, "triad check failed\n");
  return 24.0 * static_cast<double>(n) / best;
}

// The data movement of the two-array D2Q9 step without its arithmetic: 9 planes copied to 9
// planes (same 144 B per node, same write-allocate), best of `repeats`, in node updates / s.
// Shows how much of the gap to the triad roofline is due to the access pattern itself.
double nineStreamCopyRate(int threads, std::int64_t nodes, int repeats) {
  omp_set_num_threads(threads);
  // Same layout as the solver's arrays: padded plane stride, second array shifted.
  lbm::PopulationArrays in(9, nodes, 72, 0), out(9, nodes, 72, 32);
  const std::int64_t stride = in.stride();
  double* pin = in.data();
  double* pout = out.data();
#pragma omp parallel for schedule(static)
  for (std::int64_t n = 0; n < nodes; ++n)
    for (int q = 0; q < 9; ++q) pin[q * stride + n] = pout[q * stride + n] = 1.0;
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
#pragma omp parallel for schedule(static)
    for (std::int64_t n = 0; n < nodes; ++n)
#pragma GCC unroll 9
      for (int q = 0; q < 9; ++q) pout[q * stride + n] = pin[q * stride + n];
    best = std::min(best, seconds(t0, Clock::now()));
  }
  return static_cast<double>(nodes) / best;
}

// Periodic box with a decaying shear wave, so that the collision works on non-trivial values.
std::unique_ptr<lbm::LbmSolverD2Q9> periodicBox(int n) {
  lbm::LbmParams p;
  p.domain_size = {1.0, 1.0};
  p.resolution = n;
  p.viscosity = 1e-3;
  const double dx = 1.0 / n;
  p.time_step = 0.1 * dx * dx / 1e-3;  // nu_lb = 0.1, tau = 0.8
  p.end_time = 1e9;
  p.max_steps = 2'000'000'000;
  for (auto* w : {&p.walls.x_min, &p.walls.x_max, &p.walls.y_min, &p.walls.y_max})
    w->type = "periodic";
  auto solver = std::make_unique<lbm::LbmSolverD2Q9>(p);
  const auto& u = solver->units();
  std::vector<double> rho(std::size_t(n) * n, p.density);
  std::vector<Vec3> vel(rho.size());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      vel[std::size_t(j) * n + i] =
          Vec3(u.toPhysicalVelocity(0.05 * std::sin(2 * M_PI * (j + 0.5) / n)), 0.0, 0.0);
  solver->initialise(rho, vel);
  return solver;
}

std::unique_ptr<lbm::LbmSolverD2Q9> cavity(int n) {
  lbm::LbmParams p;
  p.resolution = n;
  p.reynolds = 1000;
  p.lattice_velocity = 0.1;
  p.walls.y_max = {"moving_wall", {1.0, 0.0}};
  p.end_time = 1e9;
  p.max_steps = 2'000'000'000;
  return std::make_unique<lbm::LbmSolverD2Q9>(p);
}

// Million lattice updates per second (fluid nodes), best of `repeats` runs of `steps` steps.
double mlups(lbm::LbmSolverD2Q9& solver, int threads, int steps, int repeats) {
  omp_set_num_threads(threads);
  solver.step(2);  // warm-up (thread pool, page mapping)
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    solver.step(steps);
    best = std::min(best, seconds(t0, Clock::now()));
  }
  solver.checkStability();
  return static_cast<double>(solver.fluidNodeCount()) * steps / best / 1e6;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1024;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 100;
  const std::size_t triadElements = std::size_t(1) << 25;  // 3 x 256 MiB >> last-level cache
  const double bytesPerUpdate = 144.0;                      // 9 reads + 9 writes of 8 bytes

  std::printf("lbm_bench: D2Q9 BGK double, fused pull stream-collide, %d x %d nodes, %d steps\n",
              n, n, steps);
  std::printf("roofline: MLUPS_max = STREAM-triad bandwidth / %.0f B per node update "
              "(write-allocate not counted, as in STREAM)\n\n", bytesPerUpdate);
  std::printf("%-22s %7s %12s %10s %12s %10s\n", "case", "threads", "triad GB/s", "MLUPS",
              "roofline", "fraction");
  auto box = periodicBox(n);
  auto lid = cavity(n);
  for (int threads : {1, 2}) {
    // Best of 3 rounds of every measurement, interleaved, so that a transient load on the
    // (shared) machine does not penalise one side of the ratio only.
    double bw = 0, copy = 0, periodic = 0, walls = 0;
    for (int round = 0; round < 3; ++round) {
      bw = std::max(bw, triadBandwidth(threads, triadElements, 10));
      copy = std::max(copy, nineStreamCopyRate(threads, std::int64_t(n) * n, 5) / 1e6);
      periodic = std::max(periodic, mlups(*box, threads, steps, 2));
      walls = std::max(walls, mlups(*lid, threads, steps, 2));
    }
    const double roof = bw / bytesPerUpdate / 1e6;
    auto row = [&](const char* name, double rate) {
      std::printf("%-22s %7d %12.2f %10.1f %12.1f %10.3f\n", name, threads, bw / 1e9, rate, roof,
                  rate / roof);
    };
    row("periodic box", periodic);
    row("lid-driven cavity", walls);
    row("9-plane copy (no math)", copy);
  }
  std::printf("\nfraction = MLUPS * %.0f B / triad bandwidth; target for later work: 0.75\n"
              "The 9-plane copy moves the same bytes as a step with no arithmetic: the ceiling of "
              "the two-array scheme (write-allocate included) on this machine.\n",
              bytesPerUpdate);
  return 0;
}
