#pragma once
// Scene-facing parameters of the SPH solver, in physical units (m, s, kg).
//
// Two models (see SphSolver.h for the equations and references):
//   "A"  Mueller, Charypar & Gross 2003: density by summation (poly6), p = k (rho - rho0) with
//        k = c0^2 (clamped at 0), symmetric pressure force (spiky), viscosity by the viscosity
//        kernel's Laplacian, optional colour-field surface tension, reflecting box walls that
//        also carry boundary particles (density and mirrored pressure, Akinci et al. 2012).
//   "B"  weakly compressible SPH (Monaghan 1992, 1994; Morris et al. 1997): density by the
//        continuity equation, Tait equation of state, Monaghan's symmetric pressure gradient,
//        Morris laminar viscosity, Monaghan artificial viscosity, XSPH, optional cohesion,
//        walls made of boundary particles with Lennard-Jones-type repulsion (Monaghan 1994)
//        and, by default, the wall pressure of Adami et al. (2012).
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

/// An axis-aligned box (a block of fluid or a solid obstacle).
struct SphBoxParams {
  std::array<double, 3> lower{0.0, 0.0, 0.0};  ///< m, lower corner (z ignored in 2D)
  std::array<double, 3> upper{0.0, 0.0, 0.0};  ///< m, upper corner, > lower on used axes

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
  std::array<double, 2> center{0.0, 0.0};  ///< m, axis position (x, y); inside the domain
  double radius = 0.0;                     ///< m, >= 2 particle spacings
  double angular_velocity = 0.0;           ///< rad/s, counter-clockwise (about +z) positive

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
  std::string x_min = "wall";  ///< side x = domain_lower[0]
  std::string x_max = "wall";  ///< side x = domain_upper[0]
  std::string y_min = "wall";  ///< side y = domain_lower[1]
  std::string y_max = "wall";  ///< side y = domain_upper[1]
  std::string z_min = "wall";  ///< side z = domain_lower[2] (3D only)
  std::string z_max = "wall";  ///< side z = domain_upper[2] (3D only)

  template <class V>
  static void describe(V& v) {
    const std::vector<std::string> kinds{"wall", "open", "periodic"};
    const std::string d = "wall: solid (model A reflects, model B: boundary particles); open: "
                          "nothing (a particle leaving stops the run); periodic: wraps to the "
                          "opposite side (which must be periodic too)";
    v(&SphWallsParams::x_min, {.key = "x_min", .description = d, .choices = kinds});
    v(&SphWallsParams::x_max, {.key = "x_max", .description = d, .choices = kinds});
    v(&SphWallsParams::y_min, {.key = "y_min", .description = d, .choices = kinds});
    v(&SphWallsParams::y_max, {.key = "y_max", .description = d, .choices = kinds});
    v(&SphWallsParams::z_min, {.key = "z_min", .description = d + " (3D only)", .choices = kinds});
    v(&SphWallsParams::z_max, {.key = "z_max", .description = d + " (3D only)", .choices = kinds});
  }
};

struct SphParams {
  int dimension = 2;                    ///< 2 or 3
  std::string model = "B";              ///< "A" (Mueller 2003) or "B" (weakly compressible)
  std::string kernel = "cubic_spline";  ///< model B kernel: cubic_spline | wendland_c2
  double particle_spacing = 0.02;       ///< m, dx, > 0
  double smoothing_length_ratio = 1.3;  ///< h / dx, [1, 3]; support radius is 2h
  double rest_density = 1000.0;         ///< kg/m^3, rho0, > 0
  double speed_of_sound = 20.0;         ///< m/s, c0 > 0; A: k = c0^2; B: Tait B = rho0 c0^2/gamma
  double eos_exponent = 7.0;            ///< Tait exponent gamma (model B), [1, 10]
  double viscosity = 0.0;               ///< m^2/s, kinematic viscosity nu >= 0 (mu = rho0 nu)
  double alpha = 0.0;                   ///< artificial viscosity alpha (model B), [0, 10]
  double beta = 0.0;                    ///< artificial viscosity beta (model B), [0, 10]
  double xsph_epsilon = 0.0;            ///< XSPH epsilon (model B), [0, 1]
  double density_diffusion = 0.1;       ///< delta-SPH delta (model B), [0, 1]; 0 = off
  double cohesion = 0.0;                ///< m^d/s^2, cohesion kappa (model B), >= 0
  double surface_tension = 0.0;         ///< N/m (3D) or N (2D), sigma (model A), >= 0
  double surface_threshold = 0.5;       ///< colour-gradient threshold |n| h (model A), > 0
  std::array<double, 3> gravity{0.0, -9.81, 0.0};  ///< m/s^2, body acceleration (z: 3D)
  std::array<double, 3> domain_lower{0.0, 0.0, 0.0};  ///< m, lower corner of the domain box
  std::array<double, 3> domain_upper{1.0, 1.0, 1.0};  ///< m, upper corner, > domain_lower
  SphWallsParams walls;                               ///< boundary type of each side
  double boundary_strength = 0.0;  ///< m^2/s^2, Lennard-Jones D >= 0; 0 = c0^2 / 40 (~ 5 g H)
  std::array<double, 2> boundary_exponents{12.0, 4.0};  ///< n1 > n2 >= 1 (Monaghan 1994)
  double boundary_range = 0.0;  ///< r0 / dx of the repulsion, [0, 2]; 0 = 1 (model B with
                                ///< wall_pressure none) or 0.7 (walls carry pressure: the
                                ///< repulsion is only a backstop)
  std::string wall_pressure = "adami2012";  ///< model B walls in the pressure term: adami2012 | none
  double restitution = 0.5;        ///< model A reflecting walls: kept normal speed, [0, 1]
  std::string initial_pressure = "hydrostatic";  ///< model B: hydrostatic | zero
  std::vector<SphBoxParams> fluid_blocks;        ///< boxes filled with fluid particles, >= 1
  std::vector<SphBoxParams> obstacles;           ///< solid boxes made of boundary particles
  std::vector<SphRollerParams> rollers;          ///< rotating rollers (boundary particles)
  double end_time = 0.0;                         ///< s, simulated time, > 0 (required)
  std::optional<double> time_step;  ///< s, fixed step > 0; unset = automatic (CFL/viscous/force)
  double cfl_factor = 0.25;         ///< dt <= cfl_factor h / (c + |v|max), (0, 1]
  double viscous_factor = 0.125;    ///< dt <= viscous_factor h^2 / nu, (0, 1]
  double force_factor = 0.25;       ///< dt <= force_factor sqrt(h / |a|max), (0, 1]
  double max_density_error = 0.1;   ///< |rho/rho0 - 1| (A: compression only) that stops, (0, 1]
  double min_step_fraction = 1e-3;  ///< stop when dt < this * (cfl_factor h / c0), (0, 1)
  int max_steps = 10'000'000;       ///< upper limit on time steps, >= 1

