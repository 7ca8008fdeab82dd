#include "solvers/surface/SurfaceDiffusion.h"

#include <stdexcept>

namespace fluidviz::surface {

SurfaceDiffusion::SurfaceDiffusion(const TriangleMesh& mesh, double diffusivity, double timeStep,
                                   MassLumping lumping)
    : dt_(timeStep), mass_(lumpedMass(mesh, lumping)) {
  if (!(diffusivity >= 0.0) || !(timeStep > 0.0))
    throw std::invalid_argument("SurfaceDiffusion needs diffusivity >= 0 and a time step > 0");
  const SparseMatrix m = diagonalMatrix(mass_);
  const SparseMatrix halfStiffness = (0.5 * diffusivity * timeStep) * cotanStiffness(mesh);
  explicitPart_ = m - halfStiffness;
  implicitPart_.compute(m + halfStiffness);
  if (implicitPart_.info() != Eigen::Success)
    throw std::runtime_error("SurfaceDiffusion: the Crank-Nicolson matrix could not be factorised");
}

void SurfaceDiffusion::step(Eigen::VectorXd& phi) const {
  phi = implicitPart_.solve(explicitPart_ * phi);
}

}  // namespace fluidviz::surface
