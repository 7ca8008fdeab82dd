#include "filters/topology/StreamFunction.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include "filters/topology/PlanarField.h"

namespace fluidviz::topology {

namespace {
// Interior unknowns up to which "auto" factorises (SimplicialLDLT, AMD ordering): measured here
// 0.13 s at 257^2, 1.0 s at 513^2, 15 s and 0.73 GB at 1025^2 nodes; conjugate gradients (Jacobi
// preconditioner; incomplete Cholesky was slower still) took 3.2 s at 513^2 and 32 s at 1025^2.
constexpr long kDirectSolverLimit = 1100000;

/// World-space in-plane components of one slice.
struct SliceVelocity {
  int nx, ny;
  double dx, dy;
  std::vector<double> u, v;
  double U(int i, int j) const { return u[static_cast<std::size_t>(j) * nx + i]; }
  double V(int i, int j) const { return v[static_cast<std::size_t>(j) * nx + i]; }
};

SliceVelocity extractSlice(const VectorField& field, int slice) {
  const PlanarField planar(field, slice);  // validates grid, size and slice
  const Grid& g = field.grid;
  SliceVelocity s{g.dims[0], g.dims[1], g.spacing[0], g.spacing[1], {}, {}};
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      const Vec3& w = field.values[g.index(i, j, planar.slice())];
      s.u.push_back(w.x());
      s.v.push_back(w.y());
    }
  return s;
}

/// Boundary nodes counter-clockwise from (0, 0): bottom, right, top, left.
std::vector<std::array<int, 2>> boundaryLoop(int nx, int ny) {
  std::vector<std::array<int, 2>> loop;
  for (int i = 0; i < nx - 1; ++i) loop.push_back({i, 0});
  for (int j = 0; j < ny - 1; ++j) loop.push_back({nx - 1, j});
  for (int i = nx - 1; i > 0; --i) loop.push_back({i, ny - 1});
  for (int j = ny - 1; j > 0; --j) loop.push_back({0, j});
  return loop;
}

/// psi on the boundary by the trapezoidal rule for d psi = -v dx + u dy; returns the mismatch
/// (net outflow) that was spread along the boundary.
double integrateBoundaryFlux(const SliceVelocity& s, std::vector<double>& psi) {
  const auto loop = boundaryLoop(s.nx, s.ny);
  const std::size_t n = loop.size();
  std::vector<double> value(n + 1, 0.0), arc(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const auto [ia, ja] = loop[k];
    const auto [ib, jb] = loop[(k + 1) % n];
    const double ddx = (ib - ia) * s.dx, ddy = (jb - ja) * s.dy;
    value[k + 1] = value[k] - 0.5 * (s.V(ia, ja) + s.V(ib, jb)) * ddx +
                   0.5 * (s.U(ia, ja) + s.U(ib, jb)) * ddy;
    arc[k + 1] = arc[k] + std::hypot(ddx, ddy);
  }
  const double mismatch = value[n];
  for (std::size_t k = 0; k < n; ++k) {
    const auto [i, j] = loop[k];
    psi[static_cast<std::size_t>(j) * s.nx + i] = value[k] - mismatch * arc[k] / arc[n];
  }
  return mismatch;
}

double vorticity(const SliceVelocity& s, int i, int j) {
  return (s.V(i + 1, j) - s.V(i - 1, j)) / (2 * s.dx) - (s.U(i, j + 1) - s.U(i, j - 1)) / (2 * s.dy);
}

using SparseMatrix = Eigen::SparseMatrix<double>;

/// -lap psi = omega on interior nodes (unknown k = (j-1)(nx-2) + (i-1)), boundary values moved
/// to the right-hand side. The matrix is symmetric positive definite.
void assemblePoisson(const SliceVelocity& s, const std::vector<double>& psi, SparseMatrix& a,
                     Eigen::VectorXd& b) {
  const int mx = s.nx - 2, my = s.ny - 2;
  const double cx = 1.0 / (s.dx * s.dx), cy = 1.0 / (s.dy * s.dy);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(mx) * my * 5);
  b.resize(static_cast<Eigen::Index>(mx) * my);
  auto unknown = [&](int i, int j) { return static_cast<Eigen::Index>(j - 1) * mx + (i - 1); };
  for (int j = 1; j <= my; ++j)
    for (int i = 1; i <= mx; ++i) {
      const Eigen::Index k = unknown(i, j);
      double rhs = vorticity(s, i, j);
      t.emplace_back(k, k, 2 * cx + 2 * cy);
      const int ni[4] = {i - 1, i + 1, i, i};
      const int nj[4] = {j, j, j - 1, j + 1};
      for (int m = 0; m < 4; ++m) {
        const double c = m < 2 ? cx : cy;
        const bool boundary = ni[m] == 0 || nj[m] == 0 || ni[m] == s.nx - 1 || nj[m] == s.ny - 1;
        if (boundary)
          rhs += c * psi[static_cast<std::size_t>(nj[m]) * s.nx + ni[m]];
        else
          t.emplace_back(k, unknown(ni[m], nj[m]), -c);
      }
      b[k] = rhs;
    }
  a.resize(b.size(), b.size());
  a.setFromTriplets(t.begin(), t.end());
}

