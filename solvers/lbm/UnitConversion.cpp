#include "solvers/lbm/UnitConversion.h"

#include <cmath>
#include <sstream>
#include <string>

namespace fluidviz::lbm {

namespace {

std::string num(double x, int digits = 4) {
  std::ostringstream s;
  s.precision(digits);
  s << x;
  return s.str();
}

struct Geometry {
  int nx, ny;
  double dx;
};

Geometry latticeGeometry(const LbmParams& p) {
  const double lx = p.domain_size[0], ly = p.domain_size[1];
  const int nx = p.resolution;
  const long ny = std::lround(ly / lx * nx);
  if (ny < 4)
    throw ParamError("domain_size",
                     "gives ny = round(Ly / Lx * resolution) = " + std::to_string(ny) +
                         " nodes across y, fewer than 4: raise lbm.resolution to at least " +
                         std::to_string(static_cast<long>(std::ceil(3.5 * lx / ly))) +
                         " or make lbm.domain_size[1] larger");
  if (static_cast<double>(nx) * ny > LatticeLimits::maxNodes)
    throw ParamError("resolution", "gives " + std::to_string(nx) + " x " + std::to_string(ny) +
                                       " = " + num(double(nx) * ny, 3) + " nodes, more than " +
                                       num(LatticeLimits::maxNodes, 3) + " (" +
                                       num(LatticeLimits::maxNodes * 144 / 1e9, 3) +
                                       " GB of populations): lower lbm.resolution to at most " +
                                       std::to_string(static_cast<long>(std::floor(
                                           std::sqrt(LatticeLimits::maxNodes * lx / ly)))));
  return {nx, static_cast<int>(ny), lx / nx};
}

double physicalViscosity(const LbmParams& p, double uRef, double lRef) {
  if (p.viscosity) return *p.viscosity;
  if (uRef == 0.0)
    throw ParamError("reynolds",
                     "needs a reference speed, but no wall moves and no roller turns; give "
                     "lbm.viscosity (m^2/s) instead");
  return uRef * lRef / *p.reynolds;
}

double timeStep(const LbmParams& p, double uRef, double dx, double nu) {
  if (uRef > 0.0) {
    if (p.time_step)
      throw ParamError("time_step",
                       "is only used when nothing moves; here dt = lattice_velocity dx / U_ref "
                       "= " +
                           num(p.lattice_velocity * dx / uRef) +
                           " s follows from lbm.lattice_velocity: remove lbm.time_step");
    return p.lattice_velocity * dx / uRef;
  }
  if (!p.time_step)
    throw ParamError("time_step",
                     "is required because no wall moves and no roller turns; e.g. "
                     "time_step = dx^2 / (6 nu) = " +
                         num(dx * dx / (6 * nu)) + " s gives tau = 1");
  return *p.time_step;
}

// How each knob scales the lattice viscosity nu_lb = nu dt / dx^2: with a moving wall
// dt = u_lb dx / U_ref, so nu_lb = nu u_lb / (U_ref dx) ~ resolution; without, nu_lb ~
// resolution^2. `factor` = wanted nu_lb / current nu_lb.
std::string knobsForViscosityFactor(const LbmParams& p, bool moving, double factor) {
  const bool raise = factor > 1.0;
  const double exponent = moving ? 1.0 : 2.0;
  const double res = p.resolution * std::pow(factor, 1.0 / exponent);
  std::string s =
      (raise ? "raise lbm.resolution to at least " : "lower lbm.resolution to at most ") +
      std::to_string(static_cast<long>(raise ? std::ceil(res) : std::floor(res)));
  if (p.reynolds)
    s += (raise ? ", or lower lbm.reynolds to at most " : ", or raise lbm.reynolds to at least ") +
         num(*p.reynolds / factor);
  else
    s +=
        (raise ? ", or raise lbm.viscosity to at least " : ", or lower lbm.viscosity to at most ") +
        num(*p.viscosity * factor) + " m^2/s";
  if (moving) {
    const double u = p.lattice_velocity * factor;
    if (u * std::sqrt(3.0) <= LatticeLimits::maxMach)
      s += (raise ? ", or raise lbm.lattice_velocity to at least "
                  : ", or lower lbm.lattice_velocity to at most ") +
           num(u);
  } else {
    s +=
        (raise ? ", or raise lbm.time_step to at least " : ", or lower lbm.time_step to at most ") +
        num(*p.time_step * factor) + " s";
  }
  return s;
}

void checkRelaxationTime(const LbmParams& p, const LatticeUnits& u) {
  const bool moving = u.referenceVelocity > 0.0;
  if (u.tau < LatticeLimits::minTau) {
    // Aim slightly inside the limit so that the rounded suggestions pass.
    const double factor = (LatticeLimits::minTau + 1e-3 - 0.5) / (u.tau - 0.5);
    throw ParamError("resolution",
                     "gives tau = " + num(u.tau, 6) +
                         ", too close to 1/2 (BGK needs tau >= " + num(LatticeLimits::minTau) +
                         " to stay stable): " + knobsForViscosityFactor(p, moving, factor));
  }
  if (u.tau > LatticeLimits::maxTau) {
    const double factor = (LatticeLimits::maxTau - 1e-2 - 0.5) / (u.tau - 0.5);
    throw ParamError(moving ? "lattice_velocity" : "time_step",
                     "gives tau = " + num(u.tau) + ", above " + num(LatticeLimits::maxTau) +
                         " (the wall slip of bounce-back grows with tau): " +
                         knobsForViscosityFactor(p, moving, factor));
  }
}

void checkMach(const LatticeUnits& u) {
  if (u.mach > LatticeLimits::maxMach)
    throw ParamError("lattice_velocity",
                     "gives Mach = lattice_velocity * sqrt(3) = " + num(u.mach) + ", above " +
                         num(LatticeLimits::maxMach) +
                         " (compressibility error ~ Mach^2): lower lbm.lattice_velocity to at "
                         "most " +
                         num(LatticeLimits::maxMach / std::sqrt(3.0), 3));
}

void checkRollerResolution(const LbmParams& p, double dx) {
  for (std::size_t i = 0; i < p.rollers.size(); ++i) {
    const double cells = p.rollers[i].radius / dx;
    if (cells < LatticeLimits::minRollerRadiusCells)
      throw ParamError(
          "rollers[" + std::to_string(i) + "].radius",
          "is " + num(cells, 3) + " lattice cells, fewer than " +
              num(LatticeLimits::minRollerRadiusCells) + ": raise lbm.resolution to at least " +
              std::to_string(static_cast<long>(
                  std::ceil(p.resolution * LatticeLimits::minRollerRadiusCells / cells))));
  }
}

}  // namespace

LatticeUnits computeLatticeUnits(const LbmParams& p) {
  validateLbmParams(p);
  const Geometry g = latticeGeometry(p);
  LatticeUnits u;
  u.nx = g.nx;
  u.ny = g.ny;
  u.dx = g.dx;
  u.density = p.density;
  u.referenceVelocity = referenceVelocity(p);
  u.referenceLength = p.reference_length > 0 ? p.reference_length : p.domain_size[0];
  u.viscosity = physicalViscosity(p, u.referenceVelocity, u.referenceLength);
  u.dt = timeStep(p, u.referenceVelocity, u.dx, u.viscosity);
  u.latticeViscosity = u.viscosity * u.dt / (u.dx * u.dx);
  u.tau = 3.0 * u.latticeViscosity + 0.5;
  u.latticeVelocity = u.referenceVelocity * u.dt / u.dx;
  u.mach = u.latticeVelocity * std::sqrt(3.0);
  u.reynolds = u.referenceVelocity * u.referenceLength / u.viscosity;
  for (int a = 0; a < 2; ++a) u.latticeBodyForce[a] = p.body_force[a] * u.dt * u.dt / u.dx;
  checkRelaxationTime(p, u);
  checkMach(u);
  checkRollerResolution(p, u.dx);
  if (p.end_time < u.dt)
    throw ParamError("end_time", "is " + num(p.end_time) +
                                     " s, shorter than one time step dt = " + num(u.dt) + " s");
  return u;
}

}  // namespace fluidviz::lbm
