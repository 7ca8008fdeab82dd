// LBM throughput against the memory-bandwidth roofline, both measured in this run, for the
// lattices D2Q9 and D3Q19 in double and single precision.
//
// LBM on CPUs is memory bound: a fused two-array stream-collide step reads Q and writes Q
// populations per node, 2 Q sizeof(T) bytes: D2Q9 144 B (double) / 72 B (float), D3Q19 304 B /
// 152 B. The solver writes with streaming (non-temporal) stores (StreamCollidePull.h), so these
// are the bytes it really moves: no write-allocate read of the destination. The roofline is
// MLUPS_max = bandwidth / (2 Q sizeof(T)) with the bandwidth of the STREAM triad
// a[i] = b[i] + s c[i] (McCalpin 1995) written the same way -- streaming stores of whole cache
// lines, so its 24 bytes per iteration are also the bytes it moves -- arrays far larger than the
// last-level cache, OpenMP static schedule, best of several repetitions, measured just before and
// just after each round of solver measurements (LbmBench main). Both sides are counted
// alike and honestly. For reference the triad with ordinary stores is printed too, counted as
// STREAM does (24 B; it really moves 32 B, the extra 8 B being the write-allocate read of a[i]).
// Printed ratio ("fraction"): MLUPS * 2 Q sizeof(T) / triad bandwidth, for 1 and 2 threads.
// Targets: 0.75 for D2Q9 double, 0.7 for D3Q19.
// Also printed: the Q-plane copy (the same bytes as a step, no arithmetic, same layout, same
// streaming stores), the ceiling of the two-array access pattern on this machine.
//
// Usage: lbm_bench [nodes_per_side_2d=1024] [nodes_per_side_3d=128] [steps_2d=50]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "solvers/lbm/LbmSolver.h"
#include "solvers/lbm/kernel/LineVector.h"
#include "solvers/lbm/kernel/PopulationArrays.h"

