#include "solvers/lbm/LbmSolverD2Q9.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "solvers/lbm/Equilibrium.h"
#include "solvers/lbm/RotatingRoller.h"
#include "solvers/lbm/StreamCollidePull.h"

namespace fluidviz::lbm {

namespace {

using L = LatticeD2Q9;

// 72 doubles = 9 cache lines: successive planes start at different offsets within a 4 KiB page,
// and the second array starts 4 cache lines later, so that the 18 streams of a step never all
// map to the same L1 sets (4K aliasing). Cheap insurance: on the Zen 5 test machine it made no
// difference beyond the run-to-run noise of lbm_bench.
constexpr std::int64_t kPlanePadding = 72;
constexpr std::int64_t kSecondArrayShift = 32;
// Below this many nodes per thread a step takes only tens of microseconds and the barrier after
// it dominates -- badly so when the cores are shared with other processes (a descheduled thread
// stalls the others for a whole time slice). Small lattices therefore use fewer threads.
constexpr std::int64_t kMinNodesPerThread = 8192;

int threadsFor(std::int64_t nodes) {
  const std::int64_t wanted = std::max<std::int64_t>(1, nodes / kMinNodesPerThread);
  return static_cast<int>(std::min<std::int64_t>(wanted, omp_get_max_threads()));
}

std::vector<SolidBody> allBodies(const LbmParams& p, std::vector<SolidBody> extra) {
  std::vector<SolidBody> bodies;
  for (std::size_t i = 0; i < p.rollers.size(); ++i)
    bodies.push_back(rotatingRoller(p.rollers[i], "rollers[" + std::to_string(i) + "]"));
  for (SolidBody& b : extra) bodies.push_back(std::move(b));
  return bodies;
}

Grid nodeGrid(const LatticeUnits& u) {
  Grid g;
  g.dims = {u.nx, u.ny, 1};
  g.origin = {0.5 * u.dx, 0.5 * u.dx, 0.0};
  g.spacing = {u.dx, u.dx, u.dx};
  return g;
}

std::string num(double x, int digits = 4) {
  std::ostringstream s;
  s.precision(digits);
  s << x;
  return s.str();
}

}  // namespace

LbmSolverD2Q9::LbmSolverD2Q9(const LbmParams& params, std::vector<SolidBody> extraBodies)
    : params_(params),
      units_(computeLatticeUnits(params_)),
      grid_(nodeGrid(units_)),
      bodies_(allBodies(params_, std::move(extraBodies))),
      populations_{PopulationArrays(L::Q, std::int64_t(units_.nx) * units_.ny, kPlanePadding, 0),
                   PopulationArrays(L::Q, std::int64_t(units_.nx) * units_.ny, kPlanePadding,
                                    kSecondArrayShift)},
      table_(units_, BoxSides::fromParams(params_.walls, units_), bodies_,
             populations_[0].stride()),
      collision_{units_.omega(), units_.latticeBodyForce[0], units_.latticeBodyForce[1]},
      forced_(units_.latticeBodyForce[0] != 0.0 || units_.latticeBodyForce[1] != 0.0) {
  firstTouchAndRest();
}

// Equilibrium at rest, rho = 1, in both arrays (solid nodes included, although never read).
// Written with the kernel's row partition so that pages land near the threads that use them.
void LbmSolverD2Q9::firstTouchAndRest() {
  const std::int64_t stride = populations_[0].stride(), nx = units_.nx;
  const int threads = threadsFor(nx * units_.ny);
  for (PopulationArrays& a : populations_) {
    double* f = a.data();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int j = 0; j < units_.ny; ++j)
      for (int q = 0; q < L::Q; ++q) std::fill_n(f + q * stride + j * nx, nx, L::w[q]);
  }
}

