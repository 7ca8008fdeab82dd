#pragma once
// Scene-facing parameters of the Lattice-Boltzmann solver, in PHYSICAL units (m, s, kg).
// UnitConversion.h turns them into lattice units and rejects combinations that would be
// unstable or inaccurate, naming the parameter to change.
//
// Geometry: the box [0, Lx] x [0, Ly] is covered by nx x ny cells of size dx = Lx / resolution;
// nodes sit at cell centres ((i + 1/2) dx, (j + 1/2) dx), so halfway bounce-back puts the walls
// exactly on the box edges x = 0, x = nx dx (= Lx) and y = 0, y = ny dx (= Ly up to the rounding
// of ny = round(Ly / Lx * resolution)).
//
// 3D (lattice D3Q19): the box gets a depth Lz = domain_depth along z (nz = round(Lz / Lx *
// resolution) nodes) and two more sides, walls.z_min and walls.z_max. The keys of 2D scenes keep
// their meaning and their two components (domain_size, body_force, wall velocity, roller centre
// are [x, y]); the z components are separate keys (domain_depth, body_force_z, velocity_z), so that
// every 2D scene reads unchanged. Rollers become cylinders along z through the whole depth.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"

namespace fluidviz::lbm {

/// Boundary rule of one side (Ladd 1994 moving bounce-back; Zou & He 1997 for the open sides;
/// pressure_outlet and pressure_inlet are the same rule under two names).
enum class WallType {
  wall, moving_wall, periodic, velocity_inlet, pressure_outlet, pressure_inlet
};
constexpr std::array<Choice<WallType>, 6> paramChoices(WallType) {
  return {{{WallType::wall, "wall"},
           {WallType::moving_wall, "moving_wall"},
           {WallType::periodic, "periodic"},
           {WallType::velocity_inlet, "velocity_inlet"},
           {WallType::pressure_outlet, "pressure_outlet"},
           {WallType::pressure_inlet, "pressure_inlet"}}};
}

/// Velocity profile across a velocity_inlet: the same velocity at every node, or the
/// fully developed channel (Poiseuille) profile between the sides that meet the inlet.
enum class InletProfile { uniform, parabolic };
constexpr std::array<Choice<InletProfile>, 2> paramChoices(InletProfile) {
  return {{{InletProfile::uniform, "uniform"}, {InletProfile::parabolic, "parabolic"}}};
}

/// Bounce-back of a curved roller surface: first order (staircase) or Bouzidi et al. 2001.
enum class RollerBoundary { staircase, interpolated };
constexpr std::array<Choice<RollerBoundary>, 2> paramChoices(RollerBoundary) {
  return {{{RollerBoundary::staircase, "staircase"},
           {RollerBoundary::interpolated, "interpolated"}}};
}

enum class Lattice { D2Q9, D3Q19 };
constexpr std::array<Choice<Lattice>, 2> paramChoices(Lattice) {
  return {{{Lattice::D2Q9, "D2Q9"}, {Lattice::D3Q19, "D3Q19"}}};
}

enum class Collision { bgk, trt };
constexpr std::array<Choice<Collision>, 2> paramChoices(Collision) {
  return {{{Collision::bgk, "bgk"}, {Collision::trt, "trt"}}};
}

/// Floating-point type of the populations.
enum class Precision { float64, float32 };
constexpr std::array<Choice<Precision>, 2> paramChoices(Precision) {
  return {{{Precision::float64, "double"}, {Precision::float32, "float"}}};
}

/// Initial state: at rest, or the decaying Taylor-Green vortex array u = U0 sin(2 pi x/Lx)
/// cos(2 pi y/Ly), v = -U0 Ly/Lx cos(2 pi x/Lx) sin(2 pi y/Ly) with its pressure field, or a
/// sketched field (issue 20): the pipeline computes it from the scene's strokes (filters/sketch,
/// pipeline/LbmSketchStart.h) and hands it to LbmSolver::initialise; the solver starts at rest.
enum class InitialFlow { rest, taylor_green, sketch };
constexpr std::array<Choice<InitialFlow>, 3> paramChoices(InitialFlow) {
  return {{{InitialFlow::rest, "rest"},
           {InitialFlow::taylor_green, "taylor_green"},
           {InitialFlow::sketch, "sketch"}}};
}

/// One side of the box.
struct WallParams {
  WallType type = WallType::wall;
  /// velocity of a moving_wall or of a velocity_inlet (any direction; normally into the box)
  std::array<double, 2> velocity{0.0, 0.0};
  double velocity_z = 0.0;
  /// in lattice units rho = 1 + pressure dt^2 / (cs2 density dx^2)
  double pressure = 0.0;
  InletProfile profile = InletProfile::uniform;
  double ramp_time = 0.0;  ///< s over which a velocity_inlet starts; 0: at full speed

