#pragma once
// Time-step limits of explicit SPH, each with a safety factor from SphParams:
//   CFL       dt <= C_cfl h / (c_max + |v|max)      (Monaghan 1992; Morris et al. 1997)
//   viscous   dt <= C_visc h^2 / nu                   (Morris et al. 1997, sec. 3.4)
//   force     dt <= C_f sqrt(h / |a|max)              (Monaghan 1994)
// Defaults C_cfl = 0.25, C_visc = 0.125, C_f = 0.25 follow Morris et al. 1997.
//
// References:
//   J. P. Morris, P. J. Fox, Y. Zhu, J. Comput. Phys. 136 (1997) 214-226, sec. 3.4.
//   J. J. Monaghan, J. Comput. Phys. 110 (1994) 399-406.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace fluidviz::sph {

struct TimeStepLimits {
  double cfl = std::numeric_limits<double>::infinity();      ///< s
  double viscous = std::numeric_limits<double>::infinity();  ///< s
  double force = std::numeric_limits<double>::infinity();    ///< s

  double stable() const { return std::min({cfl, viscous, force}); }
  /// Name of the binding condition: "cfl", "viscous" or "force".
  std::string binding() const {
    const double s = stable();
    return s == cfl ? "cfl" : (s == viscous ? "viscous" : "force");
  }
};

struct TimeStepFactors {
  double cfl = 0.25, viscous = 0.125, force = 0.25;
};

/// h: smoothing length (m); cMax: largest sound speed (m/s); vMax: largest speed (m/s);
/// nu: kinematic viscosity (m^2/s); aMax: largest acceleration (m/s^2).
inline TimeStepLimits timeStepLimits(const TimeStepFactors& f, double h, double cMax, double vMax,
                                     double nu, double aMax) {
  TimeStepLimits l;
  l.cfl = f.cfl * h / (cMax + vMax);
  if (nu > 0.0) l.viscous = f.viscous * h * h / nu;
  if (aMax > 0.0) l.force = f.force * std::sqrt(h / aMax);
  return l;
}

}  // namespace fluidviz::sph
