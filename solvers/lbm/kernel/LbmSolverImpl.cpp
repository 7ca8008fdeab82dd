#include "solvers/lbm/kernel/LbmSolverImpl.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "solvers/lbm/boundaries/RotatingRoller.h"
#include "solvers/lbm/lattice/Equilibrium.h"

namespace fluidviz::lbm {

namespace {

// 72 doubles = 9 cache lines (144 floats likewise): successive planes start at different
// offsets within a 4 KiB page, and the second array starts 4 cache lines later, so that the 2 Q
// streams of a step never all map to the same L1 sets (4K aliasing). Cheap insurance: on the
// Zen 5 test machine it made no difference beyond the run-to-run noise of lbm_bench.
constexpr std::int64_t kPlanePaddingBytes = 576;
constexpr std::int64_t kSecondArrayShiftBytes = 256;
// Below this many nodes per thread a step takes well under a millisecond and the barrier after
// it dominates -- badly so when the cores are shared with other processes (a descheduled thread
// stalls the others for a whole time slice). Small lattices therefore use fewer threads.
// Measured on the shared 2-core test machine (load ~5): the 128^2 circular Couette test took
// 0.44 s on 1 thread and 6.7 s on 2 threads with 8192 nodes per thread.
constexpr std::int64_t kMinNodesPerThread = 65536;

int threadsFor(std::int64_t nodes) {
  const std::int64_t wanted = std::max<std::int64_t>(1, nodes / kMinNodesPerThread);
  return static_cast<int>(std::min<std::int64_t>(wanted, omp_get_max_threads()));
}

Grid nodeGrid(const LatticeUnits& u, bool threeD) {
  Grid g;
  g.dims = {u.nx, u.ny, threeD ? u.nz : 1};
  g.origin = {0.5 * u.dx, 0.5 * u.dx, threeD ? 0.5 * u.dx : 0.0};
  g.spacing = {u.dx, u.dx, u.dx};
  return g;
}

std::string num(double x, int digits = 4) { return formatNumber(x, digits); }

template <class L, class T>
const LbmParams& checkedParams(const LbmParams& p) {
  const Precision wanted = std::is_same_v<T, float> ? Precision::float32 : Precision::float64;
  if (choiceName(p.lattice) != L::name || p.precision != wanted)
    throw std::invalid_argument(std::string("LbmSolverImpl<") + L::name + ", " +
                                choiceName(wanted) + "> constructed for lattice " +
                                choiceName(p.lattice) + ", precision " + choiceName(p.precision) +
                                "; use createLbmSolver");
  return p;
}

// The step kernel of one thread, compiled for three x86-64 instruction sets; the best one for
// the running CPU is picked once (bestIsaLevel, fieldviz/core/IsaLevel.h): the library stays
// portable (x86-64-v2 baseline, no -march=native) yet uses AVX2/FMA or AVX-512 where present.
// AVX-512 matters twice here: the collision of a line of nodes is one register wide, and a line
// is written back with one full-line streaming store (StreamCollidePull.h). mode: 0 BGK,
// 1 BGK forced, 2 TRT, 3 TRT forced.
template <class Isa, class L, class T>
FLUIDVIZ_LBM_INLINE void stepNodesFor(const T* post, T* next, const StepTables<L, T>& t,
                                      const NodeRange& r, const CollisionBGK& bgk,
                                      const CollisionTRT& trt, int mode) {
  switch (mode) {
    case 0: streamCollideNodes<Isa, L, T, CollisionBGK, false>(post, next, t, r, bgk); break;
    case 1: streamCollideNodes<Isa, L, T, CollisionBGK, true>(post, next, t, r, bgk); break;
    case 2: streamCollideNodes<Isa, L, T, CollisionTRT, false>(post, next, t, r, trt); break;
    default: streamCollideNodes<Isa, L, T, CollisionTRT, true>(post, next, t, r, trt); break;
  }
}

template <class L, class T>
__attribute__((noinline)) void stepNodesBase(const T* post, T* next, const StepTables<L, T>& t,
                                             const NodeRange& r, const CollisionBGK& bgk,
                                             const CollisionTRT& trt, int mode) {
  stepNodesFor<IsaBase, L, T>(post, next, t, r, bgk, trt, mode);
}

#if defined(FLUIDVIZ_LBM_MULTI_ISA)
template <class L, class T>
__attribute__((noinline, target("arch=x86-64-v3"))) void stepNodesV3(
    const T* post, T* next, const StepTables<L, T>& t, const NodeRange& r,
    const CollisionBGK& bgk, const CollisionTRT& trt, int mode) {
  stepNodesFor<IsaV3, L, T>(post, next, t, r, bgk, trt, mode);
}

template <class L, class T>
__attribute__((noinline, target("arch=x86-64-v4"))) void stepNodesV4(
    const T* post, T* next, const StepTables<L, T>& t, const NodeRange& r,
    const CollisionBGK& bgk, const CollisionTRT& trt, int mode) {
  stepNodesFor<IsaV4, L, T>(post, next, t, r, bgk, trt, mode);
}
#endif

template <class L, class T>
void stepNodes(const T* post, T* next, const StepTables<L, T>& t, const NodeRange& r,
               const CollisionBGK& bgk, const CollisionTRT& trt, int mode) {
#if defined(FLUIDVIZ_LBM_MULTI_ISA)
  const int isa = bestIsaLevel();
  if (isa == 4) return stepNodesV4<L, T>(post, next, t, r, bgk, trt, mode);
  if (isa == 3) return stepNodesV3<L, T>(post, next, t, r, bgk, trt, mode);
#endif
  stepNodesBase<L, T>(post, next, t, r, bgk, trt, mode);
}

/// The nodes of rows [rowBegin, rowEnd) and the runs and boundary nodes in them.
template <class L>
NodeRange nodeRangeOfRows(const BoundaryLinkTable<L>& table, int rowBegin, int rowEnd) {
  const std::int64_t nx = table.nx();
  if (rowBegin >= rowEnd) return {0, 0, 0, 0, 0, 0};
  const RowPlan& first = table.rows()[rowBegin];
  const RowPlan& last = table.rows()[rowEnd - 1];
  return {rowBegin * nx, rowEnd * nx, first.runBegin, last.runEnd, first.boundaryBegin,
          last.boundaryEnd};
}

}  // namespace

template <class L, class T>
LbmSolverImpl<L, T>::LbmSolverImpl(const LbmParams& params, std::vector<SolidBody> extraBodies)
    : params_(checkedParams<L, T>(params)),
      units_(computeLatticeUnits(params_)),
      grid_(nodeGrid(units_, L::D == 3)),
      bodies_(sceneBodies(params_, std::move(extraBodies))),
      populations_{PopulationArraysOf<T>(L::Q, static_cast<std::int64_t>(grid_.nodeCount()),
                                         kPlanePaddingBytes / std::int64_t(sizeof(T)), 0),
                   PopulationArraysOf<T>(L::Q, static_cast<std::int64_t>(grid_.nodeCount()),
                                         kPlanePaddingBytes / std::int64_t(sizeof(T)),
                                         kSecondArrayShiftBytes / std::int64_t(sizeof(T)))},
      table_(units_, BoxSides::fromParams(params_.walls, units_), bodies_,
             populations_[0].stride()),
      bgk_{units_.omega(), units_.latticeBodyForce[0], units_.latticeBodyForce[1],
           units_.latticeBodyForce[2]},
      trt_{units_.omega(), units_.omegaMinus(), units_.latticeBodyForce[0],
           units_.latticeBodyForce[1], units_.latticeBodyForce[2]},
      useTrt_(params_.collision == Collision::trt),
      forced_(units_.latticeBodyForce[0] != 0.0 || units_.latticeBodyForce[1] != 0.0 ||
              units_.latticeBodyForce[2] != 0.0) {
  setOpenSideRules(1);
  firstTouchAndRest();
  std::vector<double> rho;
  std::vector<Vec3> velocity;
  initialFlowFields(params_, units_, grid_, rho, velocity);
  if (!rho.empty()) initialise(rho, velocity);
}

// Equilibrium at rest, rho = 1, in both arrays (solid nodes included, although never read): as
// shifted populations that is 0. Written with the kernel's row partition so that pages land near
// the threads that use them.
template <class L, class T>
void LbmSolverImpl<L, T>::firstTouchAndRest() {
  const std::int64_t stride = populations_[0].stride(), nx = units_.nx;
  const int rows = table_.rowCount();
  const int threads = threadsFor(nx * rows);
  for (PopulationArraysOf<T>& a : populations_) {
    T* f = a.data();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int r = 0; r < rows; ++r)
      for (int q = 0; q < L::Q; ++q) std::fill_n(f + q * stride + r * nx, nx, T(0));
  }
}

