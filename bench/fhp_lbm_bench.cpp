// FHP lattice gas against the D2Q9 LBM on the same problem: time to reach the same error.
//
// Problem: the decaying shear wave u_x = U0 exp(-nu k^2 t) sin(k y) on a periodic box, compared
// at t* = 1 / (nu k^2) (amplitude down to 1/e) with the analytic profile, on 16 bins along y
// (both the solver's profile and the analytic one averaged over the nodes of each bin). Error =
// RMS over the bins / U0.
// - FHP-I at d = 0.2, 64 rows per wavelength, U0 = 0.12 links per step, reference viscosity the
//   Boltzmann value of Frisch et al. 1987 (its departure from the lattice gas's, -2.4% here, is
//   part of the error); the profile is the row average over all nx nodes and over the steps
//   t* - W .. t* + W (W = t* / 10; the analytic profile averaged the same way). nx doubles from
//   64 until the error falls below the target: the noise falls as 1 / sqrt(nx).
// - D2Q9 BGK, tau = 0.8, u0 = 0.05 in lattice units, n nodes per wavelength doubling from 16
//   until the error is below the target.
// Time: the steps and the averaging (FHP) or the steps and reading the fields (LBM), best of
// several runs, one thread each; building and initialising the lattices is not counted.
//
// Usage: fhp_lbm_bench [target_error=0.02]
#include <omp.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "solvers/fhp/collision/CollisionTable.h"
#include "solvers/fhp/lattice/BitLattice.h"
#include "solvers/fhp/lattice/Initialisation.h"
#include "solvers/fhp/lattice/TriangularLattice.h"
#include "solvers/lbm/LbmSolver.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace fhp = fluidviz::fhp;
namespace lbm = fluidviz::lbm;
constexpr int kBins = 16;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// RMS over bins of (profile - reference), both averaged over the consecutive nodes of each bin.
double binnedError(const std::vector<double>& profile, const std::vector<double>& reference, double u0) {
  const int per = static_cast<int>(profile.size()) / kBins;
  double sum = 0;
  for (int b = 0; b < kBins; ++b) {
    double diff = 0;
    for (int i = b * per; i < (b + 1) * per; ++i) diff += profile[i] - reference[i];
    sum += (diff / per) * (diff / per);
  }
  return std::sqrt(sum / kBins) / u0;
}

struct Run {
  double error = 0, seconds = 0, nodeUpdates = 0;
};

Run fhpShearWave(int nx) {
  const fhp::Model model = fhp::Model::fhp1;
  const int ny = 64;
  const double d = 0.2, u0 = 0.12, rho = 6 * d;
  const double nu = 1.0 / (12 * d * std::pow(1 - d, 3)) - 0.125;  // Frisch et al. 1987
  const double k = 2 * std::numbers::pi / (ny * fhp::kRowSpacing);
  const int tStar = static_cast<int>(std::lround(1.0 / (nu * k * k))), window = tStar / 10;
  const fhp::CollisionTable table = fhp::buildCollisionTable(model);
  Run best{0, 1e30, 0};
  for (int repeat = 0; repeat < 2; ++repeat) {
    fhp::BitLattice lattice(nx, ny);
    fhp::fillEquilibrium(lattice, model, d,
                         [&](int, int y) {
                           return std::array<double, 2>{u0 * std::sin(2 * std::numbers::pi * y / ny), 0.0};
                         },
                         11 + repeat);
    std::vector<double> profile(ny, 0.0), reference(ny, 0.0);
    const auto t0 = Clock::now();
    for (int t = 0; t <= tStar + window; ++t) {
      if (t >= tStar - window) {
        for (int y = 0; y < ny; ++y) {
          double jx = 0;
          for (int c = 0; c < fhp::kMovingChannels; ++c) {
            int count = 0;
            for (int w = 0; w < lattice.wordsPerRow(); ++w) count += std::popcount(lattice.word(c, y, w));
            jx += fhp::kCx[c] * count;
          }
          profile[y] += jx / nx / rho / (2 * window + 1);
        }
      }
      lattice.step(table, {.model = model, .seed = 21u + static_cast<unsigned>(repeat)});
    }
    const double elapsed = seconds(t0, Clock::now());
    for (int t = tStar - window; t <= tStar + window; ++t)
      for (int y = 0; y < ny; ++y)
        reference[y] += u0 * std::exp(-nu * k * k * t) * std::sin(2 * std::numbers::pi * y / ny) /
                        (2 * window + 1);
    const double error = binnedError(profile, reference, u0);
    if (elapsed < best.seconds) best = {error, elapsed, double(nx) * ny * (tStar + window + 1)};
  }
  return best;
}

