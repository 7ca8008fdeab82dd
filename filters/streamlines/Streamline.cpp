#include "filters/streamlines/Streamline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fieldviz/core/Sampling.h"

namespace fluidviz::streamlines {

namespace {

// Steps are bisected down to this length (cells) before a failed step counts as an exit: the
// exit point is then found to about this accuracy before the final straight extension.
constexpr double kBisectionLimit = 1e-6;

// Butcher tableaux (row i of a holds a_{i,0..i-1}; b the weights of the solution).
struct Tableau {
  int stages;
  double a[7][6];
  double b[7];
  double e[7];  // b - b_hat of an embedded pair: weights of the local error estimate
};
// Explicit midpoint rule (order 2).
constexpr Tableau kMidpoint = {2, {{}, {0.5}}, {0.0, 1.0}, {}};
// Classical Runge-Kutta (order 4).
constexpr Tableau kClassicalRk4 = {
    4, {{}, {0.5}, {0.0, 0.5}, {0.0, 0.0, 1.0}}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}, {}};
// Dormand & Prince (1980), "A family of embedded Runge-Kutta formulae", J. Comp. Appl. Math. 6:
// the RK5(4)7M tableau. b gives the order-5 solution (equal to the last row, "first same as
// last"), e = b5 - b4 the error estimate weights.
constexpr Tableau kDormandPrince = {
    7,
    {{},
     {1.0 / 5},
     {3.0 / 40, 9.0 / 40},
     {44.0 / 45, -56.0 / 15, 32.0 / 9},
     {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
     {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
     {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0.0},
    {35.0 / 384 - 5179.0 / 57600, 0.0, 500.0 / 1113 - 7571.0 / 16695, 125.0 / 192 - 393.0 / 640,
     -2187.0 / 6784 + 92097.0 / 339200, 11.0 / 84 - 187.0 / 2100, -1.0 / 40}};

const Tableau& tableauOf(Integrator integrator) {
  switch (integrator) {
    case Integrator::rk2: return kMidpoint;
    case Integrator::rk4: return kClassicalRk4;
    case Integrator::rk45: return kDormandPrince;
  }
  return kClassicalRk4;
}

// A line that makes no headway ends as stagnant: over the last kStuckWindow steps it got less
// than kStuckHeadway of the summed step lengths away (steps whose stages cancel move nothing). It circles or jitters about a zero it cannot
// resolve with its step (a sink, or a converging line between opposed flows: issue 15, defect 2),
// where |v| need not fall below stagnation_speed at any point the steps land on.
constexpr int kStuckWindow = 8;
constexpr double kStuckHeadway = 0.25;

double distancePointSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double maxFiniteSpeed(const VectorField& f) {
  double m = 0.0;
  const bool planar = f.grid.is2D();
  for (const Vec3& v : f.values) {
    const double s = planar ? std::hypot(v.x(), v.y()) : v.norm();
    if (std::isfinite(s)) m = std::max(m, s);
  }
  return m;
}

// stepped[i]: the summed lengths h of the steps up to point i.
bool isStuck(const std::vector<Vec3>& q, const std::vector<double>& stepped) {
  const std::size_t n = q.size();
  if (n <= kStuckWindow) return false;
  const std::size_t first = n - 1 - kStuckWindow;
  return (q.back() - q[first]).norm() < kStuckHeadway * (stepped.back() - stepped[first]);
}

}  // namespace

const char* toString(TerminationReason r) {
  switch (r) {
    case TerminationReason::not_traced: return "not_traced";
    case TerminationReason::domain_exit: return "domain_exit";
    case TerminationReason::stagnation: return "stagnation";
    case TerminationReason::max_length: return "max_length";
    case TerminationReason::max_steps: return "max_steps";
    case TerminationReason::closed_loop: return "closed_loop";
    case TerminationReason::nan_in_field: return "nan_in_field";
    case TerminationReason::too_close: return "too_close";
  }
  return "unknown";
}

// One direction of a line, in index space, starting with the seed.
struct StreamlineTracer::Branch {
  std::vector<Vec3> q;
  std::vector<double> times;
  std::vector<double> speeds;
  TerminationReason reason = TerminationReason::not_traced;
};

struct StreamlineTracer::StepResult {
  enum Status { ok, outside, not_finite, zero_speed } status = ok;
  Vec3 q;          // end point (index space)
  Vec3 v;          // index-space velocity at q (unsigned), reused by the next step
  double dt = 0;   // time step taken (s, > 0)
  double err = 0;  // rk45: local error estimate (cells)
};

StreamlineTracer::StreamlineTracer(const VectorField& field, StreamlineParams params)
    : field_(field), params_(std::move(params)) {
  validateStreamlineParams(params_);
  field_.grid.validate();
  if (field_.values.size() != field_.grid.nodeCount())
    throw std::invalid_argument("vector field '" + field_.name + "' has " +
                                std::to_string(field_.values.size()) + " values, its grid " +
                                std::to_string(field_.grid.nodeCount()) + " nodes");
  max_speed_ = maxFiniteSpeed(field_);
}

bool StreamlineTracer::insideIndex(const Vec3& q) const {
  const double eps = 1e-9;
  for (int a = 0; a < 3; ++a) {
    const int n = field_.grid.dims[a];
    if (q[a] < -eps || q[a] > (n - 1) + eps) return false;
  }
  return true;
}

// Index-space velocity (cells / s) at q; false when q is outside the grid.
bool StreamlineTracer::velocityAt(const Vec3& q, Vec3& v_index, bool& finite) const {
  if (!insideIndex(q)) return false;
  const auto v = sampleIndexSpace(field_, q);
  if (!v) return false;
  const auto& h = field_.grid.spacing;
  v_index = Vec3(v->x() / h[0], v->y() / h[1], field_.grid.is2D() ? 0.0 : v->z() / h[2]);
  finite = v_index.allFinite();
  return true;
}

double StreamlineTracer::worldSpeed(const Vec3& v_index) const {
  const auto& h = field_.grid.spacing;
  return Vec3(v_index.x() * h[0], v_index.y() * h[1], v_index.z() * h[2]).norm();
}

Vec3 StreamlineTracer::toWorld(const Vec3& q) const {
  const Grid& g = field_.grid;
  return {g.origin[0] + q.x() * g.spacing[0], g.origin[1] + q.y() * g.spacing[1],
          g.origin[2] + q.z() * g.spacing[2]};
}

// One Runge-Kutta step of arc length h along sign * v, in the arc-length parametrisation
// dx/ds = v / |v| with dt/ds = 1 / |v| integrated by the same stages: every stage moves at most h,
// so the step is at most h long however fast |v| changes across it (with positive weights; rk45's
// negative weight is checked by the caller), and times stay of the method's order. A step of
// dt = h / |v(x_n)| with unnormalised stages jumped 5-40 cells near slow points (issue 15, defect 1).
StreamlineTracer::StepResult StreamlineTracer::rkStep(const Vec3& q, const Vec3& v, double h,
                                                      double sign) const {
  const Tableau& tab = tableauOf(params_.integrator);
  StepResult r;
  Vec3 dir[7], k = v;
  double slowness[7];
  for (int i = 0; i < tab.stages; ++i) {
    if (i > 0) {
      Vec3 at = q;
      for (int j = 0; j < i; ++j) at += sign * h * tab.a[i][j] * dir[j];
      bool finite = true;
      if (!velocityAt(at, k, finite)) return r.status = StepResult::outside, r;
      if (!finite) return r.status = StepResult::not_finite, r;
    }
    const double speed = k.norm();
    if (speed == 0.0) return r.status = StepResult::zero_speed, r;
    dir[i] = k / speed;
    slowness[i] = 1.0 / speed;
  }
  r.q = q;
  Vec3 e = Vec3::Zero();
  for (int i = 0; i < tab.stages; ++i) {
    r.q += sign * h * tab.b[i] * dir[i];
    r.dt += h * tab.b[i] * slowness[i];
    e += h * tab.e[i] * dir[i];
  }
  r.err = e.norm();
  // rk45's negative weight can make the quadrature of 1 / |v| negative where |v| varies wildly
  // within the step: refused like a step across a zero (the caller shortens it).
  if (!(r.dt > 0.0)) return r.status = StepResult::zero_speed, r;
  if (params_.integrator == Integrator::rk45) {
    r.v = k;  // FSAL: the last stage is the velocity at the new point
    return r;
  }
  bool finite = true;
  if (!velocityAt(r.q, r.v, finite)) r.status = StepResult::outside;
  else if (!finite) r.status = StepResult::not_finite;
  return r;
}

StreamlineTracer::Branch StreamlineTracer::traceBranch(const Vec3& seed, Direction dir,
                                                       const StopRule& stop,
                                                       double maxLength) const {
  Branch b;
  Vec3 v;
  bool finite = true;
  if (!velocityAt(seed, v, finite)) {
    b.reason = TerminationReason::domain_exit;
    return b;
  }
  if (!finite) {
    b.reason = TerminationReason::nan_in_field;
    return b;
  }
  const double sign = dir == Direction::forward ? 1.0 : -1.0;
  auto isStagnant = [&](double speed) {
    return speed == 0.0 || speed <= params_.stagnation_speed * max_speed_;
  };
  auto push = [&](const Vec3& q, double t, double speed) {
    b.q.push_back(q);
    b.times.push_back(t);
    b.speeds.push_back(speed);
  };
  push(seed, 0.0, worldSpeed(v));
  if (isStagnant(b.speeds.back())) {
    b.reason = TerminationReason::stagnation;
    return b;
  }

  Vec3 q = seed;
  double h = params_.step;  // rk45: the controller's step
  double cap = std::numeric_limits<double>::infinity();  // bisection cap after a failed step
  double length = 0.0, t = 0.0;
  int steps = 0;
  bool leftSeed = false;
  const double lengthEps = 1e-9 * std::max(1.0, maxLength);
  std::vector<double> stepped{0.0};  // summed step lengths at each point of b.q
  while (true) {
    if (steps >= params_.max_steps) {
      b.reason = TerminationReason::max_steps;
      break;
    }
    const double remaining = maxLength - length;
    if (remaining <= lengthEps) {
      b.reason = TerminationReason::max_length;
      break;
    }
    const double hTry = std::min({h, remaining, cap});
    const StepResult r = rkStep(q, v, hTry, sign);

    if (r.status != StepResult::ok) {
      if (hTry > kBisectionLimit) {
        cap = 0.5 * hTry;
        continue;
      }
      if (r.status == StepResult::not_finite) {
        b.reason = TerminationReason::nan_in_field;
        break;
      }
      if (r.status == StepResult::zero_speed) {  // ran into v = 0 (a no-slip solid, a zero)
        b.reason = TerminationReason::stagnation;
        break;
      }
      // Exit: extend straight along v to the boundary; the remaining distance is below the
      // bisection limit unless v runs nearly parallel to the boundary, where we project instead.
      b.reason = TerminationReason::domain_exit;
      const Vec3 u = sign * v.normalized();
      double d = std::numeric_limits<double>::infinity();
      int axis = -1;
      for (int a = 0; a < 3; ++a) {
        if (field_.grid.dims[a] == 1 || u[a] == 0.0) continue;
        const double bound = u[a] > 0 ? field_.grid.dims[a] - 1 : 0.0;
        const double da = std::max(0.0, (bound - q[a]) / u[a]);
        if (da < d) d = da, axis = a;
      }
      Vec3 end = q;
      if (axis >= 0 && d <= 1e3 * kBisectionLimit) {
        end = q + d * u;
        end[axis] = u[axis] > 0 ? field_.grid.dims[axis] - 1 : 0.0;
      } else {  // project onto the nearest face
        double best = std::numeric_limits<double>::infinity();
        for (int a = 0; a < 3; ++a) {
          const int n = field_.grid.dims[a];
          if (n == 1) continue;
          if (q[a] < best) best = q[a], axis = a, end = q, end[a] = 0.0;
          if (n - 1 - q[a] < best) best = n - 1 - q[a], axis = a, end = q, end[a] = n - 1;
        }
        d = (end - q).norm();
      }
      for (int a = 0; a < 3; ++a)
        end[a] = std::clamp(end[a], 0.0, double(field_.grid.dims[a] - 1));
      Vec3 vEnd;
      bool endFinite = true;
      if (d > 0 && velocityAt(end, vEnd, endFinite) && endFinite &&
          !(stop && stop(StepInfo{toWorld(end), dir, length + d}))) {
        push(end, t + sign * d / v.norm(), worldSpeed(vEnd));
      } else if (d == 0) {
        b.q.back() = end;  // already on the boundary (round-off): snap
      }
      break;
    }

    if (params_.integrator == Integrator::rk45) {
      const double errPerCell = r.err / hTry;
      const double factor =
          std::clamp(0.9 * std::pow(params_.tolerance / std::max(errPerCell, 1e-300), 0.25),
                     0.2, 5.0);
      if (errPerCell > params_.tolerance && hTry > params_.min_step) {
        h = std::max(params_.min_step, hTry * factor);
        continue;
      }
      if (hTry == h) h = std::clamp(h * factor, params_.min_step, params_.max_step);
    }

    const double segment = (r.q - q).norm();
    if (segment > hTry * (1 + 1e-12) && hTry > params_.min_step) {  // rk45's negative weight
      h = std::max(params_.min_step, 0.5 * hTry);
      continue;
    }
    if (stop && stop(StepInfo{toWorld(r.q), dir, length + segment})) {
      b.reason = TerminationReason::too_close;
      break;
    }
    t += sign * r.dt;
    length += segment;
    ++steps;
    push(r.q, t, worldSpeed(r.v));
    if (std::isfinite(cap)) cap = 2 * cap >= h ? std::numeric_limits<double>::infinity() : 2 * cap;

    if (params_.loop_detection) {
      if (leftSeed && distancePointSegment(seed, q, r.q) < params_.closing_distance) {
        b.reason = TerminationReason::closed_loop;
        break;
      }
      if ((r.q - seed).norm() > 2.0 * params_.closing_distance) leftSeed = true;
    }
    q = r.q;
    v = r.v;
    stepped.push_back(stepped.back() + hTry);
    if (isStuck(b.q, stepped)) {
      endAtSlowestOfStuckWindow(b);
      b.reason = TerminationReason::stagnation;
      break;
    }
    if (isStagnant(b.speeds.back())) {
      b.reason = TerminationReason::stagnation;
      break;
    }
  }
  return b;
}

// A stuck line jitters over the zero it cannot resolve (a midpoint step can swing between two
// points up to a step either side): it ends at the slowest of those points, the nearest to it.
void StreamlineTracer::endAtSlowestOfStuckWindow(Branch& b) {
  const auto window = b.speeds.end() - (kStuckWindow + 1);
  const std::size_t end = std::min_element(window, b.speeds.end()) - b.speeds.begin() + 1;
  b.q.resize(end);
  b.times.resize(end);
  b.speeds.resize(end);
}

Streamline StreamlineTracer::trace(const Vec3& seed_world, const StopRule& stop) const {
  return trace(seed_world, stop, params_.max_length);
}

Streamline StreamlineTracer::trace(const Vec3& seed_world, const StopRule& stop,
                                   double maxLength) const {
  const Vec3 seed = field_.grid.toIndexSpace(seed_world);
  const bool forward = params_.direction != TraceDirection::backward;
  const bool backward = params_.direction != TraceDirection::forward;
  Branch fw, bw;
  if (forward) fw = traceBranch(seed, Direction::forward, stop, maxLength);
  if (backward) {
    if (forward && fw.reason == TerminationReason::closed_loop)
      bw.reason = TerminationReason::closed_loop;  // the loop is complete already
    else
      bw = traceBranch(seed, Direction::backward, stop, maxLength);
  }

  Streamline line;
  line.forward_end = fw.reason;
  line.backward_end = bw.reason;
  // Backward branch reversed (without its seed when the forward branch supplies it), then forward.
  const std::size_t skip = fw.q.empty() ? 0 : 1;
  for (std::size_t i = bw.q.size(); i-- > skip;) {
    line.points.push_back(toWorld(bw.q[i]));
    line.times.push_back(bw.times[i]);
    line.speeds.push_back(bw.speeds[i]);
  }
  line.seed_index = line.points.empty() ? 0 : line.points.size() - (fw.q.empty() ? 1 : 0);
  for (std::size_t i = 0; i < fw.q.size(); ++i) {
    line.points.push_back(toWorld(fw.q[i]));
    line.times.push_back(fw.times[i]);
    line.speeds.push_back(fw.speeds[i]);
  }
  if (line.points.empty()) line.seed_index = 0;
  return line;
}

Streamline traceStreamline(const VectorField& field, const Vec3& seed_world,
                           const StreamlineParams& params) {
  return StreamlineTracer(field, params).trace(seed_world);
}

std::vector<Streamline> traceStreamlines(const VectorField& field, const std::vector<Vec3>& seeds,
                                         const StreamlineParams& params) {
  const StreamlineTracer tracer(field, params);
  std::vector<Streamline> lines(seeds.size());
  const long n = static_cast<long>(seeds.size());
#pragma omp parallel for schedule(dynamic, 4)
  for (long i = 0; i < n; ++i) lines[i] = tracer.trace(seeds[i]);
  return lines;
}

}  // namespace fluidviz::streamlines
