#pragma once
// Stream function psi of a planar incompressible flow: u = d psi / dy, v = -d psi / dx.
//
// psi solves the Poisson problem  lap psi = -omega,  omega = dv/dx - du/dy (vorticity), with
// Dirichlet values on the domain boundary from integrating the flux across it:
//   psi(s) = integral_0^s (u . n) ds'  (n: outward normal, boundary traversed counter-clockwise
//                                       from the corner at the grid origin, where psi = 0).
// Discretisation (second order): omega by central differences at interior nodes, the 5-point
// Laplacian (spacings dx, dy), the boundary integral by the trapezoidal rule. For a flow with
// non-zero net outflow (compressible or noisy data) the boundary integral does not close; the
// mismatch is spread along the boundary in proportion to arc length and reported.
// Solved with Eigen: SimplicialLDLT (direct) or conjugate gradients with a Jacobi preconditioner.
#include "fieldviz/core/Field.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz::topology {

struct StreamFunctionResult {
  ScalarField psi;  ///< "stream_function", m^2/s, on the slice's 2D grid (z = the slice's z)
  /// Net outflow through the boundary, integral of u . n ds (m^2/s); ~0 for incompressible
  /// flow. It was spread along the boundary values.
  double boundary_flux_mismatch = 0.0;
  int iterations = 0;              ///< conjugate-gradient iterations (0 for the direct solver)
  double relative_residual = 0.0;  ///< |A psi - b| / |b| of the interior system
};

/// Stream function of slice params.slice_index of `field` (v_x, v_y). Throws ParamError for bad
/// params, std::invalid_argument for an unusable field, std::runtime_error if the solver fails.
StreamFunctionResult computeStreamFunction(const VectorField& field, const TopologyParams& params);

}  // namespace fluidviz::topology
