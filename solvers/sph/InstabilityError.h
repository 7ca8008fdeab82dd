#pragma once
// Thrown when an SPH run leaves the range where its result means anything: a NaN, a particle
// leaving the domain, a density error past SphParams::max_density_error, or an automatic time
// step collapsing (a particle pushed by an enormous force). Says when, which particle, why, and
// which parameter to change. The solver's particles keep the last good state (no NaN).
// A fluidviz::InstabilityError (fieldviz/core), like lbm::InstabilityError.
#include <string>

#include "fieldviz/core/Grid.h"
#include "fieldviz/core/InstabilityError.h"

namespace fluidviz::sph {

class InstabilityError : public fluidviz::InstabilityError {
 public:
  InstabilityError(long long step, double time, long long particle, const Vec3& position,
                   std::string reason, const std::string& message)
      : fluidviz::InstabilityError(step, message),
        time_(time),
        particle_(particle),
        position_(position),
        reason_(std::move(reason)) {}
  // step(): the step that failed (0-based)
  double time() const { return time_; }           ///< s, time at the start of that step
  long long particle() const { return particle_; }  ///< fluid particle index
  const Vec3& position() const { return position_; }  ///< m, its last good position
  /// "NaN", "left domain", "density error" or "time step collapsed".
  const std::string& reason() const { return reason_; }

 private:
  double time_;
  long long particle_;
  Vec3 position_;
  std::string reason_;
};

}  // namespace fluidviz::sph
