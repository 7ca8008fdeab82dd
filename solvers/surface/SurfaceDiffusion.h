#pragma once
// Scalar diffusion on a closed triangle mesh, d phi / dt = kappa Delta phi, in the P1 /
// cotangent discretisation M d phi / dt = -kappa S phi (operators/SurfaceOperators.h), stepped
// by Crank-Nicolson (Crank & Nicolson 1947):
//   (M + kappa dt S / 2) phi^{n+1} = (M - kappa dt S / 2) phi^n,
// second order in time and unconditionally stable. The left-hand matrix is factorised once
// (Eigen's SimplicialLDLT) and reused by every step. Since 1^T S = 0, the total mass 1^T M phi is
// conserved to round-off.
#include <Eigen/SparseCholesky>

#include "solvers/surface/operators/SurfaceOperators.h"

namespace fluidviz::surface {

class SurfaceDiffusion {
 public:
  SurfaceDiffusion(const TriangleMesh& mesh, double diffusivity, double timeStep,
                   MassLumping lumping = MassLumping::mixed_voronoi);

  /// One Crank-Nicolson step of phi (vertex values) in place.
  void step(Eigen::VectorXd& phi) const;

  const Eigen::VectorXd& mass() const { return mass_; }
  double timeStep() const { return dt_; }

 private:
  double dt_;
  Eigen::VectorXd mass_;
  SparseMatrix explicitPart_;  ///< M - kappa dt S / 2
  Eigen::SimplicialLDLT<SparseMatrix> implicitPart_;  ///< factors of M + kappa dt S / 2
};

}  // namespace fluidviz::surface