template <class L, class T>
BoundaryGatherData<T> LbmSolverImpl<L, T>::gatherData() const {
  BoundaryGatherData<T> d;
  d.interpolated = table_.interpolatedLinks().data();
  d.open = openSides_;
  d.gx = T(units_.latticeBodyForce[0]);
  d.gy = T(units_.latticeBodyForce[1]);
  d.gz = T(units_.latticeBodyForce[2]);
  return d;
}

template <class L, class T>
void LbmSolverImpl<L, T>::initialise(const std::vector<double>& density,
                                     const std::vector<Vec3>& velocity) {
  const std::size_t nodes = grid_.nodeCount();
  if (density.size() != nodes || velocity.size() != nodes)
    throw std::invalid_argument("LbmSolver::initialise: expected " + std::to_string(nodes) +
                                " values per field (nx * ny * nz)");
  // Invert the pull: the population a node will gather through link (source, delta) is
  // f*[source] + delta, so store f^eq - delta at the source. Every source is used exactly once.
  // With a body force the measured velocity is sum f c / rho + g/2 (Guo et al. 2002), so the
  // equilibrium is taken at u - g/2.
  T* post = populations_[current_].data();
  const double gx = units_.latticeBodyForce[0], gy = units_.latticeBodyForce[1],
               gz = units_.latticeBodyForce[2];
  auto place = [&](std::int64_t n, int q, const PullLink& link) {
    const double rho = units_.toLatticeDensity(density[n]);
    const double ux = units_.toLatticeVelocity(velocity[n].x()) - 0.5 * gx;
    const double uy = units_.toLatticeVelocity(velocity[n].y()) - 0.5 * gy;
    const double uz = L::D == 3 ? units_.toLatticeVelocity(velocity[n].z()) - 0.5 * gz : 0.0;
    post[link.source] = static_cast<T>(shiftedEquilibrium<L>(q, rho, ux, uy, uz) - link.delta);
  };
  for (const BulkRun& run : table_.runs()) {
    const RunPattern<L::Q>& p = table_.runPatterns()[run.pattern];
    for (std::int64_t n = run.begin; n < run.end; ++n)
      for (int q = 0; q < L::Q; ++q) place(n, q, PullLink{p.source[q] + n, p.delta[q]});
  }
  for (const auto& b : table_.boundaryNodes())
    for (int q = 0; q < L::Q; ++q) place(b.node, q, b.links[q]);
  previousUx_.clear();
  steady_ = false;
}

