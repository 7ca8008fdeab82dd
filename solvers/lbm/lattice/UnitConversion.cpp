#include "solvers/lbm/lattice/UnitConversion.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace fluidviz::lbm {

namespace {

std::string num(double x, int digits = 4) { return formatNumber(x, digits); }

struct Geometry {
  int nx, ny, nz;
  double dx;
};

int bytesPerValue(const LbmParams& p) { return p.precision == Precision::float32 ? 4 : 8; }
int velocityCount(const LbmParams& p) { return is3D(p) ? 19 : 9; }

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
  long nz = 1;
  if (is3D(p)) {
    nz = std::lround(p.domain_depth / lx * nx);
    if (nz < 4)
      throw ParamError("domain_depth",
                       "gives nz = round(Lz / Lx * resolution) = " + std::to_string(nz) +
                           " nodes across z, fewer than 4: raise lbm.resolution to at least " +
                           std::to_string(static_cast<long>(std::ceil(3.5 * lx / p.domain_depth))) +
                           " or make lbm.domain_depth larger");
  }
  const double nodes = static_cast<double>(nx) * ny * nz;
  if (nodes > LatticeLimits::maxNodes) {
    // nodes scale as resolution^D.
    const double dims = is3D(p) ? 3.0 : 2.0;
    const double bytes = 2.0 * velocityCount(p) * bytesPerValue(p);
    throw ParamError("resolution",
                     "gives " + std::to_string(nx) + " x " + std::to_string(ny) +
                         (is3D(p) ? " x " + std::to_string(nz) : std::string()) + " = " +
                         num(nodes, 3) + " nodes, more than " + num(LatticeLimits::maxNodes, 3) +
                         " (" + num(LatticeLimits::maxNodes * bytes / 1e9, 3) +
                         " GB of populations): lower lbm.resolution to at most " +
                         std::to_string(static_cast<long>(
                             std::floor(nx * std::pow(LatticeLimits::maxNodes / nodes, 1.0 / dims)))));
  }
  return {nx, static_cast<int>(ny), static_cast<int>(nz), lx / nx};
}

double physicalViscosity(const LbmParams& p, double uRef, double lRef) {
  if (p.viscosity) return *p.viscosity;
  if (uRef == 0.0)
    throw ParamError("reynolds",
                     "needs a reference speed, but no wall moves, no roller turns, no inlet and no "
                     "initial flow is given; give "
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
                     "is required because nothing moves (no moving wall, roller, inlet or initial "
                     "flow); e.g. "
                     "time_step = dx^2 / (6 nu) = " +
                         num(dx * dx / (6 * nu)) + " s gives tau = 1");
  return *p.time_step;
}

// How each knob scales the lattice viscosity nu_lb = nu dt / dx^2: with a moving wall
// dt = u_lb dx / U_ref, so nu_lb = nu u_lb / (U_ref dx) ~ resolution; without, nu_lb ~
// resolution^2. `factor` = wanted nu_lb / current nu_lb, below 1e6 (the resolution then fits a
// long).
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
  const bool trt = p.collision == Collision::trt;
  const double minTau = trt ? LatticeLimits::minTauTRT : LatticeLimits::minTau;
  if (!(u.tau >= minTau)) {
    // Aim slightly inside the limit so that the rounded suggestions pass.
    const double margin = trt ? 1e-5 : 1e-3;
    const double factor = (minTau + margin - 0.5) / (u.tau - 0.5);
    std::string why = trt ? "TRT needs tau > " + num(minTau, 6) + ", i.e. a positive viscosity"
                          : "BGK needs tau >= " + num(minTau) +
                                " to stay stable; lbm.collision = trt goes closer to 1/2";
    // Beyond a million times the viscosity no knob is practical (an absurd Reynolds number
    // rounds tau to 1/2 exactly, and the factor to infinity).
    if (!(factor < 1e6))
      throw ParamError(p.reynolds ? "reynolds" : "viscosity",
                       "gives tau = " + num(u.tau, 6) + ", too close to 1/2 (" + why +
                           ") by more than any practical lbm.resolution can make up; " +
                           (p.reynolds ? "lower lbm.reynolds" : "raise lbm.viscosity") +
                           " by orders of magnitude");
    throw ParamError("resolution", "gives tau = " + num(u.tau, 6) + ", too close to 1/2 (" + why +
                                       "): " + knobsForViscosityFactor(p, moving, factor));
  }
  if (u.tau > LatticeLimits::maxTau) {
    const double factor = (LatticeLimits::maxTau - 1e-2 - 0.5) / (u.tau - 0.5);
    throw ParamError(moving ? "lattice_velocity" : "time_step",
                     "gives tau = " + num(u.tau) + ", above " + num(LatticeLimits::maxTau) +
                         (trt ? " (the time step is then long against the relaxation: the "
                                "non-equilibrium and compressibility errors grow with tau)"
                              : " (the wall slip of bounce-back grows with tau)") +
                         ": " + knobsForViscosityFactor(p, moving, factor));
  }
}

