#pragma once
// Thrown when the lattice state leaves the range where LBM is meaningful (NaN, negative density,
// lattice speed past LatticeStabilityLimits::maxSpeed). Says where, when and what to change.
// A fluidviz::InstabilityError (fieldviz/core), like sph::InstabilityError.
#include <string>

#include "fieldviz/core/InstabilityError.h"

namespace fluidviz::lbm {

struct LatticeStabilityLimits {
  /// Lattice speed above which the run is declared unstable: close to c_s = 0.577 the
  /// equilibrium's low-Mach expansion breaks down and populations turn negative.
  static constexpr double maxSpeed = 0.5;
};

class InstabilityError : public fluidviz::InstabilityError {
 public:
  InstabilityError(long long step, double x, double y, std::string reason,
                   const std::string& message)
      : InstabilityError(step, x, y, 0.0, std::move(reason), message) {}
  InstabilityError(long long step, double x, double y, double z, std::string reason,
                   const std::string& message)
      : fluidviz::InstabilityError(step, message), x_(x), y_(y), z_(z), reason_(std::move(reason)) {}
  double x() const { return x_; }  ///< m, position of the offending node
  double y() const { return y_; }
  double z() const { return z_; }  ///< 0 in 2D
  /// Short reason: "NaN", "negative density" or "lattice speed past limit".
  const std::string& reason() const { return reason_; }

 private:
  double x_, y_, z_;
  std::string reason_;
};

}  // namespace fluidviz::lbm
