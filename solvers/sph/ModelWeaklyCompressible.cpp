// Model B: weakly compressible SPH, the free-surface formulation of Monaghan (1994) with the
// laminar viscosity and wall treatment of Morris et al. (1997). For fluid particle i:
//   d rho_i/dt = sum_j m v_ij . grad W_ij            (DensityContinuity; a separate pass, since
//                                                      the integrator drifts rho with v(n+1/2))
//                + delta h c0 sum_j psi_ij . grad W_ij m/rho_j   (DensityDiffusionMolteniColagrossi2009)
//   a_i = g - sum_j m (p_i/rho_i^2 + p_j/rho_j^2) grad W_ij              (PressureMonaghan1992)
//           - sum_j m Pi_ij grad W_ij                          (ArtificialViscosityMonaghan1992)
//           + sum_j m 2 mu/(rho_i rho_j) (x_ij . grad W_ij)/(r^2 + eta^2) v_ij
//                                                         (ViscosityMorris1997; walls too)
//           - kappa sum_j W_ij x_ij                              (CohesionBeckerTeschner2007)
//           + sum_walls D [(r0/r)^n1 - (r0/r)^n2] x_ij / r^2  (BoundaryRepulsionLennardJones)
//   XSPH:  epsilon sum_j m/rhobar (v_j - v_i) W_ij                             (XsphCorrection)
// Boundary particles take part in the repulsion, the viscous term (no-slip, Morris 1997) and,
// with wall_pressure = adami2012, in the pressure gradient and the continuity equation with the
// pressure extrapolated from the fluid (WallPressureAdami2012).
#include <variant>

#include "fieldviz/particles/Parallel.h"
#include "solvers/sph/ArtificialViscosityMonaghan1992.h"
#include "solvers/sph/CohesionBeckerTeschner2007.h"
#include "solvers/sph/DensityContinuity.h"
#include "solvers/sph/DensityDiffusionMolteniColagrossi2009.h"
#include "solvers/sph/EquationOfStateTait.h"
#include "fieldviz/particles/KernelCubicSpline.h"
#include "fieldviz/particles/KernelWendlandC2.h"
#include "solvers/sph/PressureMonaghan1992.h"
#include "solvers/sph/SphModels.h"
#include "solvers/sph/ViscosityMorris1997.h"
#include "solvers/sph/WallPressureAdami2012.h"
#include "solvers/sph/XsphCorrection.h"

namespace fluidviz::sph {

namespace {

// Per-particle quantities read by the pair loop, computed once per evaluation.
struct ParticleTerms {
  std::vector<double> pOverRho2, soundSpeed;
  std::vector<double> wallPOverRho2;  ///< p_w / rho_w^2 of each boundary particle
};

ParticleTerms pressureTerms(const ModelConstants& c, FluidState& s) {
  const EquationOfStateTait eos(c.rho0, c.c0, c.gamma);
  const std::int64_t n = static_cast<std::int64_t>(s.size());
  ParticleTerms t;
  t.pOverRho2.resize(n);
  t.soundSpeed.resize(n);
#pragma omp parallel for schedule(static) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    s.p[i] = eos.pressure(s.rho[i]);
    t.pOverRho2[i] = s.p[i] / (s.rho[i] * s.rho[i]);
    t.soundSpeed[i] = eos.soundSpeed(s.rho[i]);
  }
  return t;
}

// Wall pressure of each boundary particle from its fluid neighbours (Adami et al. 2012).
template <class Kernel>
void wallPressures(const Kernel& k, const ModelConstants& c, const Interactions& in,
                   const FluidState& s, ParticleTerms& t) {
  const BoundaryParticles& bp = in.boundary;
  const std::int64_t nb = static_cast<std::int64_t>(bp.size());
  t.wallPOverRho2.assign(nb, 0.0);
  if (!c.wallPressure || !in.boundaryLists) return;
  const EquationOfStateTait eos(c.rho0, c.c0, c.gamma);
#pragma omp parallel for schedule(dynamic, 256) if(nb >= particles::kParallelMinItems)
  for (std::int64_t b = 0; b < nb; ++b) {
    WallPressureAdami2012 wall;
    for (int f : in.boundaryLists->of(b)) {
      const Vec3 xwf = in.search.displacement(bp.positions[b], s.x[f]);
      wall.add(k.W(xwf.norm()), s.p[f], s.rho[f], xwf);
    }
    if (wall.sumW == 0.0) continue;
    const BoundarySurface& surf = bp.surfaces[bp.surface[b]];
    const Vec3 aWall = -surf.angularVelocity * surf.angularVelocity *
                       (bp.positions[b] - surf.center).cwiseProduct(Vec3(1, 1, 0));
    const double p = wall.pressure(c.gravity - aWall), rho = eos.density(p);
    t.wallPOverRho2[b] = p / (rho * rho);
  }
}

struct PairSums {
  Vec3 a = Vec3::Zero(), xsph = Vec3::Zero();
};

template <class Kernel>
class WeaklyCompressibleRates {
 public:
  WeaklyCompressibleRates(const Kernel& k, const ModelConstants& c, const Interactions& in,
                          const FluidState& s, const ParticleTerms& t)
      : k_(k), c_(c), in_(in), s_(s), t_(t) {
    const double h = c.h;
    eta2_ = 0.01 * h * h;
    twoMu_ = 2.0 * c.rho0 * c.nu;
    av_ = {c.alpha, c.beta, h, eta2_};
  }

