#pragma once
// Scene-facing parameters of the SPH solver, in physical units (m, s, kg).
//
// Two models (see SphSolver.h for the equations and references), named by SphModel:
//   muller2003 (scene alias "A"): Mueller, Charypar & Gross 2003: density by summation (poly6),
//        p = k (rho - rho0) with k = c0^2 (clamped at 0), symmetric pressure force (spiky),
//        viscosity by the viscosity kernel's Laplacian, optional colour-field surface tension,
//        reflecting box walls that also carry boundary particles (density and mirrored
//        pressure, Akinci et al. 2012).
//   weakly_compressible (scene alias "B"): weakly compressible SPH (Monaghan 1992, 1994;
//        Morris et al. 1997): density by the continuity equation, Tait equation of state,
//        Monaghan's symmetric pressure gradient, Morris laminar viscosity, Monaghan artificial
//        viscosity, XSPH, optional cohesion, walls made of boundary particles with
//        Lennard-Jones-type repulsion (Monaghan 1994) and, by default, the wall pressure of
//        Adami et al. (2012).
//
// Geometry: the fluid lives in the box [domain_lower, domain_upper]. Each side is a wall, open
// (particles leaving through it stop the run) or periodic (in pairs). In 2D only x and y are
// used (z components are ignored). Particles are laid on a lattice of spacing dx =
// particle_spacing: fluid at block_lower + (i + 1/2) dx; wall particles continue the lattice
// outside the box, so a wall sits half a spacing from its first fluid layer.
// Every kernel has compact support 2h, h = smoothing_length_ratio dx.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"

namespace fluidviz::sph {

/// The SPH model; "A" and "B" are the names older scenes used and are still read.
enum class SphModel { muller2003, weakly_compressible };
constexpr std::array<Choice<SphModel>, 2> paramChoices(SphModel) {
  return {{{SphModel::muller2003, "muller2003", "A"},
           {SphModel::weakly_compressible, "weakly_compressible", "B"}}};
}

/// Smoothing kernel of the weakly compressible model.
enum class SphKernel { cubic_spline, wendland_c2 };
constexpr std::array<Choice<SphKernel>, 2> paramChoices(SphKernel) {
  return {{{SphKernel::cubic_spline, "cubic_spline"}, {SphKernel::wendland_c2, "wendland_c2"}}};
}

/// Boundary type of one side of the domain box.
enum class SphSide { wall, open, periodic };
constexpr std::array<Choice<SphSide>, 3> paramChoices(SphSide) {
  return {{{SphSide::wall, "wall"}, {SphSide::open, "open"}, {SphSide::periodic, "periodic"}}};
}

/// How walls of the weakly compressible model enter the pressure term.
enum class WallPressure { adami2012, none };
constexpr std::array<Choice<WallPressure>, 2> paramChoices(WallPressure) {
  return {{{WallPressure::adami2012, "adami2012"}, {WallPressure::none, "none"}}};
}

/// Initial density of the weakly compressible model.
enum class InitialPressure { hydrostatic, zero };
constexpr std::array<Choice<InitialPressure>, 2> paramChoices(InitialPressure) {
  return {{{InitialPressure::hydrostatic, "hydrostatic"}, {InitialPressure::zero, "zero"}}};
}

/// An axis-aligned box (a block of fluid or a solid obstacle).
struct SphBoxParams {
  std::array<double, 3> lower{0.0, 0.0, 0.0};  ///< z ignored in 2D
  std::array<double, 3> upper{0.0, 0.0, 0.0};

  template <class V>
  static void describe(V& v) {
    v(&SphBoxParams::lower,
      {.key = "lower", .unit = "m", .description = "lower corner", .required = true});
    v(&SphBoxParams::upper, {.key = "upper",
                             .unit = "m",
                             .description = "upper corner (greater than lower on every axis used)",
                             .required = true});
  }
};

/// A rigid roller: a disc in 2D, a cylinder along z spanning the domain in 3D, turning about
/// its fixed axis. Made of boundary particles (layers inside its surface).
struct SphRollerParams {
  std::array<double, 2> center{0.0, 0.0};
  double radius = 0.0;
  double angular_velocity = 0.0;  ///< about +z

