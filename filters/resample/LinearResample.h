#pragma once
// First-order consistent resampling (no VTK): moving least squares with the linear basis
// p(x_j) = (1, (x_j - x) / h) weighted by the SPH kernel, the reproducing-kernel correction of
// Liu, Jun & Zhang (1995, RKPM), the linear kernel correction of Bonet & Lok (1999). At a grid
// node x:
//
//   M(x) = sum_j V_j W(x - x_j, h) p_j p_j^T                  ((d+1) x (d+1) moment matrix)
//   A(x) = e1^T M^-1 sum_j V_j W(x - x_j, h) p_j A_j                                      (4)
//
// (4) reproduces every field A = a + b.x exactly, whatever the particle arrangement, wherever
// M is invertible; Shepard's (2) (ParticleResampler.h) is (4) with the basis (1) only, exact for
// constants. The offsets are divided by h so that M, and the conditioning test below, do not
// depend on the length unit.
//
// Fallback: where the neighbourhood cannot determine a linear fit, (4) amplifies noise without
// bound (M near singular: particles on a line in 2D, on a plane in 3D, or a one-sided sliver at
// a free surface). There the node keeps the Shepard value: when fewer than d+1 particles are
// within the support (M is then singular), or when the smallest over the largest eigenvalue of
// M is below kMinMomentConditioning. The output array "resample_order" says which nodes got (4)
// (1) and which kept Shepard's value (0).
//
// Each node gathers its particles through fieldviz/particles' UniformGridNeighborSearch (in a
// fixed order) and is independent of every other node: parallel over node layers (OpenMP),
// the result does not depend on the thread count.
//
// References:
//   W. K. Liu, S. Jun, Y. F. Zhang, "Reproducing kernel particle methods", Int. J. Numer. Meth.
//     Fluids 20 (1995) 1081-1106.
//   J. Bonet, T.-S. L. Lok, "Variational and momentum preservation aspects of smooth particle
//     hydrodynamic formulations", Comput. Methods Appl. Mech. Engrg. 180 (1999) 97-115.
#include <cstddef>

#include "fieldviz/core/Grid.h"
#include "filters/resample/InterpolationKernel.h"
#include "filters/resample/ScatterToGrid.h"

namespace fluidviz::resample {

/// Name of the output array: 1 where (4) was used, 0 where the node kept the Shepard value
/// (or is unsupported, mask 0).
inline const char* kResampleOrderArray = "resample_order";

/// Smallest admissible ratio of the extreme eigenvalues of M (offsets scaled by h):
/// the interior nodes of a lattice jittered by a quarter spacing (h = 1.3 s) all pass it
/// (ResampleLinear_test); a straight line of particles in 2D gives 0.
inline constexpr double kMinMomentConditioning = 1e-3;

/// Overwrites the resampled arrays of `out` at the supported nodes (out.mask == 1) with (4) where
/// the neighbourhood allows it, and writes `order` (one value per node, 1 or 0). The Shepard
/// values must already be in `out` (detail::resampleToGrid): they are what the fallback keeps.
void correctToFirstOrder(const Grid& grid, int dimension, const InterpolationKernel& kernel,
                         const detail::SortedParticles& particles,
                         const detail::OutputTargets& out, double* order);

}  // namespace fluidviz::resample
