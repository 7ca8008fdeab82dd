// FHP lattice-gas throughput: the multi-spin bit-plane stepper (BitLattice, 64 nodes per word)
// against the one-byte-per-node reference step (NodeLattice) on the same lattice, and against the
// memory bandwidth measured in this run.
//
// Bytes per node update of the bit-plane step, counted as STREAM counts (each word read once and
// written once; the write-allocate reads of ordinary stores not counted, on either side): the
// collision reads the 7 channel planes and the solid plane and writes the 7 planes, the
// propagation reads the 7 planes and writes them shifted into the second array: 29 bits per node
// (the rest plane exists and is moved for FHP-I too). The roofline is
// updates/s_max = copy bandwidth / (29 / 8 B), with the bandwidth of the STREAM copy a[i] = b[i]
// (McCalpin 1995; 16 B per element) on arrays far larger than the last-level cache, best of
// several repetitions, measured just before and just after each stepper measurement; a
// measurement whose two copies differ by more than 10% is repeated (up to four times) because a
// ratio across a change of the machine's bandwidth state means nothing. Best, not mean: on a
// shared machine interruptions only ever slow a measurement.
// The reference step moves per node: the state and solid bytes read and the state written
// (collision), the state read, a zeroed next array written and or-ed into (propagation): about
// 6 B, but it is bound by its per-node work, not by memory; its rate is printed with the
// stepper's speed-up over it (the reference runs on one thread: it has no OpenMP).
//
// Cases: periodic box at d = 0.2 (FHP-I, FHP-III); channel with bounce-back walls on a fifth of
// the rows and the body force (flip probability 0.01), FHP-III.
//
// Usage: fhp_bench [nx=8192] [ny=4096] [steps=5]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "solvers/fhp/collision/CollisionTable.h"
#include "solvers/fhp/lattice/BitLattice.h"
#include "solvers/fhp/lattice/Initialisation.h"
#include "solvers/fhp/lattice/NodeLattice.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace fhp = fluidviz::fhp;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

constexpr double kBitsPerUpdate = 29.0;  // see the header

// The two STREAM-copy arrays, allocated and first touched once by the threads that use them.
class CopyArrays {
 public:
  explicit CopyArrays(std::size_t n) : a_(n), b_(n) {
    double* pa = a_.data();
    double* pb = b_.data();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      pa[i] = 0.0;
      pb[i] = 1.0 + static_cast<double>(i % 7);
    }
  }
  /// Bytes per second of a[i] = b[i] (16 B per element), best of `repeats`.
  double bandwidth(int threads, int repeats) {
    omp_set_num_threads(threads);
    double* pa = a_.data();
    const double* pb = b_.data();
    const std::size_t n = a_.size();
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = Clock::now();
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i];
      best = std::min(best, seconds(t0, Clock::now()));
    }
    if (pa[n / 2] != pb[n / 2]) std::fprintf(stderr, "copy check failed\n");
    return 16.0 * static_cast<double>(n) / best;
  }

 private:
  std::vector<double> a_, b_;
};

struct Case {
  std::string name;
  fhp::Model model;
  bool walls;
  double forceProbability;
};

fhp::BitLattice makeLattice(const Case& c, int nx, int ny) {
  fhp::BitLattice lattice(nx, ny);
  if (c.walls)  // a wall every fifth row: channels of four fluid rows
    for (int y = 0; y < ny; y += 5)
      for (int x = 0; x < nx; ++x) lattice.setSolid(x, y, true);
  fhp::fillEquilibrium(lattice, c.model, 0.2, [](int, int) { return std::array<double, 2>{0.05, 0.0}; },
                       7);
  return lattice;
}

/// Node updates per second of the bit-plane stepper, best of `bursts` bursts of `steps` steps.
double stepperRate(fhp::BitLattice& lattice, const fhp::CollisionTable& table,
                   const fhp::StepRules& rules, int threads, int steps, int bursts) {
  omp_set_num_threads(threads);
  lattice.step(table, rules);  // warm-up (thread pool, pages)
  double best = 1e30;
  for (int b = 0; b < bursts; ++b) {
    const auto t0 = Clock::now();
    for (int s = 0; s < steps; ++s) lattice.step(table, rules);
    best = std::min(best, seconds(t0, Clock::now()));
  }
  return static_cast<double>(lattice.nx()) * lattice.ny() * steps / best;
}