  template <class V>
  static void describe(V& v) {
    v(&WallParams::type,
      {.key = "type",
       .description = "wall: no-slip at rest (halfway bounce-back); moving_wall: no-slip, slides "
                      "along itself with `velocity`; periodic: wraps to the opposite side (which "
                      "must be periodic too); velocity_inlet: fluid enters with `velocity` (Zou & "
                      "He 1997); pressure_outlet, pressure_inlet: pressure held at `pressure` "
                      "(Zou & He 1997). Open sides act on the first node layer, half a cell "
                      "inside the side"});
    v(&WallParams::velocity, {.key = "velocity",
                              .unit = "m/s",
                              .description = "[x, y] velocity of a moving_wall (only the "
                                             "components along the wall may be non-zero) or of "
                                             "a velocity_inlet"});
    v(&WallParams::velocity_z,
      {.key = "velocity_z", .unit = "m/s", .description = "z component of velocity (3D only)"});
    v(&WallParams::pressure, {.key = "pressure",
                              .unit = "Pa",
                              .description = "gauge pressure of a pressure_outlet / "
                                             "pressure_inlet, relative to the pressure at the "
                                             "reference density lbm.density"});
    v(&WallParams::profile,
      {.key = "profile",
       .description = "velocity_inlet only: uniform (`velocity` at every node) or parabolic "
                      "(`velocity` at the centre, falling to 0 at the two sides that meet the "
                      "inlet: 4 s (1 - s) across the side in 2D, 16 s (1 - s) t (1 - t) in 3D, as "
                      "the benchmarks of Schaefer & Turek 1996; its mean is 2/3 (2D) or 4/9 (3D) "
                      "of `velocity`)"});
    v(&WallParams::ramp_time,
      {.key = "ramp_time", .unit = "s",
       .description = "velocity_inlet only: the inlet speed rises from 0 as sin^2(pi t / (2 "
                      "ramp_time)) and is `velocity` from t = ramp_time on; 0: at full speed from "
                      "the start. A smooth start sends far weaker pressure waves through the box "
                      "than a sudden one, and the Zou-He sides reflect them rather than let them "
                      "out; a ramp of a few times the sound's crossing time (Lx / c_s, `fluidviz "
                      "check`) keeps them small",
       .min = 0});
  }
};

/// The sides of the box (four in 2D, six in 3D).
struct WallsParams {
  WallParams x_min;  ///< side x = 0
  WallParams x_max;  ///< side x = Lx
  WallParams y_min;  ///< side y = 0
  WallParams y_max;  ///< side y = Ly (the lid of a lid-driven cavity)
  WallParams z_min;  ///< side z = 0 (3D only)
  WallParams z_max;  ///< side z = Lz (3D only)

  template <class V>
  static void describe(V& v) {
    v(&WallsParams::x_min, {.key = "x_min", .description = "side x = 0"});
    v(&WallsParams::x_max, {.key = "x_max", .description = "side x = Lx"});
    v(&WallsParams::y_min, {.key = "y_min", .description = "side y = 0"});
    v(&WallsParams::y_max, {.key = "y_max", .description = "side y = Ly"});
    v(&WallsParams::z_min, {.key = "z_min", .description = "side z = 0 (3D only)"});
    v(&WallsParams::z_max, {.key = "z_max", .description = "side z = Lz (3D only)"});
  }
};

/// A solid disc turning about its fixed centre (a roller of an N-roll mill; with
/// angular_velocity 0 a fixed cylinder). In 3D a cylinder along z through the whole depth.
struct RollerParams {
  std::array<double, 2> center{0.0, 0.0};
  double radius = 0.0;
  double angular_velocity = 0.0;
  RollerBoundary boundary = RollerBoundary::staircase;

