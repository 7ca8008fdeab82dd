// Checkpoint state of SphSolver: what step() evolves, nothing derived from the params.
//   dimension, fluid and boundary particle counts (checked on restore)
//   time, step count, last time step, steps past the stable limit, warnings, whether the rates
//   are valid
//   fluid: x, v, a, xsph, rho, drho, p (the rates are those of the last force evaluation, which
//     used the predicted velocity: recomputing them from v would not give the same numbers)
//   boundary: positions, velocities (rollers turn)
// The neighbour lists are rebuilt from the restored positions: the search is a deterministic
// function of the points, so they equal the lists the uninterrupted run holds.
#include "solvers/sph/SphSolver.h"

namespace fluidviz::sph {

void SphSolver::saveState(StateWriter& out) const {
  out.put<std::int32_t>(params_.dimension);
  out.put<std::uint64_t>(state_.size());
  out.put<std::uint64_t>(boundary_.size());
  out.put<double>(time_);
  out.put<std::int64_t>(steps_);
  out.put<double>(lastDt_);
  out.put<std::int64_t>(stepsPastLimit_);
  out.putStrings(warnings_);
  out.put<std::uint8_t>(ratesValid_ ? 1 : 0);
  out.putVec3s(state_.x);
  out.putVec3s(state_.v);
  out.putVec3s(state_.a);
  out.putVec3s(state_.xsph);
  out.putVector(state_.rho);
  out.putVector(state_.drho);
  out.putVector(state_.p);
  out.putVec3s(boundary_.positions);
  out.putVec3s(boundary_.velocities);
}

void SphSolver::restoreState(StateReader& in) {
  StateReader::requireSame("the dimension", in.get<std::int32_t>(),
                           static_cast<std::int32_t>(params_.dimension));
  const auto fluid = static_cast<std::int64_t>(in.get<std::uint64_t>());
  StateReader::requireSame("the boundary particle count",
                           static_cast<std::int64_t>(in.get<std::uint64_t>()),
                           static_cast<std::int64_t>(boundary_.size()));
  const auto time = in.get<double>();
  const auto steps = in.get<std::int64_t>();
  const auto lastDt = in.get<double>();
  const auto pastLimit = in.get<std::int64_t>();
  std::vector<std::string> warnings = in.getStrings();
  const bool ratesValid = in.get<std::uint8_t>() != 0;
  FluidState s;
  in.getVec3s(s.x, fluid);
  in.getVec3s(s.v, fluid);
  in.getVec3s(s.a, fluid);
  in.getVec3s(s.xsph, fluid);
  in.getVector(s.rho, fluid);
  in.getVector(s.drho, fluid);
  in.getVector(s.p, fluid);
  const auto nb = static_cast<std::int64_t>(boundary_.size());
  std::vector<Vec3> boundaryPositions, boundaryVelocities;
  in.getVec3s(boundaryPositions, nb);
  in.getVec3s(boundaryVelocities, nb);
  state_ = std::move(s);
  boundary_.positions = std::move(boundaryPositions);
  boundary_.velocities = std::move(boundaryVelocities);
  time_ = time;
  steps_ = steps;
  lastDt_ = lastDt;
  stepsPastLimit_ = pastLimit;
  warnings_ = std::move(warnings);
  ratesValid_ = ratesValid;
  if (ratesValid_) rebuildNeighbors();  // the lists the next step's first half uses
}

}  // namespace fluidviz::sph
