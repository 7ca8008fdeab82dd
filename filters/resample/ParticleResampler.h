#pragma once
// SPH interpolation of particle arrays onto a regular grid (no VTK).
//
// At every grid node x, with particle volumes V_j = m_j / rho_j (or a uniform volume, see
// ResampleParams.h) and the kernel W of smoothing length h:
//
//   colour field        c(x) = sum_j V_j W(x - x_j, h)                                    (1)
//   Shepard estimate    A(x) = sum_j V_j A_j W(x - x_j, h) / c(x)                          (2)
//   summation density   rho(x) = sum_j m_j W(x - x_j, h)   (only when masses are given)    (3)
//
// (1) is Monaghan's SPH estimate of the constant 1: ~1 inside the fluid, falling to 0 over ~2h
// across a free surface, so its 0.5 level set is the surface (Mueller et al. 2003, sec. 4.4;
// Akinci et al. 2012). (2) divides the SPH estimate by (1) (Shepard 1968; Price 2012, eq. 49
// with the normalisation of sec. 3.2), which reproduces constants exactly and removes the
// surface deficiency of the plain sum; its error is grad A . m1 + O(h^2) with m1 the kernel's
// first moment over the particles (0 on symmetric arrangements: then O(h^2)).
//
// Nodes with c(x) < support_threshold are "unsupported": mask = 0 and every resampled array holds
// empty_value (NaN unless set) there, never a silent 0. Output arrays: each resampled array under
// its own name (1 or 3 components), "color" (1), "mask" (1: 1 = supported, 0 = not) and
// "summation_density" (3) when the particles have masses.
//
// order = linear replaces (2) by the first-order moving-least-squares estimate (4) of
// LinearResample.h wherever the particle neighbourhood supports it, keeping (2) elsewhere; the
// output array "resample_order" (1 = first order, 0 = Shepard) then says which. With order =
// shepard (the default) nothing of the above changes and that array is not written.
//
// The sums are scattered: each particle adds its terms to the grid nodes inside its support,
// found by index arithmetic on the grid (ScatterToGrid.h) - the grid is the neighbour search.
// Kernels are solvers/sph's; its UniformGridNeighborSearch estimates the particle spacing when
// it is not given. Threads own blocks of grid layers and add particles in a fixed order, so the
// result does not depend on the thread count (OpenMP).
//
// References:
//   J. J. Monaghan, "Smoothed particle hydrodynamics", Rep. Prog. Phys. 68 (2005) 1703, eq. 2.9.
//   D. Shepard, "A two-dimensional interpolation function for irregularly-spaced data",
//     Proc. ACM National Conference 1968, 517-524.
//   D. J. Price, "Smoothed particle hydrodynamics and magnetohydrodynamics", J. Comput. Phys.
//     231 (2012) 759-794, eq. 49.
//   M. Mueller, D. Charypar, M. Gross, "Particle-based fluid simulation for interactive
//     applications", SCA 2003 (colour field).
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/resample/ResampleGrid.h"
#include "filters/resample/ResampleParams.h"
#include "fieldviz/particles/ParticleSet.h"

namespace fluidviz::resample {

/// Names of the arrays the resampler adds to the resampled ones.
inline const char* kColorArray = "color";
inline const char* kMaskArray = "mask";
inline const char* kSummationDensityArray = "summation_density";
/// The particle array of smoothing lengths h (m) that fluidviz snapshots carry and `fluidviz
/// resample` uses when no h is given.
inline const char* kSmoothingLengthArray = "smoothing_length";

/// The median of the particles' array smoothing_length (fluidviz snapshots have one value per
/// particle), nullopt when they have no such array or it is empty: the h that `fluidviz
/// resample` and the ParaView plugin use when none is given. The value is not checked.
std::optional<double> medianSmoothingLength(const particles::ParticleSet& particles);

/// What the resampler chose and assumed (for logs: defaults are never silent).
struct ResampleReport {
  int dimension = 3;                 ///< 2 or 3
  std::string kernel;                ///< kernel name
  double smoothingLength = 0.0;      ///< h, m
  double particleSpacing = 0.0;      ///< s, m
  std::string spacingSource;         ///< how s was obtained
  std::string volumeSource;          ///< how V_j was obtained
  Grid grid;                         ///< the output grid
  std::size_t particles = 0;         ///< particle count
  std::size_t supportedNodes = 0;    ///< nodes with mask = 1
  std::size_t unsupportedNodes = 0;  ///< nodes with mask = 0
  ResampleOrder order = ResampleOrder::shepard;
  std::size_t firstOrderNodes = 0;   ///< nodes where eq. (4) was used (order linear)
  std::vector<std::string> resampledArrays;  ///< particle arrays interpolated, in output order
  double fieldBytes = 0.0;           ///< memory of the output fields, bytes

  /// Several lines "key: value (source)" describing the above.
  std::string summary() const;
};

struct ResampleResult {
  FieldSet fields;
  ResampleReport report;
};

/// Resamples `particles` (all arrays, or those listed in params.arrays) onto a grid covering
/// their bounding box plus padding. Throws ParamError (key named) for bad parameters, for a grid
/// that would need more than max_memory_mb (before allocating it; the message gives the memory
/// it would need), and std::invalid_argument naming the particle array or particle index for
/// bad particle data (no particles, non-finite positions, array sizes, mass or density <= 0).
ResampleResult resampleParticles(const particles::ParticleSet& particles,
                                 const ParticleResampleParams& params);

/// The same on a grid covering `gridBox` (grown by the padding) instead of the particles'
/// bounding box when gridBox is not null: a fixed grid for every snapshot of a run.
ResampleResult resampleParticles(const particles::ParticleSet& particles,
                                 const ParticleResampleParams& params, const Bounds* gridBox);

/// Every choice and check of resampleParticles (parameters, arrays, volumes, spacing, the grid
/// and its memory) without computing anything on the grid; throws as resampleParticles does.
ResampleReport planResampling(const particles::ParticleSet& particles,
                              const ParticleResampleParams& params,
                              const Bounds* gridBox = nullptr);

}  // namespace fluidviz::resample