void LbmSolverD2Q9::initialise(const std::vector<double>& density,
                               const std::vector<Vec3>& velocity) {
  const std::size_t nodes = std::size_t(units_.nx) * units_.ny;
  if (density.size() != nodes || velocity.size() != nodes)
    throw std::invalid_argument("LbmSolverD2Q9::initialise: expected " + std::to_string(nodes) +
                                " values per field (nx * ny)");
  // Invert the pull: the population a node will gather through link (source, delta) is
  // f*[source] + delta, so store f^eq - delta at the source. Every source is used exactly once.
  // With a body force the measured velocity is sum f c / rho + g/2 (Guo et al. 2002), so the
  // equilibrium is taken at u - g/2.
  double* post = populations_[current_].data();
  const std::int64_t stride = table_.stride();
  const double gx = units_.latticeBodyForce[0], gy = units_.latticeBodyForce[1];
  auto place = [&](std::int64_t n, int q, const PullLink& link) {
    const double rho = units_.toLatticeDensity(density[n]);
    const double ux = units_.toLatticeVelocity(velocity[n].x()) - 0.5 * gx;
    const double uy = units_.toLatticeVelocity(velocity[n].y()) - 0.5 * gy;
    post[link.source] = equilibrium<L>(q, rho, ux, uy) - link.delta;
  };
  for (const BulkRun& run : table_.runs())
    for (std::int64_t n = run.begin; n < run.end; ++n)
      for (int q = 0; q < L::Q; ++q)
        place(n, q, PullLink{q * stride + n - table_.bulkOffset(q), 0.0});
  for (const BoundaryNode& b : table_.boundaryNodes())
    for (int q = 0; q < L::Q; ++q) place(b.node, q, b.links[q]);
  previousUx_.clear();
  steady_ = false;
}

namespace {

// Everything one row of the stream-collide step needs.
struct RowKernelArgs {
  const double* post;
  double* next;
  std::int64_t stride;
  std::int64_t offset[L::Q];
  const RowPlan* rows;
  const BulkRun* runs;
  const BoundaryNode* boundary;
  CollisionBGK collision;
};

template <bool Forced>
FLUIDVIZ_LBM_INLINE void streamCollideRowImpl(const RowKernelArgs& a, int j) {
  const RowPlan& row = a.rows[j];
  for (std::int64_t r = row.runBegin; r < row.runEnd; ++r)
    streamCollideBulkRun<L, CollisionBGK, Forced>(a.post, a.next, a.stride, a.offset, a.runs[r],
                                                  a.collision);
  for (std::int64_t b = row.boundaryBegin; b < row.boundaryEnd; ++b)
    streamCollideBoundaryNode<L, CollisionBGK, Forced>(a.post, a.next, a.stride, a.boundary[b],
                                                       a.collision);
}

// The row kernel is compiled for three instruction sets and the best one for the running CPU is
// picked when the library loads (GCC function multi-versioning): the library stays portable
// (x86-64-v2 baseline, no -march=native) yet uses AVX2/FMA or AVX-512 vectors where present.
// At SSE width the kernel is compute bound: lbm_bench, 1024^2, 1 thread, measured 93 MLUPS
// without the clones and 155-160 MLUPS with them (the 9-plane copy ceiling is 145-170).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define FLUIDVIZ_LBM_KERNEL_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define FLUIDVIZ_LBM_KERNEL_CLONES
#endif

FLUIDVIZ_LBM_KERNEL_CLONES void streamCollideRow(const RowKernelArgs& a, int j) {
  streamCollideRowImpl<false>(a, j);
}
FLUIDVIZ_LBM_KERNEL_CLONES void streamCollideRowForced(const RowKernelArgs& a, int j) {
  streamCollideRowImpl<true>(a, j);
}

}  // namespace

