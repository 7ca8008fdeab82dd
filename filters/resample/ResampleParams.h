#pragma once
// Parameters of SPH particle-to-grid resampling (filters/resample/ParticleResampler.h). One
// declaration drives scene keys, the `fluidviz resample` flags, validation messages and docs.
//
// Conventions: h is the smoothing length; every kernel has compact support 2h (the convention of
// solvers/sph, KernelsMuller2003.h). "Particle spacing" s is the typical distance between
// neighbouring particles; the particle volume V_j defaults to m_j / rho_j when the particles
// carry both a mass and a density array, otherwise to the uniform s^d (d = 2 or 3).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"

namespace fluidviz::resample {

/// The SPH kernels of solvers/sph, all with support 2h.
enum class ResampleKernel { cubic_spline, wendland_c2, poly6 };
constexpr std::array<Choice<ResampleKernel>, 3> paramChoices(ResampleKernel) {
  return {{{ResampleKernel::cubic_spline, "cubic_spline"},
           {ResampleKernel::wendland_c2, "wendland_c2"},
           {ResampleKernel::poly6, "poly6"}}};
}

/// Consistency order of the interpolation (ParticleResampler.h eq. (2), LinearResample.h eq. (4)).
enum class ResampleOrder { shepard, linear };
constexpr std::array<Choice<ResampleOrder>, 2> paramChoices(ResampleOrder) {
  return {{{ResampleOrder::shepard, "shepard"}, {ResampleOrder::linear, "linear"}}};
}

struct ParticleResampleParams {
  // Units, ranges and meanings of the members: their describe() declarations below.
  ResampleKernel kernel = ResampleKernel::cubic_spline;
  ResampleOrder order = ResampleOrder::shepard;
  std::optional<double> smoothing_length;  ///< h
  std::optional<double> spacing;
  int dims = 0;
  std::optional<double> padding;
  double support_threshold = 0.05;  ///< on the colour field c = sum_j V_j W_j
  std::optional<double> particle_spacing;  ///< s
  std::optional<double> particle_volume;   ///< V_j for all particles
  std::string mass_array = "mass";
  std::string density_array = "density";
  std::string arrays;
  std::optional<double> empty_value;
  int dimension = 0;
  double max_memory_mb = 4096.0;

  template <class V>
  static void describe(V& v) {
    v(&ParticleResampleParams::kernel,
      {.key = "kernel",
       .description = "SPH kernel W (solvers/sph): cubic_spline (Monaghan 1992), wendland_c2 "
                      "(Wendland 1995), poly6 (Mueller 2003); all have support 2h"});
    v(&ParticleResampleParams::order,
      {.key = "order",
       .description = "shepard: sum V A W / sum V W, exact for constants (Shepard 1968); linear: "
                      "moving least squares with basis (1, x) (RKPM, Liu et al. 1995; Bonet & "
                      "Lok 1999), exact for linear fields, falling back to shepard where the "
                      "moment matrix is near singular (fewer than d+1 particles, eigenvalue "
                      "ratio < 1e-3); array resample_order says where (1 linear, 0 shepard)"});
    v(&ParticleResampleParams::smoothing_length,
      {.key = "smoothing_length",
       .unit = "m",
       .description = "smoothing length h; empty: 1.3 x particle spacing",
       .min = 0,
       .minExclusive = true});
    v(&ParticleResampleParams::spacing,
      {.key = "spacing",
       .unit = "m",
       .description = "grid node distance; empty: from dims, or else the particle spacing",
       .min = 0,
       .minExclusive = true});
    v(&ParticleResampleParams::dims,
      {.key = "dims",
       .description = "nodes along the grid's longest axis (used when spacing is empty); 0: "
                      "spacing decides",
       .min = 0,
       .max = 65536});
    v(&ParticleResampleParams::padding,
      {.key = "padding",
       .unit = "m",
       .description = "margin around the particles' bounding box; empty: kernel support 2h",
       .min = 0});
    v(&ParticleResampleParams::support_threshold,
      {.key = "support_threshold",
       .description = "nodes with colour field sum_j V_j W_j below this get mask 0 and "
                      "empty_value",
       .min = 0,
       .max = 1});
    v(&ParticleResampleParams::particle_spacing,
      {.key = "particle_spacing",
       .unit = "m",
       .description = "typical particle distance s; empty: median (m/rho)^(1/d), or median "
                      "nearest-neighbour distance without mass and density",
       .min = 0,
       .minExclusive = true});
    v(&ParticleResampleParams::particle_volume,
      {.key = "particle_volume",
       .unit = "m^d",
       .description = "volume V_j of every particle; empty: mass/density, or else s^d",
       .min = 0,
       .minExclusive = true});
    v(&ParticleResampleParams::mass_array,
      {.key = "mass_array", .description = "particle array with masses (kg)"});
    v(&ParticleResampleParams::density_array,
      {.key = "density_array", .description = "particle array with densities (kg/m^d)"});
    v(&ParticleResampleParams::arrays,
      {.key = "arrays", .description = "comma-separated particle arrays to resample; empty: all"});
    v(&ParticleResampleParams::empty_value,
      {.key = "empty_value",
       .description = "value written at unsupported nodes (mask 0); empty: NaN"});
    v(&ParticleResampleParams::dimension,
      {.key = "dimension",
       .description = "2 or 3; 0: 2 when all particles have the same z, else 3",
       .min = 0,
       .max = 3});
    v(&ParticleResampleParams::max_memory_mb,
      {.key = "max_memory_mb",
       .unit = "MB",
       .description = "largest memory the grid's fields may take",
       .min = 1,
       .max = 1e7});
  }
};

/// Range and choice checks of every key plus dimension in {0, 2, 3}. Throws ParamError.
void validateResampleParams(const ParticleResampleParams& params);

/// "a, b ,c" -> {"a", "b", "c"}; empty entries are dropped.
std::vector<std::string> splitArrayList(const std::string& list);

}  // namespace fluidviz::resample
