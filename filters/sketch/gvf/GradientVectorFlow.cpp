#include "filters/sketch/gvf/GradientVectorFlow.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fieldviz/core/Params.h"

namespace fluidviz::sketch {

double GvfStepLimits::stable() const { return std::min({diffusion, reaction, combined}); }

namespace {

struct Components {
  std::vector<double> u, w;
};

Components componentsOf(const VectorField& f, const PlaneGrid& g) {
  if (f.values.size() != static_cast<std::size_t>(g.size()))
    throw std::invalid_argument("field '" + f.name + "' has " + std::to_string(f.values.size()) +
                                " values for " + std::to_string(g.size()) + " grid nodes");
  Components c{std::vector<double>(f.values.size()), std::vector<double>(f.values.size())};
  for (std::size_t n = 0; n < f.values.size(); ++n) {
    if (!f.values[n].allFinite())
      throw std::invalid_argument("field '" + f.name + "' is not finite at node " +
                                  std::to_string(n));
    c.u[n] = f.values[n][0];
    c.w[n] = f.values[n][1];
  }
  return c;
}

/// Weights checked (one per node, finite, >= 0, not all 0) and divided by their largest value.
std::vector<double> normalisedWeights(std::vector<double> b, std::size_t nodes) {
  if (b.size() != nodes)
    throw std::invalid_argument("GVF: " + std::to_string(b.size()) + " weights for " +
                                std::to_string(nodes) + " nodes");
  double largest = 0.0;
  for (double x : b) {
    if (!(x >= 0.0) || !std::isfinite(x))
      throw std::invalid_argument("GVF: a weight is negative or not finite");
    largest = std::max(largest, x);
  }
  if (!(largest > 0.0))
    throw std::invalid_argument(
        "the sketched field is zero everywhere: no stroke reaches the grid");
  for (double& x : b) x /= largest;
  return b;
}

/// mu in m^2 from GvfParams::mu in cells^2.
double physicalMu(const GvfParams& p, const PlaneGrid& g) { return p.mu * g.hx * g.hy; }

GvfStepLimits stepLimits(const PlaneGrid& g, double mu, double maxB) {
  const double s = g.inverseSquareSpacingSum();
  return {1.0 / (2.0 * mu * s), 1.0 / maxB, 2.0 / (4.0 * mu * s + maxB)};
}

VectorField assemble(const Grid& grid, const std::string& name, const std::vector<double>& u,
                     const std::vector<double>& w) {
  VectorField f{name, grid, std::vector<Vec3>(u.size())};
  for (std::size_t n = 0; n < u.size(); ++n) f.values[n] = Vec3(u[n], w[n], 0.0);
  return f;
}

double residualOf(const PlaneGrid& g, double mu, const std::vector<double>& b,
                  const std::vector<double>& v, const std::vector<double>& v0) {
  const std::vector<double> lap = applyLaplacian(g, v);
  double r = 0.0;
  for (std::size_t n = 0; n < v.size(); ++n)
    r = std::max(r, std::abs(mu * lap[n] - b[n] * (v[n] - v0[n])));
  return r;
}

double energyOf(const PlaneGrid& g, double mu, const std::vector<double>& b, const Components& v,
                const Components& v0) {
  double data = 0.0;
  for (std::size_t n = 0; n < b.size(); ++n) {
    const double du = v.u[n] - v0.u[n], dw = v.w[n] - v0.w[n];
    data += b[n] * (du * du + dw * dw);
  }
  return g.hx * g.hy * (mu * (gradientEnergy(g, v.u) + gradientEnergy(g, v.w)) + data);
}

double largestSpeed(const Components& c) {
  double s = 0.0;
  for (std::size_t n = 0; n < c.u.size(); ++n) s = std::max(s, std::hypot(c.u[n], c.w[n]));
  return s;
}

}  // namespace

void checkGvfTimeStep(double dt, const GvfStepLimits& l) {
  auto refuse = [&](const std::string& rule, double limit) {
    throw ParamError("time_step", "is " + formatNumber(dt) +
                                      ", above the explicit GVF stability "
                                      "limit " +
                                      rule + " (dt <= " + formatNumber(limit) +
                                      "); lower time_step or leave it unset");
  };
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw ParamError("time_step", "is " + formatNumber(dt) + ", must be a finite number > 0");
  if (dt > l.diffusion) refuse("mu dt sum(1/h^2) <= 1/2 (mu dt / h^2 <= 1/(2D))", l.diffusion);
  if (dt > l.reaction)
    refuse("dt max|v0|^2 <= 1 (|v0| normalised by its largest value)", l.reaction);
  if (dt > l.combined) refuse("dt (4 mu sum(1/h^2) + max|v0|^2) <= 2", l.combined);
}

std::vector<double> speedWeights(const VectorField& v0) {
  std::vector<double> b(v0.values.size());
  for (std::size_t n = 0; n < b.size(); ++n)
    b[n] = v0.values[n][0] * v0.values[n][0] + v0.values[n][1] * v0.values[n][1];
  return b;
}

GvfIteration::GvfIteration(const VectorField& v0, const GvfParams& params)
    : GvfIteration(v0, speedWeights(v0), params) {}

GvfIteration::GvfIteration(const VectorField& v0, std::vector<double> weights,
                           const GvfParams& params)
    : grid_(PlaneGrid::of(v0.grid, params.boundary_x, params.boundary_y)),
      fullGrid_(v0.grid),
      mu_(physicalMu(params, grid_)) {
  validateGvfParams(params);
  const Components c = componentsOf(v0, grid_);
  b_ = normalisedWeights(std::move(weights), c.u.size());
  u0_ = c.u;
  w0_ = c.w;
  u_ = u0_;
  w_ = w0_;
  limits_ = stepLimits(grid_, mu_, *std::max_element(b_.begin(), b_.end()));
  dt_ = params.time_step ? *params.time_step : 0.9 * limits_.stable();
  checkGvfTimeStep(dt_, limits_);
}

void GvfIteration::step() {
  const std::vector<double> lapU = applyLaplacian(grid_, u_);
  const std::vector<double> lapW = applyLaplacian(grid_, w_);
  for (std::size_t n = 0; n < u_.size(); ++n) {
    u_[n] += dt_ * (mu_ * lapU[n] - b_[n] * (u_[n] - u0_[n]));
    w_[n] += dt_ * (mu_ * lapW[n] - b_[n] * (w_[n] - w0_[n]));
  }
  ++iterations_;
}

double GvfIteration::residual() const {
  return std::max(residualOf(grid_, mu_, b_, u_, u0_), residualOf(grid_, mu_, b_, w_, w0_));
}

double GvfIteration::energy() const { return energyOf(grid_, mu_, b_, {u_, w_}, {u0_, w0_}); }

VectorField GvfIteration::field(const std::string& name) const {
  return assemble(fullGrid_, name, u_, w_);
}

namespace {

GvfResult solveExplicit(const VectorField& v0, std::vector<double> weights,
                        const GvfParams& params) {
  GvfIteration it(v0, std::move(weights), params);
  const PlaneGrid g = PlaneGrid::of(v0.grid, params.boundary_x, params.boundary_y);
  const double target = params.tolerance * largestSpeed(componentsOf(v0, g));
  double r = it.residual();
  // The residual costs one more Laplacian: look at it every 16 steps.
  while (r > target) {
    if (it.iterations() >= params.max_iterations)
      throw ParamError("max_iterations",
                       "is " + std::to_string(params.max_iterations) +
                           ": explicit GVF stopped there at residual " + formatNumber(r) + " > " +
                           formatNumber(target) +
                           " (tolerance x max|v0|); raise it, or use the direct solver");
    for (int k = 0; k < 16 && it.iterations() < params.max_iterations; ++k) it.step();
    r = it.residual();
  }
  return {it.field(v0.name), it.iterations(), r};
}

GvfResult solveDirect(const VectorField& v0, std::vector<double> weights, const GvfParams& params) {
  validateGvfParams(params);
  const PlaneGrid g = PlaneGrid::of(v0.grid, params.boundary_x, params.boundary_y);
  const Components c = componentsOf(v0, g);
  const std::vector<double> b = normalisedWeights(std::move(weights), c.u.size());
  const double mu = physicalMu(params, g);
  SparseMatrix a = -mu * laplacianMatrix(g);
  Eigen::MatrixXd rhs(g.size(), 2);
  for (int n = 0; n < g.size(); ++n) {
    a.coeffRef(n, n) += b[n];
    rhs(n, 0) = b[n] * c.u[n];
    rhs(n, 1) = b[n] * c.w[n];
  }
  Eigen::SimplicialLDLT<SparseMatrix> solver(a);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("GVF: the sparse LDLT factorisation failed");
  const Eigen::MatrixXd v = solver.solve(rhs);
  std::vector<double> u(v.col(0).data(), v.col(0).data() + g.size());
  std::vector<double> w(v.col(1).data(), v.col(1).data() + g.size());
  const double r = std::max(residualOf(g, mu, b, u, c.u), residualOf(g, mu, b, w, c.w));
  return {assemble(v0.grid, v0.name, u, w), 0, r};
}

}  // namespace

GvfResult gradientVectorFlow(const VectorField& v0, const GvfParams& params) {
  return gradientVectorFlow(v0, speedWeights(v0), params);
}

GvfResult gradientVectorFlow(const VectorField& v0, std::vector<double> weights,
                             const GvfParams& params) {
  switch (params.solver) {
    case GvfSolver::explicit_euler:
      return solveExplicit(v0, std::move(weights), params);
    case GvfSolver::direct:
      return solveDirect(v0, std::move(weights), params);
  }
  throw std::invalid_argument("unknown GVF solver");
}

double gvfEnergy(const VectorField& v, const VectorField& v0, const GvfParams& params) {
  const PlaneGrid g = PlaneGrid::of(v0.grid, params.boundary_x, params.boundary_y);
  const Components c0 = componentsOf(v0, g);
  return energyOf(g, physicalMu(params, g), normalisedWeights(speedWeights(v0), c0.u.size()),
                  componentsOf(v, g), c0);
}

}  // namespace fluidviz::sketch
