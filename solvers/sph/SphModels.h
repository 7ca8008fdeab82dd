#pragma once
// The two SPH models as rate functions: given positions, velocities (and for model B the
// densities), compute accelerations (and density rates). The solver (SphSolver) owns the state,
// the neighbour search and the time integration.
#include <string>
#include <vector>

#include "fieldviz/core/Grid.h"
#include "solvers/sph/BoundaryParticles.h"
#include "solvers/sph/BoundaryRepulsionLennardJones.h"
#include "solvers/sph/SphParams.h"
#include "fieldviz/particles/UniformGridNeighborSearch.h"

namespace fluidviz::sph {

/// Per-particle state of the fluid; all arrays have one entry per fluid particle.
struct FluidState {
  std::vector<Vec3> x;       ///< m, positions
  std::vector<Vec3> v;       ///< m/s, velocities
  std::vector<Vec3> a;       ///< m/s^2, accelerations at the last evaluation
  std::vector<Vec3> xsph;    ///< m/s, XSPH velocity correction (model B; epsilon included)
  std::vector<double> rho;   ///< kg/m^3, density
  std::vector<double> drho;  ///< kg/m^3/s, density rate (model B)
  std::vector<double> p;     ///< Pa, pressure

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    x.resize(n), v.resize(n), a.resize(n), xsph.resize(n);
    rho.resize(n), drho.resize(n), p.resize(n);
  }
};

/// Constants of both models, derived from SphParams.
struct ModelConstants {
  int dimension = 2;
  double h = 0.0;      ///< m, smoothing length (support 2h)
  double spacing = 0.0;  ///< m, initial particle spacing dx
  double mass = 0.0;   ///< kg, particle mass rho0 dx^d
  double rho0 = 0.0;   ///< kg/m^3
  double c0 = 0.0;     ///< m/s
  double gamma = 7.0;  ///< Tait exponent
  double nu = 0.0;     ///< m^2/s
  double alpha = 0.0, beta = 0.0, xsphEpsilon = 0.0;
  double cohesion = 0.0;        ///< kappa
  double densityDiffusion = 0.0;  ///< delta of delta-SPH (model B)
  double surfaceTension = 0.0;  ///< sigma
  double surfaceThreshold = 0.0;  ///< dimensionless, |n| h
  Vec3 gravity = Vec3::Zero();
  /// gravity without its components along periodic axes: the part a fluid at rest balances
  /// by a pressure gradient (hydrostatic initial density, density-diffusion correction)
  Vec3 hydrostaticGravity = Vec3::Zero();
  BoundaryRepulsionLennardJones repulsion;
  bool wallPressure = false;  ///< model B: walls take part in pressure and continuity (Adami 2012)
};

/// Who interacts with whom: neighbour lists of the fluid particles over the combined point set
/// (fluid first, then boundary particles).
struct Interactions {
  const particles::NeighborLists& lists;
  const particles::UniformGridNeighborSearch& search;
  const BoundaryParticles& boundary;
  std::size_t fluidCount;
  /// Fluid neighbours of each boundary particle (row k: boundary particle k); needed by the
  /// wall pressure of model B, may be null otherwise.
  const particles::NeighborLists* boundaryLists = nullptr;
};

/// Model B (weakly compressible SPH). Reads x, v, rho; writes p (Tait), a, xsph.
void computeRatesWeaklyCompressible(SphKernel kernel, const ModelConstants& c,
                                    const Interactions& in, FluidState& s);

/// Model B continuity equation: drho_i = sum_j m (v_i - v_j) . grad W_ij at positions x (the
/// ones `in` was built for) with velocities v (walls: their own velocity), plus the density
/// diffusion (delta-SPH) of densities rho when c.densityDiffusion > 0.
void computeDensityRateWeaklyCompressible(SphKernel kernel, const ModelConstants& c,
                                          const Interactions& in, const std::vector<Vec3>& x,
                                          const std::vector<Vec3>& v,
                                          const std::vector<double>& rho,
                                          std::vector<double>& drho);

/// Model A (Mueller et al. 2003). Reads x, v; writes rho (summation), p, a.
void computeRatesMuller2003(const ModelConstants& c, const Interactions& in, FluidState& s);

}  // namespace fluidviz::sph
