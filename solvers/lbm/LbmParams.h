#pragma once
// Scene-facing parameters of the Lattice-Boltzmann solver, in PHYSICAL units (m, s, kg).
// UnitConversion.h turns them into lattice units and rejects combinations that would be
// unstable or inaccurate, naming the parameter to change.
//
// Geometry: the box [0, Lx] x [0, Ly] is covered by nx x ny cells of size dx = Lx / resolution;
// nodes sit at cell centres ((i + 1/2) dx, (j + 1/2) dx), so halfway bounce-back puts the walls
// exactly on the box edges x = 0, x = nx dx (= Lx) and y = 0, y = ny dx (= Ly up to the rounding
// of ny = round(Ly / Lx * resolution)).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"

namespace fluidviz::lbm {

/// One side of the box.
struct WallParams {
  /// "wall": no-slip wall at rest; "moving_wall": no-slip wall sliding along itself with
  /// `velocity` (Ladd 1994 moving bounce-back); "periodic": flow leaving here enters at the
  /// opposite side (the opposite side must be periodic too).
  std::string type = "wall";
  /// m/s, velocity of a moving_wall. Only the tangential component may be non-zero (a wall does
  /// not move through the box): x component for y_min/y_max, y component for x_min/x_max.
  std::array<double, 2> velocity{0.0, 0.0};

  template <class V>
  static void describe(V& v) {
    v(&WallParams::type, {.key = "type",
                          .description = "wall: no-slip at rest; moving_wall: no-slip, slides "
                                         "along itself with `velocity`; periodic: wraps to the "
                                         "opposite side (which must be periodic too)",
                          .choices = {"wall", "moving_wall", "periodic"}});
    v(&WallParams::velocity, {.key = "velocity",
                              .unit = "m/s",
                              .description = "velocity of a moving_wall; only the component "
                                             "along the wall may be non-zero"});
  }
};

/// The four sides of the box.
struct WallsParams {
  WallParams x_min;  ///< side x = 0
  WallParams x_max;  ///< side x = Lx
  WallParams y_min;  ///< side y = 0
  WallParams y_max;  ///< side y = Ly (the lid of a lid-driven cavity)

  template <class V>
  static void describe(V& v) {
    v(&WallsParams::x_min, {.key = "x_min", .description = "side x = 0"});
    v(&WallsParams::x_max, {.key = "x_max", .description = "side x = Lx"});
    v(&WallsParams::y_min, {.key = "y_min", .description = "side y = 0"});
    v(&WallsParams::y_max, {.key = "y_max", .description = "side y = Ly"});
  }
};

/// A solid disc turning about its fixed centre (a roller of an N-roll mill).
struct RollerParams {
  std::array<double, 2> center{0.0, 0.0};  ///< m, centre; the disc must lie inside the box
  double radius = 0.0;                     ///< m, > 0 (and at least 2 cells)
  double angular_velocity = 0.0;           ///< rad/s, counter-clockwise positive

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
       .description = "rotation rate, counter-clockwise positive"});
  }
};

struct LbmParams {
  std::string lattice = "D2Q9";                 ///< velocity set
  std::string collision = "bgk";                ///< collision operator (BGK single relaxation time)
  std::array<double, 2> domain_size{1.0, 1.0};  ///< m, box [0, Lx] x [0, Ly]; each > 0
  int resolution = 128;  ///< lattice nodes along x, [8, 8192]; ny = round(Ly / Lx * resolution)
  std::optional<double> viscosity;  ///< m^2/s, kinematic viscosity > 0 (exactly one of
                                    ///< viscosity and reynolds)
  std::optional<double> reynolds;   ///< Re = U_ref L_ref / nu > 0; U_ref = fastest wall speed
  double reference_length = 0.0;    ///< m, L_ref of the Reynolds number, >= 0; 0 = Lx
  double lattice_velocity = 0.05;   ///< lattice speed of the fastest wall, (0, 0.4]; sets
                                    ///< dt = lattice_velocity dx / U_ref
  std::optional<double> time_step;  ///< s, > 0; required (and only allowed) when nothing moves
  double density = 1000.0;          ///< kg/m^3, reference density (lattice density 1), > 0
  std::array<double, 2> body_force{0.0, 0.0};  ///< m/s^2, uniform acceleration (Guo forcing)
  WallsParams walls;                           ///< the four sides of the box
  std::vector<RollerParams> rollers;           ///< rotating solid discs inside the box
  double end_time = 0.0;                       ///< s, simulated time, > 0 (required)
  int max_steps = 10'000'000;                  ///< upper limit on time steps, >= 1
  double steady_tolerance = 0.0;  ///< >= 0; stop when max |u_new - u_old| / max |u| between
                                  ///< two checks falls below it; 0 = run to end_time
  int check_interval = 500;       ///< steps between stability / steady-state checks, [1, 1e6]

  template <class V>
  static void describe(V& v) {
    v(&LbmParams::lattice,
      {.key = "lattice", .description = "lattice velocity set", .choices = {"D2Q9"}});
    v(&LbmParams::collision,
      {.key = "collision",
       .description = "collision operator: bgk = single relaxation time (Qian et al. 1992)",
       .choices = {"bgk"}});
    v(&LbmParams::domain_size,
      {.key = "domain_size",
       .unit = "m",
       .description = "box size [Lx, Ly]; walls at x = 0, Lx and y = 0, Ly",
       .min = 0,
       .minExclusive = true});
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
                                            "fastest wall or roller surface speed (give this or "
                                            "viscosity)",
                             .min = 0,
                             .minExclusive = true});
    v(&LbmParams::reference_length, {.key = "reference_length",
                                     .unit = "m",
                                     .description = "length L_ref of the Reynolds number; 0 = Lx",
                                     .min = 0});
    v(&LbmParams::lattice_velocity,
      {.key = "lattice_velocity",
       .description = "lattice speed of the fastest wall (sets dt = lattice_velocity dx / U_ref); "
                      "lower is more accurate (Mach error ~ u^2) and slower (cost ~ 1/u)",
       .min = 0,
       .max = 0.4,
       .minExclusive = true});
    v(&LbmParams::time_step, {.key = "time_step",
                              .unit = "s",
                              .description = "time step when no wall or roller moves (otherwise "
                                             "it follows from lattice_velocity)",
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
    v(&LbmParams::walls, {.key = "walls", .description = "boundary of each side of the box"});
    v(&LbmParams::rollers,
      {.key = "rollers", .description = "rotating solid discs (moving bounce-back, Ladd 1994)"});
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

/// Fastest wall speed U_ref (m/s): |velocity| of moving walls, |omega| radius of rollers.
double referenceVelocity(const LbmParams& p);

}  // namespace fluidviz::lbm