template <class L, class T>
void LbmSolverImpl<L, T>::streamCollide(int steps) {
  const StepTables<L, T> tables{table_.stride(), table_.runs().data(), table_.runPatterns().data(),
                                table_.boundaryNodes().data(), gatherData(),
                                mixedLinePrefetchNodes(table_.nx())};
  const int rows = table_.rowCount();
  const int mode = (useTrt_ ? 2 : 0) + (forced_ ? 1 : 0);
  const int threads = threadsFor(std::int64_t(units_.nx) * rows);
  // One parallel region for all steps; each thread swaps its own copy of the two array pointers
  // after the barrier that ends a step. Static partition of the rows: each thread keeps the same
  // contiguous block of rows (and of memory) every step, and threads share at most the cache
  // lines at the two ends of their blocks.
#pragma omp parallel num_threads(threads)
  {
    const int team = omp_get_num_threads(), me = omp_get_thread_num();
    const NodeRange range =
        nodeRangeOfRows(table_, static_cast<int>(std::int64_t(rows) * me / team),
                        static_cast<int>(std::int64_t(rows) * (me + 1) / team));
    T* in = populations_[current_].data();
    T* out = populations_[1 - current_].data();
    for (int s = 0; s < steps; ++s) {
      stepNodes<L, T>(in, out, tables, range, bgk_, trt_, mode);
      fenceStreamingStores();
#pragma omp barrier
      std::swap(in, out);
    }
  }
  if (steps % 2 == 1) current_ = 1 - current_;
}

template <class L, class T>
void LbmSolverImpl<L, T>::setOpenSideRules(long long step) {
  for (int s = 0; s < 6; ++s) {
    const SideCondition& side = table_.sides().side[s];
    OpenSideRule& rule = openSides_[s];
    rule.geometry = {s / 2, s % 2 == 0 ? 1 : -1};
    rule.pressure = side.type == SideCondition::Type::Pressure;
    const double ramp = inletRampFactor(side, step);
    for (int a = 0; a < 3; ++a) rule.velocity[a] = side.velocity[a] * ramp;
    rule.drho = side.density - 1.0;
  }
}

template <class L, class T>
long long LbmSolverImpl<L, T>::rampEndStep() const {
  double end = 0.0;
  for (const SideCondition& side : table_.sides().side) end = std::max(end, side.rampSteps);
  return static_cast<long long>(std::ceil(end));
}