namespace {

using Clock = std::chrono::steady_clock;
using fluidviz::Vec3;
namespace lbm = fluidviz::lbm;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// The triad and the plane copy in whole cache lines with the solver's streaming stores
// (LineVector.h), for the instruction set the solver picks (bestIsaLevel).
template <class Isa>
FLUIDVIZ_LBM_INLINE void triadLinesFor(double* a, const double* b, const double* c,
                                       std::int64_t begin, std::int64_t end) {
  using V = lbm::LineOf<double>;
  const V s(3.0);
  for (std::int64_t i = begin; i < end; i += V::width)
    Isa::streamLine(a + i, V::load(b + i) + s * V::load(c + i));
}

template <class Isa, class T>
FLUIDVIZ_LBM_INLINE void copyLinesFor(const T* in, T* out, std::int64_t stride, int planes,
                                      std::int64_t begin, std::int64_t end) {
  using V = lbm::LineOf<T>;
  for (std::int64_t n = begin; n < end; n += V::width)
    for (int q = 0; q < planes; ++q) Isa::streamLine(out + q * stride + n, V::load(in + q * stride + n));
}

#if defined(FLUIDVIZ_LBM_MULTI_ISA)
__attribute__((noinline, target("arch=x86-64-v4"))) void triadLinesV4(
    double* a, const double* b, const double* c, std::int64_t begin, std::int64_t end) {
  triadLinesFor<lbm::IsaV4>(a, b, c, begin, end);
}
__attribute__((noinline, target("arch=x86-64-v3"))) void triadLinesV3(
    double* a, const double* b, const double* c, std::int64_t begin, std::int64_t end) {
  triadLinesFor<lbm::IsaV3>(a, b, c, begin, end);
}
template <class T>
__attribute__((noinline, target("arch=x86-64-v4"))) void copyLinesV4(
    const T* in, T* out, std::int64_t stride, int planes, std::int64_t begin, std::int64_t end) {
  copyLinesFor<lbm::IsaV4, T>(in, out, stride, planes, begin, end);
}
template <class T>
__attribute__((noinline, target("arch=x86-64-v3"))) void copyLinesV3(
    const T* in, T* out, std::int64_t stride, int planes, std::int64_t begin, std::int64_t end) {
  copyLinesFor<lbm::IsaV3, T>(in, out, stride, planes, begin, end);
}
#endif

void triadLines(double* a, const double* b, const double* c, std::int64_t begin,
                std::int64_t end) {
#if defined(FLUIDVIZ_LBM_MULTI_ISA)
  if (fluidviz::bestIsaLevel() == 4) return triadLinesV4(a, b, c, begin, end);
  if (fluidviz::bestIsaLevel() == 3) return triadLinesV3(a, b, c, begin, end);
#endif
  triadLinesFor<lbm::IsaBase>(a, b, c, begin, end);
}

template <class T>
void copyLines(const T* in, T* out, std::int64_t stride, int planes, std::int64_t begin,
               std::int64_t end) {
#if defined(FLUIDVIZ_LBM_MULTI_ISA)
  if (fluidviz::bestIsaLevel() == 4) return copyLinesV4<T>(in, out, stride, planes, begin, end);
  if (fluidviz::bestIsaLevel() == 3) return copyLinesV3<T>(in, out, stride, planes, begin, end);
#endif
  copyLinesFor<lbm::IsaBase, T>(in, out, stride, planes, begin, end);
}

/// This thread's share of [0, count) in whole lines of `width` values (static partition).
std::pair<std::int64_t, std::int64_t> threadShare(std::int64_t count, int width) {
  const std::int64_t lines = count / width;
  const int team = omp_get_num_threads(), me = omp_get_thread_num();
  return {lines * me / team * width, lines * (me + 1) / team * width};
}

struct FreeDeleter {
  void operator()(double* p) const { std::free(p); }
};
using AlignedArray = std::unique_ptr<double[], FreeDeleter>;
AlignedArray alignedArray(std::size_t n) {
  return AlignedArray(static_cast<double*>(std::aligned_alloc(64, n * sizeof(double))));
}

struct TriadResult {
  double streaming = 0;  ///< bytes/s, streaming stores (24 B counted and moved per element)
  double ordinary = 0;   ///< bytes/s counted as STREAM does (24 B), ordinary stores
};

// The three STREAM arrays, allocated and first touched once (by the threads that use them):
// allocating 768 MiB per measurement cost more system time than the measurements themselves.
class TriadArrays {
 public:
  explicit TriadArrays(std::size_t n) : n_(n), a_(alignedArray(n)), b_(alignedArray(n)), c_(alignedArray(n)) {
    double* pa = a_.get();
    double* pb = b_.get();
    double* pc = c_.get();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      pa[i] = 0.0;
      pb[i] = 1.0;
      pc[i] = 2.0;
    }
  }
  // STREAM triad, best of `repeats`, with streaming and with ordinary stores.
  TriadResult bandwidth(int threads, int repeats) {
    omp_set_num_threads(threads);
    double* pa = a_.get();
    const double* pb = b_.get();
    const double* pc = c_.get();
    const std::size_t n = n_;
    const double s = 3.0;
    double bestStreaming = 1e30, bestOrdinary = 1e30;
    for (int r = 0; r < repeats; ++r) {
      auto t0 = Clock::now();
#pragma omp parallel
      {
        const auto [begin, end] = threadShare(static_cast<std::int64_t>(n), 8);
        triadLines(pa, pb, pc, begin, end);
        lbm::fenceStreamingStores();
      }
      bestStreaming = std::min(bestStreaming, seconds(t0, Clock::now()));
      t0 = Clock::now();
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
      bestOrdinary = std::min(bestOrdinary, seconds(t0, Clock::now()));
    }
    if (pa[n / 2] != 7.0) std::fprintf(stderr, "triad check failed\n");
    return {24.0 * static_cast<double>(n) / bestStreaming, 24.0 * static_cast<double>(n) / bestOrdinary};
  }

 private:
  std::size_t n_;
  AlignedArray a_, b_, c_;
};

// The data movement of a two-array step without its arithmetic: Q planes copied to Q planes
// (same bytes, same streaming stores, same padded layout as the solver), node updates / s.
template <class T, int planes>
double planeCopyRate(int threads, std::int64_t nodes, int repeats) {
  omp_set_num_threads(threads);
  lbm::PopulationArraysOf<T> in(planes, nodes, 576 / sizeof(T), 0),
      out(planes, nodes, 576 / sizeof(T), 256 / sizeof(T));
  const std::int64_t stride = in.stride();
  T* pin = in.data();
  T* pout = out.data();
#pragma omp parallel for schedule(static)
  for (std::int64_t n = 0; n < nodes; ++n)
    for (int q = 0; q < planes; ++q) pin[q * stride + n] = pout[q * stride + n] = T(1);
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
#pragma omp parallel
    {
      const auto [begin, end] = threadShare(nodes, lbm::LineOf<T>::width);
      copyLines<T>(pin, pout, stride, planes, begin, end);
      lbm::fenceStreamingStores();
    }
    best = std::min(best, seconds(t0, Clock::now()));
  }
  return static_cast<double>(nodes) / best;
}