void LbmSolverD2Q9::streamCollide(int steps) {
  RowKernelArgs args{nullptr,
                     nullptr,
                     table_.stride(),
                     {},
                     table_.rows().data(),
                     table_.runs().data(),
                     table_.boundaryNodes().data(),
                     collision_};
  for (int q = 0; q < L::Q; ++q) args.offset[q] = table_.bulkOffset(q);
  const int ny = units_.ny;
  const bool forced = forced_;
  const int threads = threadsFor(std::int64_t(units_.nx) * ny);
  // One parallel region for all steps; each thread swaps its own copy of the two array pointers
  // after the implicit barrier of the work-sharing loop. Static schedule over rows: each thread
  // keeps the same contiguous block of rows (and of memory) every step, and threads share at
  // most the cache lines at the two ends of their blocks.
#pragma omp parallel num_threads(threads) firstprivate(args)
  {
    double* in = populations_[current_].data();
    double* out = populations_[1 - current_].data();
    for (int s = 0; s < steps; ++s) {
      args.post = in;
      args.next = out;
#pragma omp for schedule(static)
      for (int j = 0; j < ny; ++j) {
        if (forced)
          streamCollideRowForced(args, j);
        else
          streamCollideRow(args, j);
      }
      std::swap(in, out);
    }
  }
  if (steps % 2 == 1) current_ = 1 - current_;
}

void LbmSolverD2Q9::step(int n) {
  if (n <= 0) return;
  streamCollide(n);
  steps_ += n;
}

LbmSolverD2Q9::LatticeMoments LbmSolverD2Q9::latticeMoments() const {
  const std::size_t nodes = std::size_t(units_.nx) * units_.ny;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  LatticeMoments m{std::vector<double>(nodes, nan), std::vector<double>(nodes, nan),
                   std::vector<double>(nodes, nan)};
  const double* post = populations_[current_].data();
  const double gx = units_.latticeBodyForce[0], gy = units_.latticeBodyForce[1];
#pragma omp parallel for schedule(static) \
    num_threads(threadsFor(std::int64_t(units_.nx) * units_.ny))
  for (int j = 0; j < units_.ny; ++j)
    gatherRow<L>(table_, post, j, [&](std::int64_t n, const double* f) {
      const NodeMoments nm = nodeMoments<L>(f, gx, gy);
      m.rho[n] = nm.rho;
      m.ux[n] = nm.ux;
      m.uy[n] = nm.uy;
    });
  return m;
}

FieldSet LbmSolverD2Q9::fields() const {
  const LatticeMoments m = latticeMoments();
  const std::size_t nodes = m.rho.size();
  ScalarField density{"density", grid_, std::vector<double>(nodes)};
  VectorField velocity{"velocity", grid_, std::vector<Vec3>(nodes)};
  for (int j = 0; j < units_.ny; ++j)
    for (int i = 0; i < units_.nx; ++i) {
      const std::size_t n = std::size_t(j) * units_.nx + i;
      const int owner = table_.solidOwner()[n];
      if (owner >= 0) {
        const Vec2 u = bodies_[owner].velocity(Vec2(units_.nodeX(i), units_.nodeY(j)));
        density.values[n] = units_.density;
        velocity.values[n] = Vec3(u.x(), u.y(), 0.0);
      } else {
        density.values[n] = units_.toPhysicalDensity(m.rho[n]);
        velocity.values[n] =
            Vec3(units_.toPhysicalVelocity(m.ux[n]), units_.toPhysicalVelocity(m.uy[n]), 0.0);
      }
    }
  FieldSet set;
  set.grid = grid_;
  ScalarField speed = magnitude(velocity, "speed");
  set.add(std::move(velocity));
  set.add(std::move(density));
  set.add(std::move(speed));
  return set;
}

double LbmSolverD2Q9::totalMass() const {
  // Per-row sums in long double, added in row order: deterministic for any thread count and
  // accurate enough to see a 1e-15 relative mass change.
  std::vector<long double> rowMass(units_.ny, 0.0L);
  const double* post = populations_[current_].data();
#pragma omp parallel for schedule(static) \
    num_threads(threadsFor(std::int64_t(units_.nx) * units_.ny))
  for (int j = 0; j < units_.ny; ++j)
    gatherRow<L>(table_, post, j, [&](std::int64_t, const double* f) {
      for (int q = 0; q < L::Q; ++q) rowMass[j] += f[q];
    });
  long double total = 0.0L;
  for (long double r : rowMass) total += r;
  return static_cast<double>(total);
}