template <class L, class T>
void LbmSolverImpl<L, T>::step(int n) {
  // During an inlet ramp the rules change every step: one step per kernel call.
  while (n > 0 && steps_ < rampEndStep()) {
    streamCollide(1);
    ++steps_;
    --n;
    setOpenSideRules(steps_ + 1);
  }
  if (n <= 0) return;
  streamCollide(n);
  steps_ += n;
}

template <class L, class T>
typename LbmSolverImpl<L, T>::LatticeMoments LbmSolverImpl<L, T>::latticeMoments() const {
  const std::size_t nodes = grid_.nodeCount();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  LatticeMoments m{std::vector<double>(nodes, nan), std::vector<double>(nodes, nan),
                   std::vector<double>(nodes, nan), std::vector<double>(nodes, nan)};
  const T* post = populations_[current_].data();
  const BoundaryGatherData<T> data = gatherData();
  const int rows = table_.rowCount();
#pragma omp parallel for schedule(static) num_threads(threadsFor(std::int64_t(units_.nx) * rows))
  for (int r = 0; r < rows; ++r)
    gatherRow<L, T>(table_, data, post, r, [&](std::int64_t n, const T* f) {
      const NodeMoments<T> nm = nodeMoments<L, T>(f, data.gx, data.gy, data.gz);
      m.rho[n] = nm.rho;
      m.ux[n] = nm.ux;
      m.uy[n] = nm.uy;
      m.uz[n] = nm.uz;
    });
  return m;
}

