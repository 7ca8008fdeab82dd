#pragma once
// The Taylor & Green (1937) vortex array, an exact solution of the incompressible Navier-Stokes
// equations in a periodic box, one period across it:
//   u = U0 sin(a x) cos(b y) D(t),  v = -U0 (a/b) cos(a x) sin(b y) D(t),  D = exp(-nu (a^2 + b^2) t),
//   p = rho0 U0^2 / 4 (cos 2ax + (a/b)^2 cos 2by) D(t)^2,   a = 2 pi / Lx, b = 2 pi / Ly,
// uniform along z. The initial flow `lbm.initial_flow = taylor_green` and the convergence tests and
// benchmarks that compare with it all use this one definition.
#include <cmath>

#include "fieldviz/core/Field.h"

namespace fluidviz::lbm {

struct TaylorGreenVortex {
  double a;      ///< 2 pi / Lx (1/m)
  double b;      ///< 2 pi / Ly (1/m)
  double u0;     ///< amplitude U0 (m/s)
  double nu;     ///< kinematic viscosity (m^2/s)

  double decay(double t) const { return std::exp(-nu * (a * a + b * b) * t); }
  Vec3 velocity(const Vec3& x, double t) const {
    return u0 * decay(t) *
           Vec3(std::sin(a * x.x()) * std::cos(b * x.y()),
                -(a / b) * std::cos(a * x.x()) * std::sin(b * x.y()), 0.0);
  }
  /// Pressure relative to the mean (Pa) for the density rho0 (kg/m^3).
  double pressure(const Vec3& x, double t, double rho0) const {
    const double d = decay(t), r = a / b;
    return rho0 * u0 * u0 / 4 * (std::cos(2 * a * x.x()) + r * r * std::cos(2 * b * x.y())) * d * d;
  }
  /// Relative L2 difference |u - u_exact| / |u_exact| over the nodes of `u` (z = 0 plane) at t.
  double relativeL2Error(const VectorField& u, double t) const {
    double err2 = 0, ref2 = 0;
    for (int j = 0; j < u.grid.dims[1]; ++j)
      for (int i = 0; i < u.grid.dims[0]; ++i) {
        const Vec3 exact = velocity(u.grid.position(i, j), t);
        err2 += (u.values[u.grid.index(i, j)] - exact).squaredNorm();
        ref2 += exact.squaredNorm();
      }
    return std::sqrt(err2 / ref2);
  }
};

}  // namespace fluidviz::lbm
