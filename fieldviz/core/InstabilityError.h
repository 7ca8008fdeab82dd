#pragma once
// What every solver throws when its state leaves the range where its result means anything
// (lbm::InstabilityError, sph::InstabilityError derive from it and add where and why): the app
// reports any of them with one catch ("fluidviz: unstable: ...", exit code 3).
#include <stdexcept>
#include <string>

namespace fluidviz {

class InstabilityError : public std::runtime_error {
 public:
  InstabilityError(long long step, const std::string& message)
      : std::runtime_error(message), step_(step) {}
  /// The step at which the state was found unusable.
  long long step() const { return step_; }

 private:
  long long step_;
};

}  // namespace fluidviz
