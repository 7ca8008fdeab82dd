#include "solvers/lbm/LbmSolver.h"

#include <cmath>

#include "solvers/lbm/kernel/LbmSolverImpl.h"
#include "solvers/lbm/validation/TaylorGreenVortex.h"

namespace fluidviz::lbm {

StopReason LbmSolver::advance(double targetTime) {
  const double dt = units().dt;
  const LbmParams& p = params();
  auto stepsTo = [dt](double t) { return static_cast<long long>(std::ceil(t / dt - 1e-9)); };
  const long long endStep = std::min<long long>(stepsTo(p.end_time), p.max_steps);
  const long long target = std::min(stepsTo(targetTime), endStep);
  const int interval = p.check_interval;
  while (steps_ < target && !steady_) {
    // Run up to the next multiple of check_interval so that checks fall on fixed steps.
    const long long nextCheck = (steps_ / interval + 1) * interval;
    const long long chunk = std::min(nextCheck, target) - steps_;
    step(static_cast<int>(chunk));
    if (steps_ % interval != 0) continue;
    checkStability();
    if (p.steady_tolerance > 0.0 && maxVelocityChange() < p.steady_tolerance) steady_ = true;
  }
  if (steady_) return StopReason::Steady;
  if (steps_ >= stepsTo(p.end_time)) return StopReason::EndTime;
  if (steps_ >= p.max_steps) return StopReason::MaxSteps;
  return StopReason::ReachedTime;
}

std::unique_ptr<LbmSolver> createLbmSolver(const LbmParams& params,
                                           std::vector<SolidBody> extraBodies) {
  validateLbmParams(params);  // lattice and precision are among the checked choices
  const bool single = params.precision == Precision::float32;
  if (is3D(params)) {
    if (single) return std::make_unique<LbmSolverD3Q19Float>(params, std::move(extraBodies));
    return std::make_unique<LbmSolverD3Q19>(params, std::move(extraBodies));
  }
  if (single) return std::make_unique<LbmSolverD2Q9Float>(params, std::move(extraBodies));
  return std::make_unique<LbmSolverD2Q9>(params, std::move(extraBodies));
}

void initialFlowFields(const LbmParams& p, const LatticeUnits& units, const Grid& grid,
                       std::vector<double>& density, std::vector<Vec3>& velocity) {
  density.clear();
  velocity.clear();
  if (p.initial_flow != InitialFlow::taylor_green) return;
  // Taylor & Green 1937 (TaylorGreenVortex.h) at t = 0; its pressure (the steady Euler balance
  // of the vortex) enters as the lattice density of an ideal gas, c_s^2 = 1/3.
  const TaylorGreenVortex vortex{2 * M_PI / p.domain_size[0], 2 * M_PI / p.domain_size[1],
                                 p.initial_speed, units.viscosity};
  density.resize(grid.nodeCount());
  velocity.resize(grid.nodeCount());
  for (int k = 0; k < grid.dims[2]; ++k)
    for (int j = 0; j < grid.dims[1]; ++j)
      for (int i = 0; i < grid.dims[0]; ++i) {
        const Vec3 x = grid.position(i, j, k);
        const std::size_t n = grid.index(i, j, k);
        velocity[n] = vortex.velocity(x, 0.0);
        density[n] = units.density * units.pressureToLatticeDensity(vortex.pressure(x, 0.0, p.density));
      }
}

}  // namespace fluidviz::lbm