template <class L, class T>
FieldSet LbmSolverImpl<L, T>::fields() const {
  const LatticeMoments m = latticeMoments();
  const std::size_t nodes = m.rho.size();
  ScalarField density{"density", grid_, std::vector<double>(nodes)};
  VectorField velocity{"velocity", grid_, std::vector<Vec3>(nodes)};
  for (int k = 0; k < grid_.dims[2]; ++k)
    for (int j = 0; j < units_.ny; ++j)
      for (int i = 0; i < units_.nx; ++i) {
        const std::size_t n = grid_.index(i, j, k);
        const int owner = table_.solidOwner()[n];
        if (owner >= 0) {
          const Vec2 u = bodies_[owner].velocity(Vec2(units_.nodeX(i), units_.nodeY(j)));
          density.values[n] = units_.density;
          velocity.values[n] = Vec3(u.x(), u.y(), 0.0);
        } else {
          density.values[n] = units_.toPhysicalDensity(m.rho[n]);
          velocity.values[n] =
              Vec3(units_.toPhysicalVelocity(m.ux[n]), units_.toPhysicalVelocity(m.uy[n]),
                   units_.toPhysicalVelocity(m.uz[n]));
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

template <class L, class T>
double LbmSolverImpl<L, T>::totalMass() const {
  // Per-row sums in long double, added in row order: deterministic for any thread count and
  // accurate enough to see a 1e-15 relative mass change. Each fluid node contributes
  // 1 + sum_q g_q (shifted populations).
  const int rows = table_.rowCount();
  std::vector<long double> rowMass(rows, 0.0L);
  const T* post = populations_[current_].data();
  const BoundaryGatherData<T> data = gatherData();
#pragma omp parallel for schedule(static) num_threads(threadsFor(std::int64_t(units_.nx) * rows))
  for (int r = 0; r < rows; ++r)
    gatherRow<L, T>(table_, data, post, r, [&](std::int64_t, const T* f) {
      long double s = 0.0L;
      for (int q = 0; q < L::Q; ++q) s += f[q];
      rowMass[r] += s;
    });
  long double total = static_cast<long double>(table_.fluidNodeCount());
  for (long double r : rowMass) total += r;
  return static_cast<double>(total);
}

template <class L, class T>
std::vector<BodyForce> LbmSolverImpl<L, T>::bodyForces() const {
  // Momentum exchange: the link from fluid node x_f into the body along c_i (i = opposite of the
  // incoming q) takes f*_i(x_f) (post-collision, last step) into the wall and returns
  // f_q(x_f, t + 1) (bounce-back with the wall's momentum, or the Bouzidi interpolation, as the
  // next gather computes it), so the body gains (f*_i + f_q) c_i per step. Populations are
  // stored shifted (g = f - w, Equilibrium.h): the weights are added back, since the links of a
  // body cut by a periodic side need not come in opposite pairs.
  std::vector<Vec3> lattice(bodies_.size(), Vec3::Zero());
  const T* post = populations_[current_].data();
  const std::int64_t stride = populations_[current_].stride();
  const BoundaryGatherData<T> data = gatherData();
  std::int32_t gathered = -1;
  T f[L::Q];
  for (const BodyLink& link : table_.bodyLinks()) {
    const BoundaryNode<L::Q>& node = table_.boundaryNodes()[link.boundary];
    if (link.boundary != gathered) {  // the links of a node are consecutive
      gatherBoundaryNode<L, T>(post, node, data, f);
      gathered = link.boundary;
    }
    const int q = link.q, i = L::opposite[q];
    const double exchanged = double(post[i * stride + node.node]) + L::w[i] + double(f[q]) + L::w[q];
    lattice[link.body] += exchanged * Vec3(L::cx[i], L::cy[i], L::cz[i]);
  }
  // Lattice force -> N: lattice mass density * dx^D (dx^2 per metre of depth in 2D) * dx / dt^2.
  const double toNewton =
      units_.density * std::pow(units_.dx, L::D) * units_.dx / (units_.dt * units_.dt);
  std::vector<BodyForce> forces;
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    forces.push_back({bodies_[b].name, lattice[b] * toNewton});
  return forces;
}

template <class L, class T>
void LbmSolverImpl<L, T>::throwInstability(std::int64_t node, const std::string& reason,
                                           const std::string& detail) const {
  const std::int64_t layer = std::int64_t(units_.nx) * units_.ny;
  const int k = static_cast<int>(node / layer);
  const int j = static_cast<int>((node % layer) / units_.nx), i = static_cast<int>(node % units_.nx);
  const double x = units_.nodeX(i), y = units_.nodeY(j), z = L::D == 3 ? units_.nodeZ(k) : 0.0;
  std::ostringstream s;
  s << "LBM run became unstable at step " << steps_ << " (t = " << num(time()) << " s) at node ("
    << num(x) << ", " << num(y);
  if (L::D == 3) s << ", " << num(z);
  s << ") m: " << detail << ". Settings: " << L::name << ", "
    << (useTrt_ ? "TRT" : "BGK") << ", tau = " << num(units_.tau) << ", lattice velocity "
    << num(units_.latticeVelocity) << ". To fix: ";
  if (units_.tau < 0.55)
    s << "tau is close to 1/2 (the resolution is too coarse for this Reynolds number): raise "
         "lbm.resolution or lower lbm.reynolds (or raise lbm.viscosity)"
      << (useTrt_ ? "" : ", or use lbm.collision = trt") << "; ";
  if (forced_) s << "lower lbm.body_force or lbm.time_step (the force accelerates the flow); ";
  s << "lower lbm.lattice_velocity (or lbm.time_step when nothing moves)";
  throw InstabilityError(steps_, x, y, z, reason, s.str());
}

template <class L, class T>
void LbmSolverImpl<L, T>::checkStability() const {
  const LatticeMoments m = latticeMoments();
  const double limit = LatticeStabilityLimits::maxSpeed;
  for (std::size_t n = 0; n < m.rho.size(); ++n) {
    if (table_.isSolid(static_cast<std::int64_t>(n))) continue;
    const double rho = m.rho[n];
    const double speed = std::sqrt(m.ux[n] * m.ux[n] + m.uy[n] * m.uy[n] + m.uz[n] * m.uz[n]);
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

template <class L, class T>
double LbmSolverImpl<L, T>::maxVelocityChange() {
  LatticeMoments m = latticeMoments();
  double change = 0.0, scale = 0.0;
  const bool first = previousUx_.empty();
  for (std::size_t n = 0; n < m.rho.size(); ++n) {
    if (table_.isSolid(static_cast<std::int64_t>(n))) continue;
    scale = std::max(scale, std::sqrt(m.ux[n] * m.ux[n] + m.uy[n] * m.uy[n] + m.uz[n] * m.uz[n]));
    if (!first) {
      const double dx = m.ux[n] - previousUx_[n], dy = m.uy[n] - previousUy_[n],
                   dz = m.uz[n] - previousUz_[n];
      change = std::max(change, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  }
  previousUx_ = std::move(m.ux);
  previousUy_ = std::move(m.uy);
  previousUz_ = std::move(m.uz);
  if (first) return std::numeric_limits<double>::infinity();
  return scale > 0.0 ? change / scale : change;
}

template class LbmSolverImpl<LatticeD2Q9, double>;
template class LbmSolverImpl<LatticeD2Q9, float>;
template class LbmSolverImpl<LatticeD3Q19, double>;
template class LbmSolverImpl<LatticeD3Q19, float>;

}  // namespace fluidviz::lbm
