// Model A: Mueller, Charypar & Gross (2003). For fluid particle i:
//   rho_i = sum_j m W_poly6(r_ij)  (including j = i)                    (eq. 3)
//   p_i = k (rho_i - rho0),  k = c0^2                                   (PressureMuller2003)
//   f_i = f_pressure (spiky) + f_viscosity (viscosity kernel Laplacian) + f_surface (colour field)
//   a_i = f_i / rho_i + g + sum_walls Lennard-Jones repulsion
// Boundary particles (box walls, rollers, obstacles) add to the density sum (so that fluid next
// to a wall is not thinned out, Akinci et al. 2012), push with the mirrored pressure
// p_b = p_i, rho_b = rho0 (f = -m p_i / rho0 grad W_spiky), drag with the viscosity term at the
// wall velocity, and repel (Lennard-Jones backstop). The box walls also reflect particles
// that cross them (SphSolver), as in Mueller et al.
//   N. Akinci, M. Ihmsen, G. Akinci, B. Solenthaler, M. Teschner, "Versatile rigid-fluid
//   coupling for incompressible SPH", ACM Trans. Graph. 31(4) (2012) 62.
#include "fieldviz/particles/Parallel.h"
#include "fieldviz/particles/KernelsMuller2003.h"
#include "solvers/sph/PressureMuller2003.h"
#include "solvers/sph/SphModels.h"
#include "solvers/sph/SurfaceTensionMuller2003.h"
#include "solvers/sph/ViscosityMuller2003.h"

namespace fluidviz::sph {

namespace {

struct MullerKernels {
  particles::KernelPoly6 poly6;
  particles::KernelSpiky spiky;
  particles::KernelViscosity viscosity;
  MullerKernels(double h, int d) : poly6(h, d), spiky(h, d), viscosity(h, d) {}
};

// Density by summation over fluid particles (Mueller eq. 3), and the pressure.
void densityAndPressure(const MullerKernels& k, const ModelConstants& c, const Interactions& in,
                        FluidState& s) {
  const PressureMuller2003 eos{c.c0 * c.c0, c.rho0};
  const std::int64_t n = static_cast<std::int64_t>(s.size());
#pragma omp parallel for schedule(dynamic, 256) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    double rho = c.mass * k.poly6.W(0.0);
    for (int jj : in.lists.of(i)) {
      const std::size_t j = static_cast<std::size_t>(jj);
      const Vec3& xj = j < in.fluidCount ? s.x[j] : in.boundary.positions[j - in.fluidCount];
      rho += c.mass * k.poly6.W(in.search.displacement(s.x[i], xj).norm());
    }
    s.rho[i] = rho;
    s.p[i] = eos.pressure(rho);
  }
}

Vec3 fluidForces(const MullerKernels& k, const ModelConstants& c, const Interactions& in,
                 const FluidState& s, std::size_t i) {
  const double m = c.mass, mu = c.rho0 * c.nu;
  Vec3 f = Vec3::Zero(), colourGradient = Vec3::Zero();
  double colourLaplacian = m / s.rho[i] * k.poly6.laplacianW(0.0);  // self term of eq. 15
  for (int jj : in.lists.of(i)) {
    const std::size_t j = static_cast<std::size_t>(jj);
    if (j >= in.fluidCount) continue;
    const Vec3 xij = in.search.displacement(s.x[i], s.x[j]);
    const double r = xij.norm();
    f += PressureMuller2003::force(m, s.p[i], s.p[j], s.rho[j], k.spiky.gradW(xij, r));
    if (mu > 0.0)
      f += ViscosityMuller2003::force(mu, m, s.rho[j], s.v[j] - s.v[i], k.viscosity.laplacianW(r));
    if (c.surfaceTension > 0.0) {
      colourGradient += m / s.rho[j] * k.poly6.gradW(xij, r);
      colourLaplacian += m / s.rho[j] * k.poly6.laplacianW(r);
    }
  }
  if (c.surfaceTension > 0.0) {
    const SurfaceTensionMuller2003 st{c.surfaceTension, c.surfaceThreshold / c.h};
    f += st.force(colourGradient, colourLaplacian);
  }
  return f;
}

Vec3 boundaryForces(const MullerKernels& k, const ModelConstants& c, const Interactions& in,
                    const FluidState& s, std::size_t i, Vec3& repulsion) {
  const BoundaryParticles& bp = in.boundary;
  const double mu = c.rho0 * c.nu;
  Vec3 f = Vec3::Zero();
  for (int jj : in.lists.of(i)) {
    const std::size_t j = static_cast<std::size_t>(jj);
    if (j < in.fluidCount) continue;
    const std::size_t b = j - in.fluidCount;
    const Vec3 xij = in.search.displacement(s.x[i], bp.positions[b]);
    const double r = xij.norm();
    repulsion += c.repulsion.acceleration(xij, r * r);
    f += PressureMuller2003::force(c.mass, s.p[i], s.p[i], c.rho0, k.spiky.gradW(xij, r));
    if (mu > 0.0)
      f += ViscosityMuller2003::force(mu, c.mass, c.rho0, bp.velocities[b] - s.v[i],
                                      k.viscosity.laplacianW(r));
  }
  return f;
}

}  // namespace

void computeRatesMuller2003(const ModelConstants& c, const Interactions& in, FluidState& s) {
  const MullerKernels k(c.h, c.dimension);
  densityAndPressure(k, c, in, s);
  const std::int64_t n = static_cast<std::int64_t>(s.size());
#pragma omp parallel for schedule(dynamic, 256) if(n >= particles::kParallelMinItems)
  for (std::int64_t i = 0; i < n; ++i) {
    Vec3 repulsion = Vec3::Zero();
    const Vec3 f = fluidForces(k, c, in, s, i) + boundaryForces(k, c, in, s, i, repulsion);
    s.a[i] = f / s.rho[i] + c.gravity + repulsion;
    s.drho[i] = 0.0;
    s.xsph[i].setZero();
  }
}

}  // namespace fluidviz::sph