  template <class V>
  static void describe(V& v) {
    v(&SphRollerParams::center, {.key = "center",
                                 .unit = "m",
                                 .description = "axis position (x, y); the roller must lie "
                                                "inside the domain",
                                 .required = true});
    v(&SphRollerParams::radius, {.key = "radius",
                                 .unit = "m",
                                 .description = "roller radius (at least 2 particle spacings)",
                                 .min = 0,
                                 .minExclusive = true,
                                 .required = true});
    v(&SphRollerParams::angular_velocity, {.key = "angular_velocity",
                                           .unit = "rad/s",
                                           .description = "rotation rate, counter-clockwise "
                                                          "positive"});
  }
};

/// Boundary type of each side of the domain box.
struct SphWallsParams {
  SphSide x_min = SphSide::wall;  ///< side x = domain_lower[0]
  SphSide x_max = SphSide::wall;  ///< side x = domain_upper[0]
  SphSide y_min = SphSide::wall;  ///< side y = domain_lower[1]
  SphSide y_max = SphSide::wall;  ///< side y = domain_upper[1]
  SphSide z_min = SphSide::wall;  ///< side z = domain_lower[2] (3D only)
  SphSide z_max = SphSide::wall;  ///< side z = domain_upper[2] (3D only)

  template <class V>
  static void describe(V& v) {
    const std::string d = "wall: solid (muller2003 reflects, weakly_compressible: boundary "
                          "particles); open: "
                          "nothing (a particle leaving stops the run); periodic: wraps to the "
                          "opposite side (which must be periodic too)";
    v(&SphWallsParams::x_min, {.key = "x_min", .description = d});
    v(&SphWallsParams::x_max, {.key = "x_max", .description = d});
    v(&SphWallsParams::y_min, {.key = "y_min", .description = d});
    v(&SphWallsParams::y_max, {.key = "y_max", .description = d});
    v(&SphWallsParams::z_min, {.key = "z_min", .description = d + " (3D only)"});
    v(&SphWallsParams::z_max, {.key = "z_max", .description = d + " (3D only)"});
  }
};

// Units, ranges and meanings of the members: their describe() declarations below.
struct SphParams {
  int dimension = 2;
  SphModel model = SphModel::weakly_compressible;
  SphKernel kernel = SphKernel::cubic_spline;
  double particle_spacing = 0.02;       ///< dx
  double smoothing_length_ratio = 1.3;  ///< h / dx
  double rest_density = 1000.0;         ///< rho0
  double speed_of_sound = 20.0;  ///< c0; muller2003: k = c0^2; Tait B = rho0 c0^2 / gamma
  double eos_exponent = 7.0;
  double viscosity = 0.0;  ///< nu (mu = rho0 nu)
  double alpha = 0.0;
  double beta = 0.0;
  double xsph_epsilon = 0.0;
  double density_diffusion = 0.1;
  double cohesion = 0.0;
  double surface_tension = 0.0;  ///< sigma (N/m in 3D, N in 2D)
  double surface_threshold = 0.5;
  std::array<double, 3> gravity{0.0, -9.81, 0.0};  ///< z: 3D only
  std::array<double, 3> domain_lower{0.0, 0.0, 0.0};
  std::array<double, 3> domain_upper{1.0, 1.0, 1.0};
  SphWallsParams walls;
  double boundary_strength = 0.0;  ///< Lennard-Jones D; 0 = c0^2 / 40 (~ 5 g H)
  std::array<double, 2> boundary_exponents{12.0, 4.0};  ///< n1 > n2 (Monaghan 1994)
  double boundary_range = 0.0;  ///< r0 / dx of the repulsion; 0 = a default (boundaryRange)
  WallPressure wall_pressure = WallPressure::adami2012;
  double restitution = 0.5;
  InitialPressure initial_pressure = InitialPressure::hydrostatic;
  std::vector<SphBoxParams> fluid_blocks;  ///< at least one
  std::vector<SphBoxParams> obstacles;
  std::vector<SphRollerParams> rollers;
  double end_time = 0.0;
  std::optional<double> time_step;  ///< unset = automatic (CFL/viscous/force)
  double cfl_factor = 0.25;         ///< dt <= cfl_factor h / (c + |v|max)
  double viscous_factor = 0.125;    ///< dt <= viscous_factor h^2 / nu
  double force_factor = 0.25;       ///< dt <= force_factor sqrt(h / |a|max)
  double max_density_error = 0.1;
  double min_step_fraction = 1e-3;  ///< stop when dt < this * (cfl_factor h / c0)
  int max_steps = 10'000'000;