  template <class V>
  static void describe(V& v);
};

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
                        .description = "A: Mueller et al. 2003 (summation density, p = k (rho "
                                       "- rho0)); B: weakly compressible SPH (continuity, Tait, "
                                       "Monaghan 1994)",
                        .choices = {"A", "B"}});
  v(&SphParams::kernel, {.key = "kernel",
                         .description = "smoothing kernel of model B (model A always uses "
                                        "poly6/spiky/viscosity)",
                         .choices = {"cubic_spline", "wendland_c2"}});
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
    {.key = "eos_exponent", .description = "Tait exponent gamma (model B)", .min = 1, .max = 10});
  v(&SphParams::viscosity, {.key = "viscosity",
                            .unit = "m^2/s",
                            .description = "kinematic viscosity nu (laminar term)",
                            .min = 0});
  v(&SphParams::alpha, {.key = "alpha",
                        .description = "artificial viscosity alpha (model B, Monaghan 1992)",
                        .min = 0,
                        .max = 10});
  v(&SphParams::beta, {.key = "beta",
                       .description = "artificial viscosity beta (model B)",
                       .min = 0,
                       .max = 10});
  v(&SphParams::xsph_epsilon, {.key = "xsph_epsilon",
                               .description = "XSPH velocity smoothing epsilon (model B)",
                               .min = 0,
                               .max = 1});
  v(&SphParams::density_diffusion,
    {.key = "density_diffusion",
     .description = "delta-SPH density diffusion delta (model B, Molteni & Colagrossi 2009 with "
                    "hydrostatic correction); removes pressure noise; 0 = off",
     .min = 0,
     .max = 1});
  v(&SphParams::cohesion, {.key = "cohesion",
                           .unit = "m^d/s^2",
                           .description = "cohesion kappa (model B, Becker & Teschner 2007)",
                           .min = 0});
  v(&SphParams::surface_tension,
    {.key = "surface_tension",
     .unit = "N/m",
     .description = "colour-field surface tension sigma (model A; N in 2D)",
     .min = 0});
  v(&SphParams::surface_threshold,
    {.key = "surface_threshold",
     .description = "surface tension acts where |grad colour| h exceeds this (model A)",
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
     .description = "Lennard-Jones cut-off r0 / particle_spacing (0 = 1 for model B with "
                    "wall_pressure none; 0.7 otherwise, where the wall pressure holds the fluid "
                    "and the repulsion only stops penetration)",
     .min = 0,
     .max = 2});
  v(&SphParams::wall_pressure,
    {.key = "wall_pressure",
     .description = "model B: adami2012 = boundary particles carry the pressure extrapolated "
                    "from the fluid (Adami et al. 2012; accurate hydrostatics at walls); none = "
                    "Lennard-Jones repulsion only (Monaghan 1994)",
     .choices = {"adami2012", "none"}});
  v(&SphParams::restitution,
    {.key = "restitution",
     .description = "model A reflecting walls: fraction of normal speed kept",
     .min = 0,
     .max = 1});
  v(&SphParams::initial_pressure,
    {.key = "initial_pressure",
     .description = "model B initial density: hydrostatic (each block its own column) or zero",
     .choices = {"hydrostatic", "zero"}});
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
     .description = "relative density error |rho/rho0 - 1| that stops the run (model A: "
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