void LbmSolverD2Q9::throwInstability(std::int64_t node, const std::string& reason,
                                     const std::string& detail) const {
  const int i = static_cast<int>(node % units_.nx), j = static_cast<int>(node / units_.nx);
  const double x = units_.nodeX(i), y = units_.nodeY(j);
  std::ostringstream s;
  s << "LBM run became unstable at step " << steps_ << " (t = " << num(time()) << " s) at node ("
    << num(x) << ", " << num(y) << ") m: " << detail << ". Settings: tau = " << num(units_.tau)
    << ", lattice velocity " << num(units_.latticeVelocity) << ". To fix: ";
  if (units_.tau < 0.55)
    s << "tau is close to 1/2, raise lbm.resolution or lower lbm.reynolds (or raise "
         "lbm.viscosity); ";
  if (forced_) s << "lower lbm.body_force or lbm.time_step (the force accelerates the flow); ";
  s << "lower lbm.lattice_velocity (or lbm.time_step when nothing moves)";
  throw InstabilityError(steps_, x, y, reason, s.str());
}

void LbmSolverD2Q9::checkStability() const {
  const LatticeMoments m = latticeMoments();
  const double limit = LatticeStabilityLimits::maxSpeed;
  for (std::size_t n = 0; n < m.rho.size(); ++n) {
    if (table_.isSolid(static_cast<std::int64_t>(n))) continue;
    const double rho = m.rho[n], speed = std::hypot(m.ux[n], m.uy[n]);
    if (std::isnan(rho) || std::isnan(speed))
      throwInstability(n, "NaN", "density or velocity is NaN");
    if (rho <= 0.0)
      throwInstability(n, "negative density", "lattice density " + num(rho) + " is not positive");
    if (speed > limit)
      throwInstability(n, "lattice speed past limit",
                       "lattice speed " + num(speed) + " exceeds " + num(limit) + " (Mach " +
                           num(speed * std::sqrt(3.0)) + ")");
  }
}

double LbmSolverD2Q9::maxVelocityChange() {
  LatticeMoments m = latticeMoments();
  double change = 0.0, scale = 0.0;
  const bool first = previousUx_.empty();
  for (std::size_t n = 0; n < m.rho.size(); ++n) {
    if (table_.isSolid(static_cast<std::int64_t>(n))) continue;
    scale = std::max(scale, std::hypot(m.ux[n], m.uy[n]));
    if (!first)
      change = std::max(change, std::hypot(m.ux[n] - previousUx_[n], m.uy[n] - previousUy_[n]));
  }
  previousUx_ = std::move(m.ux);
  previousUy_ = std::move(m.uy);
  if (first) return std::numeric_limits<double>::infinity();
  return scale > 0.0 ? change / scale : change;
}

StopReason LbmSolverD2Q9::advance(double targetTime) {
  const double dt = units_.dt;
  auto stepsTo = [dt](double t) { return static_cast<long long>(std::ceil(t / dt - 1e-9)); };
  const long long endStep = std::min<long long>(stepsTo(params_.end_time), params_.max_steps);
  const long long target = std::min(stepsTo(targetTime), endStep);
  const int interval = params_.check_interval;
  while (steps_ < target && !steady_) {
    // Run up to the next multiple of check_interval so that checks fall on fixed steps.
    const long long nextCheck = (steps_ / interval + 1) * interval;
    const long long chunk = std::min(nextCheck, target) - steps_;
    step(static_cast<int>(chunk));
    if (steps_ % interval != 0) continue;
    checkStability();
    if (params_.steady_tolerance > 0.0 && maxVelocityChange() < params_.steady_tolerance)
      steady_ = true;
  }
  if (steady_) return StopReason::Steady;
  if (steps_ >= stepsTo(params_.end_time)) return StopReason::EndTime;
  if (steps_ >= params_.max_steps) return StopReason::MaxSteps;
  return StopReason::ReachedTime;
}

}  // namespace fluidviz::lbm