template <class Solver>
Eigen::VectorXd solveWith(Solver& solver, const SparseMatrix& a, const Eigen::VectorXd& b) {
  solver.compute(a);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("stream function: factorising the Poisson matrix failed");
  Eigen::VectorXd x = solver.solve(b);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("stream function: the Poisson solve did not converge; raise "
                             "stream_function_tolerance or use stream_function_solver direct");
  return x;
}
}  // namespace

StreamFunctionResult computeStreamFunction(const VectorField& field, const TopologyParams& params) {
  validateTopologyParams(params);
  const SliceVelocity s = extractSlice(field, params.slice_index);
  const int slice = field.grid.is2D() ? 0 : params.slice_index;
  StreamFunctionResult r;
  r.psi.name = "stream_function";
  r.psi.grid = field.grid;
  r.psi.grid.dims[2] = 1;
  r.psi.grid.origin[2] = field.grid.origin[2] + slice * field.grid.spacing[2];
  r.psi.values.assign(static_cast<std::size_t>(s.nx) * s.ny, 0.0);
  r.boundary_flux_mismatch = integrateBoundaryFlux(s, r.psi.values);
  if (s.nx < 3 || s.ny < 3) return r;  // no interior nodes

  SparseMatrix a;
  Eigen::VectorXd b;
  assemblePoisson(s, r.psi.values, a, b);
  const bool direct = params.stream_function_solver == StreamFunctionSolver::direct ||
                      (params.stream_function_solver == StreamFunctionSolver::automatic && b.size() <= kDirectSolverLimit);
  Eigen::VectorXd x;
  if (direct) {
    Eigen::SimplicialLDLT<SparseMatrix> solver;
    x = solveWith(solver, a, b);
  } else {
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper,
                             Eigen::DiagonalPreconditioner<double>>
        solver;
    solver.setTolerance(params.stream_function_tolerance);
    solver.setMaxIterations(static_cast<int>(10 * b.size()));
    x = solveWith(solver, a, b);
    r.iterations = static_cast<int>(solver.iterations());
  }
  const double bNorm = b.norm();
  r.relative_residual = bNorm > 0 ? (a * x - b).norm() / bNorm : 0.0;
  for (int j = 1; j < s.ny - 1; ++j)
    for (int i = 1; i < s.nx - 1; ++i)
      r.psi.values[static_cast<std::size_t>(j) * s.nx + i] =
          x[static_cast<Eigen::Index>(j - 1) * (s.nx - 2) + (i - 1)];
  return r;
}

}  // namespace fluidviz::topology