  template <class V>
  static void describe(V& v) {
    v(&RollerParams::center, {.key = "center",
                              .unit = "m",
                              .description = "centre of the roller; the disc must lie inside "
                                             "the box",
                              .required = true});
    v(&RollerParams::radius, {.key = "radius",
                              .unit = "m",
                              .description = "roller radius (at least 2 lattice cells)",
                              .min = 0,
                              .minExclusive = true,
                              .required = true});
    v(&RollerParams::angular_velocity,
      {.key = "angular_velocity",
       .unit = "rad/s",
       .description = "rotation rate, counter-clockwise positive (0: a fixed cylinder)"});
    v(&RollerParams::boundary,
      {.key = "boundary",
       .description = "staircase: halfway bounce-back on the nodes inside (first order for a "
                      "curved wall); interpolated: Bouzidi et al. 2001 interpolated bounce-back "
                      "at the true surface (second order)"});
  }
};

// Units, ranges and meanings of the members: their describe() declarations below.
struct LbmParams {
  Lattice lattice = Lattice::D2Q9;
  Collision collision = Collision::bgk;
  double trt_magic = 3.0 / 16.0;
  Precision precision = Precision::float64;
  std::array<double, 2> domain_size{1.0, 1.0};
  double domain_depth = 0.0;
  int resolution = 128;  ///< ny = round(Ly / Lx * resolution)
  std::optional<double> viscosity;  ///< exactly one of viscosity and reynolds
  std::optional<double> reynolds;
  double reference_length = 0.0;
  double lattice_velocity = 0.05;
  std::optional<double> time_step;  ///< required (and only allowed) when nothing moves
  double density = 1000.0;
  std::array<double, 2> body_force{0.0, 0.0};
  double body_force_z = 0.0;
  WallsParams walls;
  std::vector<RollerParams> rollers;
  InitialFlow initial_flow = InitialFlow::rest;
  double initial_speed = 0.0;
  double end_time = 0.0;
  int max_steps = 10'000'000;
  double steady_tolerance = 0.0;
  int check_interval = 500;