void checkPressureSides(const LbmParams& p, const LatticeUnits& u) {
  const std::pair<const WallParams*, const char*> sides[6] = {
      {&p.walls.x_min, "x_min"}, {&p.walls.x_max, "x_max"}, {&p.walls.y_min, "y_min"},
      {&p.walls.y_max, "y_max"}, {&p.walls.z_min, "z_min"}, {&p.walls.z_max, "z_max"}};
  const bool moving = u.referenceVelocity > 0.0;
  for (const auto& [w, key] : sides) {
    if (w->type != WallType::pressure_outlet && w->type != WallType::pressure_inlet) continue;
    const double deviation = u.pressureToLatticeDensity(w->pressure) - 1.0;
    if (std::abs(deviation) <= LatticeLimits::maxDensityDeviation) continue;
    // deviation ~ pressure dt^2: dt scales with lattice_velocity (or time_step).
    const double factor = std::sqrt(LatticeLimits::maxDensityDeviation * 0.99 / std::abs(deviation));
    throw ParamError(std::string("walls.") + key + ".pressure",
                     "is " + num(w->pressure) + " Pa, a lattice density 1 + " + num(deviation, 3) +
                         " (more than " + num(LatticeLimits::maxDensityDeviation) +
                         " from 1: compressibility error ~ the density difference): lower the "
                         "pressure to at most " +
                         num(std::abs(w->pressure) * factor * factor, 3) + " Pa, or " +
                         (moving ? "lower lbm.lattice_velocity to at most " +
                                       num(p.lattice_velocity * factor, 3)
                                 : "lower lbm.time_step to at most " +
                                       num(*p.time_step * factor, 3) + " s"));
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

double drivenChannelPeakSpeed(const LbmParams& p, const LatticeUnits& u) {
  auto isWall = [](const WallParams& w) {
    return w.type == WallType::wall || w.type == WallType::moving_wall;
  };
  if (!isWall(p.walls.y_min) || !isWall(p.walls.y_max)) return 0.0;
  auto sidePressure = [](const WallParams& w) {
    const bool pressureSide =
        w.type == WallType::pressure_inlet || w.type == WallType::pressure_outlet;
    return pressureSide ? w.pressure : 0.0;
  };
  const double drop = sidePressure(p.walls.x_min) - sidePressure(p.walls.x_max);
  const double acceleration = p.body_force[0] + drop / (p.density * p.domain_size[0]);
  const double height = p.domain_size[1];
  return std::abs(acceleration) * height * height / (8.0 * u.viscosity);
}

long long plannedSteps(const LbmParams& p, const LatticeUnits& u) {
  return std::min<long long>(p.max_steps, std::llround(std::ceil(p.end_time / u.dt - 1e-9)));
}

LatticeUnits computeLatticeUnits(const LbmParams& p) {
  validateLbmParams(p);
  const Geometry g = latticeGeometry(p);
  LatticeUnits u;
  u.nx = g.nx;
  u.ny = g.ny;
  u.nz = g.nz;
  u.dx = g.dx;
  u.density = p.density;
  u.referenceVelocity = referenceVelocity(p);
  u.referenceLength = p.reference_length > 0 ? p.reference_length : p.domain_size[0];
  u.viscosity = physicalViscosity(p, u.referenceVelocity, u.referenceLength);
  u.dt = timeStep(p, u.referenceVelocity, u.dx, u.viscosity);
  u.latticeViscosity = u.viscosity * u.dt / (u.dx * u.dx);
  u.tau = 3.0 * u.latticeViscosity + 0.5;
  u.tauMinus = p.collision == Collision::trt ? 0.5 + p.trt_magic / (u.tau - 0.5) : u.tau;
  u.latticeVelocity = u.referenceVelocity * u.dt / u.dx;
  u.mach = u.latticeVelocity * std::sqrt(3.0);
  u.reynolds = u.referenceVelocity * u.referenceLength / u.viscosity;
  const double force[3] = {p.body_force[0], p.body_force[1], p.body_force_z};
  for (int a = 0; a < 3; ++a) u.latticeBodyForce[a] = force[a] * u.dt * u.dt / u.dx;
  checkRelaxationTime(p, u);
  checkPressureSides(p, u);
  checkMach(u);
  checkRollerResolution(p, u.dx);
  if (p.end_time < u.dt)
    throw ParamError("end_time", "is " + num(p.end_time) +
                                     " s, shorter than one time step dt = " + num(u.dt) + " s");
  return u;
}

}  // namespace fluidviz::lbm