  PairSums particle(std::size_t i) const {
    PairSums sum;
    for (int j : in_.lists.of(i)) {
      if (static_cast<std::size_t>(j) < in_.fluidCount)
        fluidPair(i, static_cast<std::size_t>(j), sum);
      else
        boundaryPair(i, static_cast<std::size_t>(j) - in_.fluidCount, sum);
    }
    sum.a += c_.gravity;
    sum.xsph *= c_.xsphEpsilon;
    return sum;
  }

 private:
  void fluidPair(std::size_t i, std::size_t j, PairSums& sum) const {
    const double m = c_.mass;
    const Vec3 xij = in_.search.displacement(s_.x[i], s_.x[j]);
    const double r2 = xij.squaredNorm(), r = std::sqrt(r2);
    const Vec3 gradW = k_.gradW(xij, r);
    const Vec3 vij = s_.v[i] - s_.v[j];
    sum.a += PressureMonaghan1992::acceleration(m, t_.pOverRho2[i], t_.pOverRho2[j], gradW);
    const double rhobar = 0.5 * (s_.rho[i] + s_.rho[j]);
    if (c_.alpha > 0.0 || c_.beta > 0.0)
      sum.a += av_.acceleration(m, xij, r2, vij, 0.5 * (t_.soundSpeed[i] + t_.soundSpeed[j]),
                                rhobar, gradW);
    if (twoMu_ > 0.0)
      sum.a += ViscosityMorris1997::acceleration(m, twoMu_, s_.rho[i], s_.rho[j], xij, r2, gradW,
                                                 vij, eta2_);
    if (c_.cohesion > 0.0 || c_.xsphEpsilon > 0.0) {
      const double W = k_.W(r);
      if (c_.cohesion > 0.0)
        sum.a += CohesionBeckerTeschner2007::acceleration(c_.cohesion, m, m, W, xij);
      if (c_.xsphEpsilon > 0.0) sum.xsph += XsphCorrection::term(m, rhobar, -vij, W);
    }
  }

  void boundaryPair(std::size_t i, std::size_t b, PairSums& sum) const {
    const BoundaryParticles& bp = in_.boundary;
    const Vec3 xij = in_.search.displacement(s_.x[i], bp.positions[b]);
    const double r2 = xij.squaredNorm();
    sum.a += c_.repulsion.acceleration(xij, r2);
    const Vec3 gradW = k_.gradW(xij, std::sqrt(r2));
    if (c_.wallPressure) {
      sum.a += PressureMonaghan1992::acceleration(c_.mass, t_.pOverRho2[i], t_.wallPOverRho2[b],
                                                  gradW);
    }
    if (twoMu_ > 0.0) {
      const double di = bp.surfaces[bp.surface[b]].fluidDistance(s_.x[i]);
      const Vec3 vij =
          ViscosityMorris1997::wallVelocityDifference(s_.v[i], bp.velocities[b], di, bp.depth[b],
                                                      0.5 * c_.spacing);
      sum.a += ViscosityMorris1997::acceleration(c_.mass, twoMu_, s_.rho[i], c_.rho0, xij, r2,
                                                 gradW, vij, eta2_);
    }
  }

