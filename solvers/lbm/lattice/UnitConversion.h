#pragma once
// Physical <-> lattice units (one class does the conversion, as FluidX3D does). The lattice
// spacing dx and time step dt map lattice quantities (dx = dt = 1, rho = 1) to SI:
//   velocity u = u_lb dx / dt,  viscosity nu = nu_lb dx^2 / dt,  acceleration g = g_lb dx / dt^2,
//   density rho = rho_lb * density.
// BGK relaxation time tau = 3 nu_lb + 1/2 (c_s^2 = 1/3; Qian, d'Humieres & Lallemand 1992).
#include <array>

#include "solvers/lbm/LbmParams.h"

namespace fluidviz::lbm {

/// Limits enforced by computeLatticeUnits (and quoted in its messages).
struct LatticeLimits {
  /// BGK needs tau > 1/2 (positive viscosity); close to 1/2 it is unstable at any useful speed.
  static constexpr double minTau = 0.505;
  /// TRT stays linearly stable down to tau+ -> 1/2 (d'Humieres & Ginzburg 2009); this only keeps
  /// tau- = 1/2 + Lambda / (tau+ - 1/2) finite. Whether a run that close to 1/2 is stable depends
  /// on the flow (checked while running) and whether it is accurate on the resolution.
  static constexpr double minTauTRT = 0.5 + 1e-5;
  /// Above this the viscosity-dependent slip of halfway bounce-back (He et al. 1997) dominates.
  static constexpr double maxTau = 5.0;
  /// Ma = u_lb / c_s = u_lb sqrt(3); compressibility errors grow as Ma^2.
  static constexpr double maxMach = 0.3;
  /// Two population arrays of Q values: 144 bytes per node for D2Q9 in double; 2^26 nodes =
  /// 9.7 GB (D2Q9, double) or 20 GB (D3Q19, double).
  static constexpr double maxNodes = 67108864.0;
  /// |rho - 1| of a pressure side in lattice units: the pressure difference is carried by a
  /// density difference, and the compressibility error grows with it.
  static constexpr double maxDensityDeviation = 0.1;
  /// A roller thinner than this many cells is not resolved by the staircase of nodes.
  static constexpr double minRollerRadiusCells = 2.0;
};

struct LatticeUnits {
  int nx = 0;                      ///< nodes along x (= resolution)
  int ny = 0;                      ///< nodes along y (= round(Ly / Lx resolution))
  int nz = 1;                      ///< nodes along z (= round(Lz / Lx resolution); 1 in 2D)
  double dx = 0.0;                 ///< m, lattice spacing Lx / nx
  double dt = 0.0;                 ///< s, time step
  double viscosity = 0.0;          ///< m^2/s, physical kinematic viscosity
  double latticeViscosity = 0.0;   ///< nu dt / dx^2
  double tau = 0.0;                ///< relaxation time 3 nu_lb + 1/2 (TRT: tau+), <= 5
  double tauMinus = 0.0;           ///< TRT: 1/2 + Lambda / (tau - 1/2); BGK: = tau
  double referenceVelocity = 0.0;  ///< m/s, fastest wall speed U_ref (0 if nothing moves)
  double referenceLength = 0.0;    ///< m, L_ref of the Reynolds number
  double latticeVelocity = 0.0;    ///< U_ref dt / dx (0 if nothing moves)
  double mach = 0.0;               ///< latticeVelocity sqrt(3)
  double reynolds = 0.0;           ///< U_ref L_ref / nu (0 if nothing moves)
  double density = 0.0;            ///< kg/m^3 of lattice density 1
  std::array<double, 3> latticeBodyForce{0.0, 0.0, 0.0};  ///< acceleration g dt^2 / dx

  double omega() const { return 1.0 / tau; }
  double omegaMinus() const { return 1.0 / tauMinus; }
  double toLatticeVelocity(double u) const { return u * dt / dx; }
  double toPhysicalVelocity(double uLattice) const { return uLattice * dx / dt; }
  double toPhysicalDensity(double rhoLattice) const { return rhoLattice * density; }
  double toLatticeDensity(double rho) const { return rho / density; }
  /// Lattice density of a gauge pressure p (Pa): p = cs2 (rho - 1) density (dx/dt)^2.
  double pressureToLatticeDensity(double p) const {
    return 1.0 + 3.0 * p * dt * dt / (density * dx * dx);
  }
  /// Position (m) of node (i, j, k): cell centres, walls on the box edges.
  double nodeX(int i) const { return (i + 0.5) * dx; }
  double nodeY(int j) const { return (j + 0.5) * dx; }
  double nodeZ(int k) const { return (k + 0.5) * dx; }
  long long nodeCount() const { return static_cast<long long>(nx) * ny * nz; }
};

/// Validates p (validateLbmParams, then the lattice limits above) and converts it. Throws
/// ParamError whose key and message name the physical parameter to change and by how much, e.g.
/// "tau = 0.5003 is too close to 1/2 ...: raise lbm.resolution to at least 410 or lower
/// lbm.reynolds to at most 3200".
LatticeUnits computeLatticeUnits(const LbmParams& p);

/// The peak speed (m/s) of plane Poiseuille flow between the y walls for a flow that nothing
/// moves but a body force along x and/or a pressure difference between the x sides drives:
/// u_max = a H^2 / (8 nu), a = g_x + (p_in - p_out) / (rho L) (White, Viscous Fluid Flow, eq.
/// 3-36). An upper bound when rollers or a duct's side walls slow the flow; 0 when the flow has
/// no such channel (no walls at both y sides, or no driving along x).
double drivenChannelPeakSpeed(const LbmParams& p, const LatticeUnits& u);

/// Time steps a run of p takes at most: ceil(end_time / dt), capped at max_steps.
long long plannedSteps(const LbmParams& p, const LatticeUnits& u);

}  // namespace fluidviz::lbm