  template <class V>
  static void describe(V& v) {
    v(&LbmParams::lattice,
      {.key = "lattice",
       .description = "lattice velocity set: D2Q9 (2D) or D3Q19 (3D, needs domain_depth > 0)"});
    v(&LbmParams::collision,
      {.key = "collision",
       .description = "collision operator: bgk = single relaxation time (Qian et al. 1992); trt "
                      "= two relaxation times (Ginzburg et al. 2008): wall position independent "
                      "of the viscosity, more stable near tau = 1/2"});
    v(&LbmParams::trt_magic,
      {.key = "trt_magic",
       .description = "TRT magic parameter Lambda = (tau+ - 1/2)(tau- - 1/2): 3/16 puts "
                      "bounce-back walls exactly halfway (Poiseuille exact), 1/4 most stable, "
                      "1/12 least advection error",
       .min = 0,
       .max = 1,
       .minExclusive = true});
    v(&LbmParams::precision,
      {.key = "precision",
       .description = "floating-point type of the populations: float halves memory and "
                      "traffic (up to 2x faster; populations stored shifted by their weight, "
                      "Lehmann et al. 2022), double is exact to round-off"});
    v(&LbmParams::domain_size,
      {.key = "domain_size",
       .unit = "m",
       .description = "box size [Lx, Ly]; walls at x = 0, Lx and y = 0, Ly",
       .min = 0,
       .minExclusive = true});
    v(&LbmParams::domain_depth,
      {.key = "domain_depth",
       .unit = "m",
       .description = "depth Lz of a 3D box (lattice D3Q19), walls at z = 0, Lz; 0 for 2D",
       .min = 0});
    v(&LbmParams::resolution, {.key = "resolution",
                               .description = "lattice nodes along x (ny = round(Ly/Lx "
                                              "resolution)); accuracy ~ 1/resolution^2, cost "
                                              "~ resolution^3 to a fixed physical time",
                               .min = 8,
                               .max = 8192});
    v(&LbmParams::viscosity, {.key = "viscosity",
                              .unit = "m^2/s",
                              .description = "kinematic viscosity (give this or reynolds)",
                              .min = 0,
                              .minExclusive = true});
    v(&LbmParams::reynolds, {.key = "reynolds",
                             .description = "Reynolds number U_ref L_ref / nu with U_ref the "
                                            "fastest wall, roller surface, inlet or initial "
                                            "speed (give this or viscosity)",
                             .min = 0,
                             .minExclusive = true});
    v(&LbmParams::reference_length, {.key = "reference_length",
                                     .unit = "m",
                                     .description = "length L_ref of the Reynolds number; 0 = Lx",
                                     .min = 0});
    v(&LbmParams::lattice_velocity,
      {.key = "lattice_velocity",
       .description = "lattice speed of U_ref, the fastest wall, roller or mean inlet speed (sets "
                      "dt = lattice_velocity dx / U_ref); "
                      "lower is more accurate (Mach error ~ u^2) and slower (cost ~ 1/u)",
       .min = 0,
       .max = 0.4,
       .minExclusive = true});
    v(&LbmParams::time_step, {.key = "time_step",
                              .unit = "s",
                              .description = "time step when nothing moves (no moving wall, "
                                             "roller, inlet or initial flow; otherwise it "
                                             "follows from lattice_velocity)",
                              .min = 0,
                              .minExclusive = true});
    v(&LbmParams::density, {.key = "density",
                            .unit = "kg/m^3",
                            .description = "reference fluid density (lattice density 1)",
                            .min = 0,
                            .minExclusive = true});
    v(&LbmParams::body_force, {.key = "body_force",
                               .unit = "m/s^2",
                               .description = "uniform body acceleration, e.g. gravity or a "
                                              "pressure gradient / density (Guo et al. 2002)"});
    v(&LbmParams::body_force_z, {.key = "body_force_z",
                                 .unit = "m/s^2",
                                 .description = "z component of body_force (3D only)"});
    v(&LbmParams::walls, {.key = "walls", .description = "boundary of each side of the box"});
    v(&LbmParams::rollers,
      {.key = "rollers",
       .description = "rotating solid discs (moving bounce-back, Ladd 1994); cylinders along z "
                      "in 3D"});
    v(&LbmParams::initial_flow,
      {.key = "initial_flow",
       .description = "initial state: rest, or taylor_green (vortex array of speed "
                      "initial_speed, one period across the box; all sides periodic), or sketch "
                      "(the field of the strokes of lbm.sketch, extended by Gradient Vector "
                      "Flow; 2D)"});
    v(&LbmParams::initial_speed, {.key = "initial_speed",
                                  .unit = "m/s",
                                  .description = "amplitude U0 of the initial flow (counts as a "
                                                 "moving part for reynolds and lattice_velocity); "
                                                 "sketch: the sketched field's largest speed, "
                                                 "the field scaled to it (0: as drawn)",
                                  .min = 0});
    v(&LbmParams::end_time, {.key = "end_time",
                             .unit = "s",
                             .description = "simulated time",
                             .min = 0,
                             .minExclusive = true,
                             .required = true});
    v(&LbmParams::max_steps,
      {.key = "max_steps", .description = "upper limit on time steps", .min = 1});
    v(&LbmParams::steady_tolerance,
      {.key = "steady_tolerance",
       .description = "stop when max|u_new - u_old| / max|u| between two checks is below this; "
                      "0 = run to end_time",
       .min = 0});
    v(&LbmParams::check_interval,
      {.key = "check_interval",
       .description = "time steps between stability and steady-state checks",
       .min = 1,
       .max = 1e6});
  }
};

/// Checks every value and combination that does not need the lattice spacing (ranges, choices,
/// exactly one of viscosity / reynolds, paired periodic sides, rollers inside the box and not
/// overlapping, tangential wall velocities). Throws ParamError with the key relative to LbmParams
/// ("walls.x_min.type", "rollers[1]") and a message saying what is allowed.
void validateLbmParams(const LbmParams& p);

/// Reference speed U_ref (m/s) of the Reynolds number and of lattice_velocity: the fastest of
/// |velocity| of moving walls, the mean speed of velocity inlets (inletMeanFactor), |omega|
/// radius of rollers, initial_speed.
double referenceVelocity(const LbmParams& p);

/// Mean of a velocity inlet's profile over the side, relative to |velocity|: 1 (uniform), 2/3
/// (parabolic, 2D) or 4/9 (parabolic, 3D: the product of two parabolas).
double inletMeanFactor(const WallParams& w, bool threeD);

/// True for a 3D scene (lattice D3Q19).
inline bool is3D(const LbmParams& p) { return p.lattice == Lattice::D3Q19; }

}  // namespace fluidviz::lbm