  const Kernel& k_;
  const ModelConstants& c_;
  const Interactions& in_;
  const FluidState& s_;
  const ParticleTerms& t_;
  double eta2_ = 0.0, twoMu_ = 0.0;
  ArtificialViscosityMonaghan1992 av_;
};

template <class Kernel>
void evaluate(const Kernel& k, const ModelConstants& c, const Interactions& in, FluidState& s) {
  ParticleTerms t = pressureTerms(c, s);
  wallPressures(k, c, in, s, t);
  const WeaklyCompressibleRates<Kernel> rates(k, c, in, s, t);
  const std::int64_t n = static_cast<std::int64_t>(s.size());
#pragma omp parallel for schedule(dynamic, 256) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    const PairSums sum = rates.particle(static_cast<std::size_t>(i));
    s.a[i] = sum.a;
    s.xsph[i] = sum.xsph;
  }
}

// d rho_i/dt = sum_j m (v_i - v_j) . grad W_ij over fluid and (with wall pressure) wall
// particles, the latter moving with the wall.
template <class Kernel>
void densityRate(const Kernel& k, const ModelConstants& c, const Interactions& in,
                 const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                 const std::vector<double>& rho, std::vector<double>& drho) {
  const BoundaryParticles& bp = in.boundary;
  const DensityDiffusionMolteniColagrossi2009 diffusion{
      c.densityDiffusion * c.h * c.c0, c.rho0, c.rho0 * c.c0 * c.c0 / c.gamma, c.gamma,
      c.hydrostaticGravity,
      0.01 * c.h * c.h};
  const std::size_t nf = in.fluidCount;
  const std::int64_t n = static_cast<std::int64_t>(nf);
#pragma omp parallel for schedule(dynamic, 256) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    double rate = 0.0;
    for (int jj : in.lists.of(i)) {
      const std::size_t j = static_cast<std::size_t>(jj);
      const bool fluid = j < nf;
      if (!fluid && !c.wallPressure) continue;
      const Vec3& xj = fluid ? x[j] : bp.positions[j - nf];
      const Vec3& vj = fluid ? v[j] : bp.velocities[j - nf];
      const Vec3 xij = in.search.displacement(x[i], xj);
      const double r2 = xij.squaredNorm();
      const Vec3 gradW = k.gradW(xij, std::sqrt(r2));
      rate += DensityContinuity::rate(c.mass, v[i] - vj, gradW);
      if (fluid && diffusion.deltaHC0 > 0.0)
        rate += diffusion.rate(c.mass, rho[i], rho[j], xij, r2, gradW);
    }
    drho[i] = rate;
  }
}

}  // namespace

void computeRatesWeaklyCompressible(SphKernel kernel, const ModelConstants& c,
                                    const Interactions& in, FluidState& s) {
  if (kernel == SphKernel::wendland_c2)
    evaluate(particles::KernelWendlandC2(c.h, c.dimension), c, in, s);
  else
    evaluate(particles::KernelCubicSpline(c.h, c.dimension), c, in, s);
}

void computeDensityRateWeaklyCompressible(SphKernel kernel, const ModelConstants& c,
                                          const Interactions& in, const std::vector<Vec3>& x,
                                          const std::vector<Vec3>& v,
                                          const std::vector<double>& rho,
                                          std::vector<double>& drho) {
  if (kernel == SphKernel::wendland_c2)
    densityRate(particles::KernelWendlandC2(c.h, c.dimension), c, in, x, v, rho, drho);
  else
    densityRate(particles::KernelCubicSpline(c.h, c.dimension), c, in, x, v, rho, drho);
}

}  // namespace fluidviz::sph
