#pragma once
// The streamline integrator shared by the whole project.
//
//   StreamlineTracer tracer(field, params);      // validates, finds max|v| once
//   Streamline line = tracer.trace(seed_world);  // thread-safe: trace many seeds in parallel
//   // or, for one seed:  traceStreamline(field, seed_world, params)
//   // or, for many:      traceStreamlines(field, seeds, params)   (OpenMP over seeds)
//
// Integration runs in index space (cells) so that `step` and `max_length` mean the same on any
// grid; points are returned in world coordinates. The lines are those of dx/dt = v(x) with v
// interpolated (bi/trilinear, fieldviz/core/Sampling.h), integrated in arc length s:
// dx/ds = v / |v|, dt/ds = 1 / |v|, with the same Runge-Kutta stages for both. So no step is
// longer than its h (rk2, rk4; rk45 refuses a step that would be), near slow points too, and
// `times` are integration times (s) of the method's order. 2D fields (dims[2] == 1) stay in their
// plane: the z component of v is ignored.
//
// Where a line ends, and what the last point is:
//   domain_exit   the step that would leave the grid is bisected down to 1e-6 cells, then the
//                 line is extended along v to the boundary: the last point lies ON the boundary.
//   stagnation    |v| <= stagnation_speed * max|v| at the last point (a zero field stops at once:
//                 the line is just the seed); or a step ran into v = 0 exactly (bisected like a
//                 domain exit: a no-slip solid); or the line stopped making headway, circling or
//                 jittering about a zero smaller than its step (then it ends at the slowest of
//                 those last points).
//   max_length / max_steps   the last step is shortened so that the length is exactly max_length.
//   closed_loop   a step passed within closing_distance of the seed after the line had gone
//                 farther than 2 closing_distance from it; the last point is that step's end.
//   nan_in_field  v is not finite (NaN/inf) at the next point: the line ends at the last finite
//                 point (a NaN inside the integration of a step is bisected like a domain exit).
//   too_close     a caller's StopRule refused the next point (used by evenly spaced seeding).
// A seed outside the grid gives a line with no points and reason domain_exit; a seed on a
// non-finite value gives no points and nan_in_field.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/streamlines/StreamlineParams.h"

namespace fluidviz::streamlines {

enum class TerminationReason {
  not_traced,  ///< this direction was not requested
  domain_exit,
  stagnation,
  max_length,
  max_steps,
  closed_loop,
  nan_in_field,
  too_close,
};

/// "domain_exit", "stagnation", ... (the enumerator's name); the VTK wrapper writes these.
const char* toString(TerminationReason r);

struct Streamline {
  std::vector<Vec3> points;   ///< world coordinates, ordered by increasing integration time
  std::vector<double> times;  ///< s, integration time per point; 0 at the seed, < 0 backward
  std::vector<double> speeds; ///< |v| (world units / s) interpolated at each point
  std::size_t seed_index = 0; ///< index of the seed in points (last point for backward-only)
  TerminationReason forward_end = TerminationReason::not_traced;   ///< why points.back() ends it
  TerminationReason backward_end = TerminationReason::not_traced;  ///< why points.front() ends it

  /// The reason of the traced direction: forward_end unless only backward was traced.
  TerminationReason reason() const {
    return forward_end != TerminationReason::not_traced ? forward_end : backward_end;
  }
};

enum class Direction { forward = 1, backward = -1 };

/// What a StopRule sees of each new point (never called for the seed itself).
struct StepInfo {
  const Vec3& point;   ///< world coordinates of the candidate point
  Direction direction; ///< branch being traced (forward first, then backward)
  double arc_length;   ///< cells travelled on this branch up to the candidate point
};
/// Return true to refuse the candidate point and end the branch with reason too_close. Called
/// from the thread that traces the line, in the order points are produced.
using StopRule = std::function<bool(const StepInfo&)>;

class StreamlineTracer {
 public:
  /// Validates params (ParamError) and the grid (std::invalid_argument), checks that the field has
  /// one value per node (std::invalid_argument naming the array) and finds max|v| over its finite
  /// values. Keeps a reference to `field`: it must outlive the tracer.
  StreamlineTracer(const VectorField& field, StreamlineParams params);

  /// Traces one line from `seed_world` (forward first, then backward when direction is both;
  /// when the forward branch closes a loop the backward branch is skipped and backward_end is
  /// closed_loop too). Thread-safe.
  Streamline trace(const Vec3& seed_world, const StopRule& stop = {}) const;
  /// The same with `maxLength` (cells) in place of params.max_length: for callers that carry
  /// many points by different arc lengths (the fronts of separating surfaces).
  Streamline trace(const Vec3& seed_world, const StopRule& stop, double maxLength) const;

  double maxSpeed() const { return max_speed_; }
  const StreamlineParams& params() const { return params_; }

 private:
  struct Branch;
  struct StepResult;
  Branch traceBranch(const Vec3& seed_index, Direction dir, const StopRule& stop,
                     double maxLength) const;
  StepResult rkStep(const Vec3& q, const Vec3& v, double h, double sign) const;
  static void endAtSlowestOfStuckWindow(Branch& b);
  bool velocityAt(const Vec3& q, Vec3& v_index, bool& finite) const;
  double worldSpeed(const Vec3& v_index) const;
  Vec3 toWorld(const Vec3& q) const;
  bool insideIndex(const Vec3& q) const;

  const VectorField& field_;
  StreamlineParams params_;
  double max_speed_ = 0.0;
};

/// One line from one seed (builds a StreamlineTracer; prefer the tracer for many seeds).
Streamline traceStreamline(const VectorField& field, const Vec3& seed_world,
                           const StreamlineParams& params);

/// One line per seed, in seed order, traced in parallel (OpenMP, dynamic schedule).
std::vector<Streamline> traceStreamlines(const VectorField& field, const std::vector<Vec3>& seeds,
                                         const StreamlineParams& params);

}  // namespace fluidviz::streamlines
