#pragma once
// Parameter sets shared by the LBM tests and benches (physical units; see each test for the
// reference).
#include <cmath>

#include <vector>

#include "fieldviz/core/Sampling.h"
#include "solvers/lbm/LbmParams.h"

namespace fluidviz::lbm::test {

inline void makePeriodic(WallParams& a, WallParams& b) {
  a.type = fluidviz::lbm::WallType::periodic;
  b.type = fluidviz::lbm::WallType::periodic;
}

/// Unit square box periodic in x and y, `n` x `n` nodes, no moving wall: the time step is set
/// from the wanted relaxation time, dt = (tau - 1/2) / 3 * dx^2 / nu.
inline LbmParams periodicBox(int n, double tau, double viscosity = 1e-3) {
  LbmParams p;
  p.domain_size = {1.0, 1.0};
  p.resolution = n;
  p.viscosity = viscosity;
  const double dx = 1.0 / n;
  p.time_step = (tau - 0.5) / 3.0 * dx * dx / viscosity;
  p.end_time = 1e6;
  makePeriodic(p.walls.x_min, p.walls.x_max);
  makePeriodic(p.walls.y_min, p.walls.y_max);
  return p;
}

/// Lid-driven unit square cavity, lid y = 1 moving at 1 m/s in +x.
inline LbmParams lidDrivenCavity(int n, double reynolds, double latticeVelocity) {
  LbmParams p;
  p.domain_size = {1.0, 1.0};
  p.resolution = n;
  p.reynolds = reynolds;
  p.lattice_velocity = latticeVelocity;
  p.walls.y_max.type = fluidviz::lbm::WallType::moving_wall;
  p.walls.y_max.velocity = {1.0, 0.0};
  p.end_time = 1e3;
  return p;
}

/// The cubic lid-driven cavity at Re 100 (D3Q19, TRT, lattice lid speed 0.1) run to a steady
/// state (1e-5), and its centreline profile u_x(0.5, 0.1 k, 0.5), k = 1..9.
inline LbmParams lidDrivenCubicCavity(int n) {
  LbmParams p = lidDrivenCavity(n, 100, 0.1);
  p.lattice = fluidviz::lbm::Lattice::D3Q19;
  p.collision = fluidviz::lbm::Collision::trt;
  p.domain_depth = 1.0;
  p.end_time = 60;
  p.steady_tolerance = 1e-5;
  p.check_interval = 200;
  return p;
}

inline std::vector<double> cubicCavityCentreline(const VectorField& u) {
  std::vector<double> profile;
  for (int k = 1; k <= 9; ++k) profile.push_back(sample(u, Vec3(0.5, 0.1 * k, 0.5))->x());
  return profile;
}

}  // namespace fluidviz::lbm::test
