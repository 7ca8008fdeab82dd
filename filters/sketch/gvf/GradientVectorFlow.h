#pragma once
// Gradient Vector Flow (Xu & Prince 1998, "Snakes, shapes, and gradient vector flow", IEEE TIP
// 7(3)): the field v minimising
//   E(v) = integral of mu |grad v|^2 + b |v - v0|^2,   b = |v0|^2 / max|v0|^2
// which follows v0 where v0 is strong and varies smoothly where v0 is weak or absent. Used here
// (Judice & Giraldi 2012) to extend the velocity of sketched strokes over the whole grid.
//
// Two solvers (GvfSolver):
// - explicit: gradient descent in pseudo-time, dv/dt = mu lap v - b (v - v0). Each
//   step is refused unless
//     mu dt sum_d 1/h_d^2 <= 1/2     (mu dt / h^2 <= 1/(2D) on a square grid: the
//                                     diffusion term alone)
//     dt max b <= 1                  (the reaction term alone; here max b = 1)
//     dt (4 mu sum_d 1/h_d^2 + max b) <= 2
//   (mu in m^2 here: GvfParams::mu hx hy.) The third is the one that matters: the step is
//   v - dt grad E/2, and the Hessian of E/2 has
//   eigenvalues up to 4 mu sum 1/h^2 + max b (Gershgorin on -mu L + diag(b)); gradient descent
//   neither diverges nor raises E iff dt lambda_max <= 2. The first two alone allow
//   dt lambda_max = 3: with b = 1 on a region, the checkerboard mode there grows by |1 - 3| = 2
//   per step.
// - direct: the steady state (-mu L + diag(b)) v = b v0, one SimplicialLDLT factorisation for
//   both components. The matrix is symmetric (L is a sum of face fluxes) and positive definite
//   once a stroke reaches the grid, so Cholesky-type LDLT is the natural exact solver: half the
//   work and memory of SparseLU, no tolerance to pick as conjugate gradients would need.
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/sketch/SketchParams.h"
#include "filters/sketch/grid/PlaneGrid.h"

namespace fluidviz::sketch {

// Weights: every entry point takes b per node (finite, >= 0, not all 0; divided by its largest
// value). Without them b is Xu & Prince's |v0|^2 (speedWeights). Generalised GVF (Xu & Prince,
// "Generalized gradient vector flow external forces for active contours", Signal Processing 71,
// 1998) lets the data weight differ from |v0|^2; the sketch pipeline uses it so that a slow
// stroke binds the field as firmly as a fast one (SketchParams.h, GvfWeight).

/// |v0|^2 at every node (x and y components).
std::vector<double> speedWeights(const VectorField& v0);

/// The largest stable pseudo-time steps of the explicit scheme, one per rule above.
struct GvfStepLimits {
  double diffusion = 0.0;  ///< 1 / (2 mu sum 1/h^2)
  double reaction = 0.0;   ///< 1 / max b
  double combined = 0.0;   ///< 2 / (4 mu sum 1/h^2 + max b)
  double stable() const;   ///< the smallest of the three
};

/// The explicit GVF iteration on one field v0 (2D; z components ignored and kept 0).
class GvfIteration {
 public:
  /// v starts at v0. Throws std::invalid_argument if v0 is zero everywhere (no stroke on the
  /// grid) or not finite, ParamError for parameters outside their ranges.
  GvfIteration(const VectorField& v0, const GvfParams& params);
  GvfIteration(const VectorField& v0, std::vector<double> weights, const GvfParams& params);

  GvfStepLimits limits() const { return limits_; }
  /// The step used: params.time_step, or 0.9 x limits().stable() when it is unset. Throws
  /// ParamError("time_step", ...) naming the rule it breaks when it is not stable.
  double timeStep() const { return dt_; }
  /// One explicit Euler step v += dt (mu L v - b (v - v0)).
  void step();
  /// max over nodes and components of |mu L v - b (v - v0)|.
  double residual() const;
  /// E(v) of the header, cell area included (Riemann sum over nodes, faces).
  double energy() const;
  int iterations() const { return iterations_; }
  VectorField field(const std::string& name = "velocity") const;

 private:
  PlaneGrid grid_;
  Grid fullGrid_;
  double mu_;
  std::vector<double> b_, u0_, w0_, u_, w_;
  GvfStepLimits limits_;
  double dt_ = 0.0;
  int iterations_ = 0;
};

/// Throws ParamError("time_step", ...) with the rule and the largest allowed step when dt
/// breaks one of the three limits.
void checkGvfTimeStep(double dt, const GvfStepLimits& limits);

struct GvfResult {
  VectorField field;
  int iterations = 0;     ///< explicit: steps taken; direct: 0
  double residual = 0.0;  ///< max |mu L v - b (v - v0)| of the result
};

/// v0 extended by GVF with the solver chosen in params. The explicit solver throws
/// ParamError("max_iterations", ...) naming the residual reached if it does not meet the
/// tolerance within max_iterations.
GvfResult gradientVectorFlow(const VectorField& v0, const GvfParams& params);
GvfResult gradientVectorFlow(const VectorField& v0, std::vector<double> weights,
                             const GvfParams& params);

/// E(v) of the header for a given v (same grid as v0), b = speedWeights(v0) normalised.
double gvfEnergy(const VectorField& v, const VectorField& v0, const GvfParams& params);

}  // namespace fluidviz::sketch
