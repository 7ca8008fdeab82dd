#include "filters/sketch/grid/DivergenceFree.h"

#include <Eigen/IterativeLinearSolvers>
#include <stdexcept>
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz::sketch {

namespace {
Eigen::VectorXd stacked(const VectorField& v, const PlaneGrid& g) {
  if (v.values.size() != static_cast<std::size_t>(g.size()))
    throw std::invalid_argument("field size does not match the grid");
  Eigen::VectorXd x(2 * g.size());
  for (int n = 0; n < g.size(); ++n) {
    x[n] = v.values[static_cast<std::size_t>(n)][0];
    x[g.size() + n] = v.values[static_cast<std::size_t>(n)][1];
  }
  return x;
}
}  // namespace

double maxDivergence(const VectorField& v, const PlaneGrid& g) {
  return (divergenceMatrix(g) * stacked(v, g)).cwiseAbs().maxCoeff();
}

DivergenceFreeResult projectDivergenceFree(const VectorField& v, const PlaneGrid& g) {
  const SparseMatrix d = divergenceMatrix(g);
  const Eigen::VectorXd x = stacked(v, g);
  const Eigen::VectorXd div = d * x;
  // Residual target 1e-12 in the 2-norm (so max |div u| <= 1e-12): a relative tolerance far
  // below round-off makes conjugate gradients wander in the null space; a field that is already
  // that divergence-free is returned as it is.
  constexpr double kTarget = 1e-12;
  if (div.norm() <= kTarget) return {v, div.cwiseAbs().maxCoeff(), div.cwiseAbs().maxCoeff(), 0};
  const SparseMatrix a = d * SparseMatrix(d.transpose());
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(kTarget / div.norm());
  cg.setMaxIterations(20 * g.size());
  cg.compute(a);
  const Eigen::VectorXd phi = cg.solve(div);
  const Eigen::VectorXd u = x - d.transpose() * phi;
  DivergenceFreeResult r{v, div.cwiseAbs().maxCoeff(), (d * u).cwiseAbs().maxCoeff(),
                         static_cast<int>(cg.iterations())};
  if (r.divergenceAfter > 1e-10)
    throw std::runtime_error(
        "divergence-free projection: conjugate gradients stopped at max "
        "|div u| = " +
        formatNumber(r.divergenceAfter, 3) + " after " + std::to_string(r.iterations) +
        " iterations (before " + formatNumber(r.divergenceBefore, 3) + ")");
  for (int n = 0; n < g.size(); ++n)
    r.field.values[static_cast<std::size_t>(n)] = Vec3(u[n], u[g.size() + n], 0.0);
  return r;
}

}  // namespace fluidviz::sketch