// Periodic box with a decaying shear wave (so that the collision works on non-trivial values),
// tau = 0.8, BGK.
std::unique_ptr<lbm::LbmSolver> periodicBox(const std::string& lattice, const std::string& precision,
                                            int n) {
  lbm::LbmParams p;
  p.lattice = fluidviz::choiceNamed<fluidviz::lbm::Lattice>(lattice);
  p.precision = fluidviz::choiceNamed<fluidviz::lbm::Precision>(precision);
  p.domain_size = {1.0, 1.0};
  const bool threeD = lattice == "D3Q19";
  if (threeD) p.domain_depth = 1.0;
  p.resolution = n;
  p.viscosity = 1e-3;
  const double dx = 1.0 / n;
  p.time_step = 0.1 * dx * dx / 1e-3;  // nu_lb = 0.1, tau = 0.8
  p.end_time = 1e9;
  p.max_steps = 2'000'000'000;
  for (auto* w : {&p.walls.x_min, &p.walls.x_max, &p.walls.y_min, &p.walls.y_max})
    w->type = fluidviz::lbm::WallType::periodic;
  if (threeD) p.walls.z_min.type = p.walls.z_max.type = fluidviz::lbm::WallType::periodic;
  auto solver = lbm::createLbmSolver(p);
  const auto& u = solver->units();
  const fluidviz::Grid& g = solver->grid();
  std::vector<double> rho(g.nodeCount(), p.density);
  std::vector<Vec3> vel(g.nodeCount());
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        vel[g.index(i, j, k)] =
            Vec3(u.toPhysicalVelocity(0.05 * std::sin(2 * M_PI * (j + 0.5) / n)), 0.0, 0.0);
  solver->initialise(rho, vel);
  return solver;
}

// Lid-driven cavity (walls on every side), Re 1000, BGK.
std::unique_ptr<lbm::LbmSolver> cavity(const std::string& lattice, const std::string& precision,
                                       int n) {
  lbm::LbmParams p;
  p.lattice = fluidviz::choiceNamed<fluidviz::lbm::Lattice>(lattice);
  p.precision = fluidviz::choiceNamed<fluidviz::lbm::Precision>(precision);
  if (lattice == "D3Q19") p.domain_depth = 1.0;
  p.resolution = n;
  p.reynolds = 1000;
  p.lattice_velocity = 0.1;
  p.walls.y_max.type = fluidviz::lbm::WallType::moving_wall;
  p.walls.y_max.velocity = {1.0, 0.0};
  p.end_time = 1e9;
  p.max_steps = 2'000'000'000;
  return lbm::createLbmSolver(p);
}

// Million lattice updates per second (fluid nodes), best of `repeats` bursts of `steps` steps.
double mlups(lbm::LbmSolver& solver, int threads, int steps, int repeats) {
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

// The measurement with the best ratio to its triad among the steady rounds (any round while
// none was steady; the row then says so).
struct Best {
  double mlups = 0, bandwidth = 0;
  bool steady = false;
  void offer(double rate, double bw, bool isSteady) {
    const bool better = bandwidth == 0 || rate / bw > mlups / bandwidth;
    if ((isSteady && (!steady || better)) || (!isSteady && !steady && better)) {
      mlups = rate;
      bandwidth = bw;
      steady = isSteady;
    }
  }
};

struct Config {
  std::string lattice, precision;
  int n, steps, q, bytes;
};

}  // namespace