double referenceRate(fhp::NodeLattice& nodes, const fhp::CollisionTable& table,
                     const fhp::StepRules& rules, int steps) {
  double best = 1e30;
  for (int s = 0; s < steps; ++s) {
    const auto t0 = Clock::now();
    fhp::referenceStep(nodes, table, rules);
    best = std::min(best, seconds(t0, Clock::now()));
  }
  return static_cast<double>(nodes.nx) * nodes.ny / best;
}

}  // namespace

int main(int argc, char** argv) {
  const int nx = argc > 1 ? std::atoi(argv[1]) : 8192;
  const int ny = argc > 2 ? std::atoi(argv[2]) : 4096;
  const int steps = argc > 3 ? std::atoi(argv[3]) : 5;
  const std::size_t copyElements = std::size_t(1) << 25;  // 2 x 256 MiB >> last-level cache
  const double latticeMiB = 2.0 * 8 * nx / 64.0 * ny * 8 / 1048576.0;
  std::printf("fhp_bench: %d x %d nodes (%.0f MiB: 7 channel planes and the solid plane, two arrays), bursts of %d steps\n",
              nx, ny, latticeMiB, steps);
  std::printf("roofline: updates/s_max = STREAM-copy bandwidth / (%.0f bits = %.3f B per node "
              "update), both counted without write-allocate bytes\n\n",
              kBitsPerUpdate, kBitsPerUpdate / 8);

  const std::vector<Case> cases{{"periodic box", fhp::Model::fhp1, false, 0.0},
                                {"periodic box", fhp::Model::fhp3, false, 0.0},
                                {"channel + force", fhp::Model::fhp3, true, 0.01}};
  CopyArrays copy(copyElements);
  std::printf("%-6s %-16s %7s %10s %12s %12s %9s %12s %9s\n", "model", "case", "threads",
              "copy GB/s", "Mupd/s", "roofline", "fraction", "ref Mupd/s", "speed-up");
  int unsteady = 0;
  for (const Case& c : cases) {
    const fhp::CollisionTable table = fhp::buildCollisionTable(c.model);
    const fhp::StepRules rules{.model = c.model, .seed = 3, .forceProbability = c.forceProbability,
                               .forceDirection = 0};
    fhp::BitLattice lattice = makeLattice(c, nx, ny);
    const std::uint64_t particles = lattice.particleCount();
    fhp::NodeLattice nodes = lattice.toNodes();
    const double reference = referenceRate(nodes, table, rules, 2);
    for (int threads : {1, 2}) {
      double rate = 0, bandwidth = 0;
      bool steady = false;
      for (int attempt = 0; attempt < 4 && !steady; ++attempt) {
        const double before = copy.bandwidth(threads, 5);
        rate = stepperRate(lattice, table, rules, threads, steps, 3);
        const double after = copy.bandwidth(threads, 5);
        steady = std::max(before, after) <= 1.1 * std::min(before, after);
        unsteady += !steady;
        bandwidth = 0.5 * (before + after);
      }
      const double roofline = bandwidth / (kBitsPerUpdate / 8);
      std::printf("%-6s %-16s %7d %10.2f %12.1f %12.1f %9.3f %12.1f %9.1f%s\n",
                  std::string(fluidviz::fhp::paramChoices(c.model)[static_cast<int>(c.model)].name).c_str(),
                  c.name.c_str(), threads, bandwidth / 1e9, rate / 1e6, roofline / 1e6,
                  rate / roofline, reference / 1e6, rate / reference, steady ? "" : "  (unsteady)");
      std::fflush(stdout);
    }
    if (c.forceProbability == 0.0 && lattice.particleCount() != particles)
      std::fprintf(stderr, "particle count changed: the stepper is broken\n");
  }
  std::printf("\n%d measurement(s) repeated: the copies before and after differed by more than 10 %%.\n",
              unsteady);
  std::printf("fraction = updates/s * %.3f B / copy bandwidth; speed-up = bit-plane stepper / byte "
              "reference (one thread).\n", kBitsPerUpdate / 8);
  return 0;
}