  template <class V>
  static void describe(V& v);
};

/// Boundary type of side 0..5 (x_min, x_max, y_min, y_max, z_min, z_max).
inline SphSide sideType(const SphWallsParams& w, int side) {
  const SphSide s[6] = {w.x_min, w.x_max, w.y_min, w.y_max, w.z_min, w.z_max};
  return s[side];
}

/// Checks every value and combination (ranges, choices, periodic pairs, periodic lengths, blocks
/// and rollers inside the domain, model-specific terms). Throws ParamError with the key
/// relative to SphParams ("fluid_blocks[0].upper", "walls.x_max") and what to change.
void validateSphParams(const SphParams& p);

/// Lennard-Jones strength D actually used (boundary_strength or its default c0^2 / 40).
double boundaryStrength(const SphParams& p);
/// Lennard-Jones cut-off r0 (m) actually used (boundary_range dx or its default).
double boundaryRange(const SphParams& p);

template <class V>
void SphParams::describe(V& v) {
  v(&SphParams::dimension,
    {.key = "dimension", .description = "2 or 3 space dimensions", .min = 2, .max = 3});
  v(&SphParams::model, {.key = "model",
                        .description = "muller2003 (alias A): Mueller et al. 2003 (summation "
                                       "density, p = k (rho - rho0)); weakly_compressible (alias "
                                       "B): weakly compressible SPH (continuity, Tait, Monaghan "
                                       "1994)"});
  v(&SphParams::kernel, {.key = "kernel",
                         .description = "smoothing kernel of model weakly_compressible (model "
                                        "muller2003 always uses poly6/spiky/viscosity)"});
  v(&SphParams::particle_spacing,
    {.key = "particle_spacing",
     .unit = "m",
     .description = "initial particle distance dx; error ~ dx^2, cost ~ dx^-(d+1)",
     .min = 0,
     .minExclusive = true});
  v(&SphParams::smoothing_length_ratio,
    {.key = "smoothing_length_ratio",
     .description = "h / dx (support radius 2h); more neighbours: smoother, costlier",
     .min = 1,
     .max = 3});
  v(&SphParams::rest_density, {.key = "rest_density",
                               .unit = "kg/m^3",
                               .description = "rest density rho0",
                               .min = 0,
                               .minExclusive = true});
  v(&SphParams::speed_of_sound,
    {.key = "speed_of_sound",
     .unit = "m/s",
     .description = "numerical sound speed c0 (EOS stiffness); >= 10 |v|max keeps density "
                    "errors near 1%; dt ~ 1/c0",
     .min = 0,
     .minExclusive = true});
  v(&SphParams::eos_exponent,
    {.key = "eos_exponent",
     .description = "Tait exponent gamma (model weakly_compressible)",
     .min = 1,
     .max = 10});
  v(&SphParams::viscosity, {.key = "viscosity",
                            .unit = "m^2/s",
                            .description = "kinematic viscosity nu (laminar term)",
                            .min = 0});
  v(&SphParams::alpha, {.key = "alpha",
                        .description = "artificial viscosity alpha (model weakly_compressible, "
                                       "Monaghan 1992)",
                        .min = 0,
                        .max = 10});
  v(&SphParams::beta, {.key = "beta",
                       .description = "artificial viscosity beta (model weakly_compressible)",
                       .min = 0,
                       .max = 10});
  v(&SphParams::xsph_epsilon, {.key = "xsph_epsilon",
                               .description = "XSPH velocity smoothing epsilon (model "
                                              "weakly_compressible)",
                               .min = 0,
                               .max = 1});
  v(&SphParams::density_diffusion,
    {.key = "density_diffusion",
     .description = "delta-SPH density diffusion delta (model weakly_compressible, Molteni & "
                    "Colagrossi 2009 with "
                    "hydrostatic correction); removes pressure noise; 0 = off",
     .min = 0,
     .max = 1});
  v(&SphParams::cohesion, {.key = "cohesion",
                           .unit = "m^d/s^2",
                           .description = "cohesion kappa (model weakly_compressible, Becker & "
                                          "Teschner 2007)",
                           .min = 0});
  v(&SphParams::surface_tension,
    {.key = "surface_tension",
     .unit = "N/m",
     .description = "colour-field surface tension sigma (model muller2003; N in 2D)",
     .min = 0});
  v(&SphParams::surface_threshold,
    {.key = "surface_threshold",
     .description = "surface tension acts where |grad colour| h exceeds this (model muller2003)",
     .min = 0,
     .minExclusive = true});
  v(&SphParams::gravity,
    {.key = "gravity", .unit = "m/s^2", .description = "body acceleration (gravity, pressure "
                                                       "gradient / rho)"});
  v(&SphParams::domain_lower,
    {.key = "domain_lower", .unit = "m", .description = "lower corner of the domain box"});
  v(&SphParams::domain_upper,
    {.key = "domain_upper", .unit = "m", .description = "upper corner of the domain box"});
  v(&SphParams::walls, {.key = "walls", .description = "boundary type of each side"});
  v(&SphParams::boundary_strength,
    {.key = "boundary_strength",
     .unit = "m^2/s^2",
     .description = "Lennard-Jones boundary strength D (0 = c0^2 / 40, about 5 g H)",
     .min = 0});
  v(&SphParams::boundary_exponents,
    {.key = "boundary_exponents",
     .description = "Lennard-Jones exponents [n1, n2], n1 > n2 >= 1",
     .min = 1,
     .max = 24});
  v(&SphParams::boundary_range,
    {.key = "boundary_range",
     .description = "Lennard-Jones cut-off r0 / particle_spacing (0 = 1 for model "
                    "weakly_compressible with "
                    "wall_pressure none; 0.7 otherwise, where the wall pressure holds the fluid "
                    "and the repulsion only stops penetration)",
     .min = 0,
     .max = 2});
  v(&SphParams::wall_pressure,
    {.key = "wall_pressure",
     .description = "model weakly_compressible: adami2012 = boundary particles carry the "
                    "pressure extrapolated "
                    "from the fluid (Adami et al. 2012; accurate hydrostatics at walls); none = "
                    "Lennard-Jones repulsion only (Monaghan 1994)"});
  v(&SphParams::restitution,
    {.key = "restitution",
     .description = "model muller2003 reflecting walls: fraction of normal speed kept",
     .min = 0,
     .max = 1});
  v(&SphParams::initial_pressure,
    {.key = "initial_pressure",
     .description = "model weakly_compressible initial density: hydrostatic (each block its "
                    "own column) or zero"});
  v(&SphParams::fluid_blocks,
    {.key = "fluid_blocks", .description = "boxes filled with fluid particles (at least one)"});
  v(&SphParams::obstacles,
    {.key = "obstacles", .description = "solid boxes made of boundary particles"});
  v(&SphParams::rollers, {.key = "rollers", .description = "rotating rollers"});
  v(&SphParams::end_time, {.key = "end_time",
                           .unit = "s",
                           .description = "simulated time",
                           .min = 0,
                           .minExclusive = true,
                           .required = true});
  v(&SphParams::time_step,
    {.key = "time_step",
     .unit = "s",
     .description = "fixed time step; unset = automatic; a step past the stable limit is "
                    "reported in warnings",
     .min = 0,
     .minExclusive = true});
  v(&SphParams::cfl_factor, {.key = "cfl_factor",
                             .description = "dt <= cfl_factor h / (c + |v|max)",
                             .min = 0,
                             .max = 1,
                             .minExclusive = true});
  v(&SphParams::viscous_factor, {.key = "viscous_factor",
                                 .description = "dt <= viscous_factor h^2 / nu",
                                 .min = 0,
                                 .max = 1,
                                 .minExclusive = true});
  v(&SphParams::force_factor, {.key = "force_factor",
                               .description = "dt <= force_factor sqrt(h / |a|max)",
                               .min = 0,
                               .max = 1,
                               .minExclusive = true});
  v(&SphParams::max_density_error,
    {.key = "max_density_error",
     .description = "relative density error |rho/rho0 - 1| that stops the run (model muller2003: "
                    "compression only)",
     .min = 0,
     .max = 1,
     .minExclusive = true});
  v(&SphParams::min_step_fraction,
    {.key = "min_step_fraction",
     .description = "stop when the automatic dt falls below this fraction of cfl_factor h / c0",
     .min = 0,
     .max = 1,
     .minExclusive = true});
  v(&SphParams::max_steps,
    {.key = "max_steps", .description = "upper limit on time steps", .min = 1});
}

}  // namespace fluidviz::sph