Run lbmShearWave(int n) {
  const double nuLattice = 0.1, uLattice = 0.05;  // tau = 0.8
  lbm::LbmParams p;
  p.domain_size = {1.0, 1.0};
  p.resolution = n;
  const double viscosity = 1e-3;  // m^2/s on a 1 m box
  p.viscosity = viscosity;
  const double dx = 1.0 / n, dt = nuLattice * dx * dx / viscosity;
  p.time_step = dt;
  p.end_time = 1e9;
  p.max_steps = 2'000'000'000;
  for (auto* w : {&p.walls.x_min, &p.walls.x_max, &p.walls.y_min, &p.walls.y_max})
    w->type = lbm::WallType::periodic;
  const double k = 2 * std::numbers::pi;  // one wavelength across the unit box
  const double tStar = 1.0 / (viscosity * k * k);
  const int steps = static_cast<int>(std::lround(tStar / dt));
  Run best{0, 1e30, 0};
  for (int repeat = 0; repeat < 5; ++repeat) {
    auto solver = lbm::createLbmSolver(p);
    const fluidviz::Grid& g = solver->grid();
    const double u0 = solver->units().toPhysicalVelocity(uLattice);
    std::vector<double> density(g.nodeCount(), p.density);
    std::vector<fluidviz::Vec3> velocity(g.nodeCount());
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        velocity[g.index(i, j)] = fluidviz::Vec3(u0 * std::sin(k * (j + 0.5) * dx), 0.0, 0.0);
    solver->initialise(density, velocity);
    const auto t0 = Clock::now();
    solver->step(steps);
    const fluidviz::FieldSet fields = solver->fields();
    const double elapsed = seconds(t0, Clock::now());
    const fluidviz::VectorField& v = *fields.findVector("velocity");
    std::vector<double> profile(n, 0.0), reference(n, 0.0);
    const double decay = std::exp(-viscosity * k * k * steps * dt);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) profile[j] += v.values[g.index(i, j)].x() / n;
      reference[j] = u0 * decay * std::sin(k * (j + 0.5) * dx);
    }
    const double error = binnedError(profile, reference, u0);
    if (elapsed < best.seconds) best = {error, elapsed, double(n) * n * steps};
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const double target = argc > 1 ? std::atof(argv[1]) : 0.02;
  omp_set_num_threads(1);
  std::printf("fhp_lbm_bench: decaying shear wave, error of the 16-bin profile at t* = 1/(nu k^2) "
              "against the analytic one, relative to U0; target %.3g\n\n", target);
  std::printf("%-6s %8s %12s %10s %12s\n", "solver", "size", "node upd", "error", "time s");
  double fhpTime = 0, lbmTime = 0;
  for (int nx = 64; nx <= 65536; nx *= 2) {
    const Run r = fhpShearWave(nx);
    std::printf("%-6s %8d %12.3g %10.4f %12.4g\n", "FHP-I", nx, r.nodeUpdates, r.error, r.seconds);
    std::fflush(stdout);
    if (r.error < target) {
      fhpTime = r.seconds;
      break;
    }
  }
  for (int n = 16; n <= 1024; n *= 2) {
    const Run r = lbmShearWave(n);
    std::printf("%-6s %8d %12.3g %10.4f %12.4g\n", "D2Q9", n, r.nodeUpdates, r.error, r.seconds);
    std::fflush(stdout);
    if (r.error < target) {
      lbmTime = r.seconds;
      break;
    }
  }
  if (fhpTime > 0 && lbmTime > 0)
    std::printf("\ntime to an error below %.3g: FHP-I / D2Q9 = %.3g\n", target, fhpTime / lbmTime);
  else
    std::printf("\na solver did not reach the target within the sizes tried\n");
  return 0;
}