int main(int argc, char** argv) {
  const int n2 = argc > 1 ? std::atoi(argv[1]) : 1024;
  const int n3 = argc > 2 ? std::atoi(argv[2]) : 128;
  const int steps2 = argc > 3 ? std::atoi(argv[3]) : 50;
  // Steps of the 3D case: about the same node updates per measurement as the 2D case.
  const int steps3 = std::max(2, static_cast<int>(double(steps2) * n2 * n2 / (double(n3) * n3 * n3)));
  const std::size_t triadElements = std::size_t(1) << 25;  // 3 x 256 MiB >> last-level cache

  const std::vector<Config> configs{{"D2Q9", "double", n2, steps2, 9, 144},
                                    {"D2Q9", "float", n2, steps2, 9, 72},
                                    {"D3Q19", "double", n3, steps3, 19, 304},
                                    {"D3Q19", "float", n3, steps3, 19, 152}};
  std::printf("lbm_bench: fused pull stream-collide, BGK, D2Q9 %d^2 (%d steps), D3Q19 %d^3 "
              "(%d steps)\n", n2, steps2, n3, steps3);
  const char* isaName = lbm::IsaBase::name;
#if defined(FLUIDVIZ_LBM_MULTI_ISA)
  if (fluidviz::bestIsaLevel() == 4) isaName = lbm::IsaV4::name;
  if (fluidviz::bestIsaLevel() == 3) isaName = lbm::IsaV3::name;
#endif
  std::printf("roofline: MLUPS_max = STREAM-triad bandwidth / (2 Q sizeof(T)) B per node update; "
              "solver and triad both write with streaming stores (%s), so neither moves "
              "write-allocate bytes\n\n", isaName);
  std::printf("%-6s %-7s %-18s %7s %6s %10s %10s %10s %9s\n", "lattice", "type", "case",
              "threads", "B/upd", "triad GB/s", "MLUPS", "roofline", "fraction");
  TriadArrays triad(triadElements);
  int unsteadyRounds = 0, rounds = 0;
  for (int threads : {1, 2}) {
    double bw = 0, ordinary = 0;
    for (int round = 0; round < 3; ++round) {
      const TriadResult t = triad.bandwidth(threads, 10);
      bw = std::max(bw, t.streaming);
      ordinary = std::max(ordinary, t.ordinary);
    }
    std::printf("%d thread(s): triad %.2f GB/s with streaming stores; with ordinary stores %.2f GB/s "
                "counted as STREAM (24 B), %.2f GB/s moved (32 B)\n", threads, bw / 1e9,
                ordinary / 1e9, ordinary / 1e9 * 32 / 24);
    for (const Config& c : configs) {
      auto box = periodicBox(c.lattice, c.precision, c.n);
      auto lid = cavity(c.lattice, c.precision, c.n);
      // Rounds of the three measurements, each bracketed by a triad just before and just after;
      // a measurement's ratio uses the mean of its round's two triads. This machine can switch
      // between bandwidth states within seconds, so a round whose triads differ by more than
      // 10 % is not used (a ratio across a switch means nothing); of the others the best ratio
      // counts. Best, not mean: on a shared machine interruptions only ever slow a measurement.
      Best periodic, walls, copy;
      for (int round = 0; round < 4; ++round) {
        const double before = triad.bandwidth(threads, 4).streaming;
        // Steps timed in bursts that move about as many bytes as one triad run, best burst
        // counted on both sides: on a shared machine a long measurement is interrupted more
        // often than a short one, which would bias the ratio against the solver.
        const double stepBytes = double(box->grid().nodeCount()) * c.bytes;
        const int burst = std::max(1, static_cast<int>(std::lround(24.0 * triadElements / stepBytes)));
        const int bursts = std::max(4, c.steps / burst);
        const double p = mlups(*box, threads, burst, bursts);
        const double w = mlups(*lid, threads, burst, bursts);
        const std::int64_t nodes = static_cast<std::int64_t>(box->grid().nodeCount());
        const double rate = c.q == 9 ? (c.precision == "float" ? planeCopyRate<float, 9>(threads, nodes, 3)
                                                             : planeCopyRate<double, 9>(threads, nodes, 3))
                                     : (c.precision == "float" ? planeCopyRate<float, 19>(threads, nodes, 3)
                                                               : planeCopyRate<double, 19>(threads, nodes, 3));
        const double after = triad.bandwidth(threads, 4).streaming;
        ++rounds;
        const bool steady = std::max(before, after) <= 1.1 * std::min(before, after);
        if (!steady) ++unsteadyRounds;
        const double bandwidth = 0.5 * (before + after);
        periodic.offer(p, bandwidth, steady);
        walls.offer(w, bandwidth, steady);
        copy.offer(rate / 1e6, bandwidth, steady);
      }
      auto row = [&](const char* name, const Best& b) {
        const double roof = b.bandwidth / c.bytes / 1e6;
        std::printf("%-6s %-7s %-18s %7d %6d %10.2f %10.1f %10.1f %9.3f%s\n", c.lattice.c_str(),
                    c.precision.c_str(), name, threads, c.bytes, b.bandwidth / 1e9, b.mlups, roof,
                    b.mlups / roof, b.steady ? "" : "  (no steady round)");
      };
      row("periodic box", periodic);
      row("lid-driven cavity", walls);
      row("Q-plane copy", copy);
      std::fflush(stdout);
    }
  }
  std::printf("\n%d of %d rounds not used: the triads before and after differed by more than 10 %%.\n",
              unsteadyRounds, rounds);
  std::printf("\nfraction = MLUPS * 2 Q sizeof(T) / triad bandwidth; targets: 0.75 (D2Q9 double), "
              "0.7 (D3Q19).\nThe Q-plane copy moves the same bytes as a step with no arithmetic, with the "
              "same streaming stores: the ceiling of the two-array scheme on this machine.\n");
  return 0;
}
