#pragma once
// Scene-facing parameters of the FHP lattice-gas solver (solver = "fhp"), in PHYSICAL units
// (m, s, kg), and their conversion to lattice units (FhpUnits).
//
// Geometry: the box [0, Lx] x [0, Ly] is covered by nx = resolution nodes along x (link length
// dx = Lx / nx) and ny rows (row spacing sqrt(3)/2 dx; ny = round(Ly / (sqrt(3)/2 dx)) rounded to
// a multiple of the block rows and of 2). Node (x, y) sits at ((x + 1/2 [y odd]) dx, y sqrt(3)/2
// dx). A wall side is a layer of solid nodes: the rows y = 0 and y = ny - 1, the columns x = 0
// and x = nx - 1.
//
// Units (Frisch et al. 1987, Complex Systems 1:649, sections 5-6): the averaged lattice-gas
// velocity u obeys d_t u + g(d) (u . grad) u = -grad P + nu(d) lap u, so v = g u obeys the
// Navier-Stokes equations with viscosity nu(d) in lattice time. The snapshots carry v, in m/s:
// v = g u dx / dt. The Reynolds number of a flow of lattice speed u on L links is therefore
// Re = g u L / nu; with the scene's Re the lattice speed of U_ref follows, and from it dt. The
// lattice speed is bounded (max_lattice_velocity: the Mach number u / c_s), so for a given
// lattice the largest reachable Re is g u_max L / nu.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"
#include "solvers/fhp/collision/CollisionTable.h"
#include "solvers/lbm/LbmParams.h"

namespace fluidviz::fhp {

/// Boundary of one side: bounce-back (no-slip at rest), bounce-back biased towards the wall's
/// velocity (no-slip on a sliding wall, kernel/MovingWall.h), specular reflection (free slip; y
/// sides only), or periodic. The names are the LBM's (lbm::WallType) where the LBM has the rule.
enum class SideType { wall, moving_wall, slip, periodic };
constexpr std::array<Choice<SideType>, 4> paramChoices(SideType) {
  return {{{SideType::wall, "wall", "no_slip"},
           {SideType::moving_wall, "moving_wall"},
           {SideType::slip, "slip"},
           {SideType::periodic, "periodic"}}};
}

/// One side of the box; the keys are the LBM's (lbm::WallParams: walls.<side>.type, .velocity).
struct FhpWallParams {
  SideType type = SideType::wall;
  std::array<double, 2> velocity{0.0, 0.0};

  template <class V>
  static void describe(V& v) {
    v(&FhpWallParams::type,
      {.key = "type",
       .description = "wall: no-slip at rest (bounce-back: every particle reversed; old name "
                      "no_slip); moving_wall: no-slip, slides along itself with `velocity` "
                      "(bounce-back, then reflected particles turned by 60 degrees towards the "
                      "wall's motion with a probability set by its speed: Wolf-Gladrow 2000, "
                      "ch. 3); slip: specular reflection (the normal momentum reversed, the "
                      "tangential kept exactly; y sides only); periodic: wraps to the opposite "
                      "side (which must be periodic too)"});
    v(&FhpWallParams::velocity,
      {.key = "velocity",
       .unit = "m/s",
       .description = "[x, y] velocity of a moving_wall: only the component along the wall may "
                      "be non-zero, and its lattice speed may not exceed max_lattice_velocity"});
  }
};

struct FhpSidesParams {
  FhpWallParams x_min{SideType::periodic};
  FhpWallParams x_max{SideType::periodic};
  FhpWallParams y_min;
  FhpWallParams y_max;

  template <class V>
  static void describe(V& v) {
    // The docs table shows the defaults of FhpWallParams{} for every side: say the x sides' here.
    v(&FhpSidesParams::x_min, {.key = "x_min", .description = "side x = 0 (type periodic unless set)"});
    v(&FhpSidesParams::x_max, {.key = "x_max", .description = "side x = Lx (type periodic unless set)"});
    v(&FhpSidesParams::y_min, {.key = "y_min", .description = "side y = 0 (type wall unless set)"});
    v(&FhpSidesParams::y_max, {.key = "y_max", .description = "side y = Ly (type wall unless set)"});
  }
};

/// A fixed solid disc of bounce-back nodes (the nodes whose position lies inside it).
struct FhpObstacleParams {
  std::array<double, 2> center{0.0, 0.0};
  double radius = 0.0;

  template <class V>
  static void describe(V& v) {
    v(&FhpObstacleParams::center,
      {.key = "center", .unit = "m", .description = "centre of the disc", .required = true});
    v(&FhpObstacleParams::radius, {.key = "radius",
                                   .unit = "m",
                                   .description = "disc radius (at least 2 links)",
                                   .min = 0,
                                   .minExclusive = true,
                                   .required = true});
  }
};

// Units, ranges and meanings of the members: their describe() declarations below.
struct FhpParams {
  Model model = Model::fhp3;
  double channel_density = 0.25;
  std::array<double, 2> domain_size{1.0, 1.0};
  int resolution = 256;
  int block_size = 8;
  int average_steps = 200;
  int seed = 1;
  double reynolds = 0.0;
  double reference_length = 0.0;
  double reference_velocity = 0.0;
  double max_lattice_velocity = 0.2;
  std::array<double, 2> flow_velocity{0.0, 0.0};
  int inflow_width = 0;
  double body_force = 0.0;
  double density = 1000.0;
  FhpSidesParams walls;
  std::vector<FhpObstacleParams> obstacles;
  std::vector<lbm::RollerParams> rollers;
  double end_time = 0.0;
  int max_steps = 10'000'000;

  template <class V>
  static void describe(V& v) {
    v(&FhpParams::model,
      {.key = "model",
       .description = "collision rules (Frisch et al. 1987): fhp1 (6 channels, head-on pairs and "
                      "symmetric triples), fhp2 (plus a rest particle), fhp3 (every collision "
                      "that conserves number and momentum: the lowest viscosity)"});
    v(&FhpParams::channel_density,
      {.key = "channel_density",
       .description = "mean occupation d of a channel (particles per node = 6 d, 7 d with the "
                      "rest particle); sets the viscosity nu(d) and the Galilean factor g(d) "
                      "(g > 0 needs d < 1/2)",
       .min = 0,
       .max = 0.5,
       .minExclusive = true,
       .maxExclusive = true});
    v(&FhpParams::domain_size,
      {.key = "domain_size", .unit = "m", .description = "box size [Lx, Ly]", .min = 0,
       .minExclusive = true});
    v(&FhpParams::resolution,
      {.key = "resolution",
       .description = "lattice nodes along x, a multiple of 64 (64 nodes per machine word); "
                      "the largest reachable Reynolds number grows in proportion",
       .min = 64,
       .max = 16384});
    v(&FhpParams::block_size,
      {.key = "block_size",
       .description = "nodes along x of an averaging block (it must divide resolution); a block "
                      "spans round(block_size / (sqrt(3)/2)) rows, so blocks are about square. "
                      "One block is one node of the snapshots",
       .min = 1,
       .max = 1024});
    v(&FhpParams::average_steps,
      {.key = "average_steps",
       .description = "time steps averaged into each snapshot (the last ones before it; at most "
                      "the steps between two snapshots); noise ~ 1/sqrt(block nodes x steps)",
       .min = 1,
       .max = 1e6});
    v(&FhpParams::seed,
      {.key = "seed",
       .description = "seed of the random bits (initial state, chirality, forcing); a run is "
                      "reproducible bit for bit",
       .min = 0,
       .max = 2147483647});
    v(&FhpParams::reynolds,
      {.key = "reynolds",
       .description = "Reynolds number U_ref L_ref / nu; sets the lattice speed u = Re nu(d) / "
                      "(g(d) L) of U_ref, refused above max_lattice_velocity",
       .min = 0,
       .minExclusive = true,
       .required = true});
    v(&FhpParams::reference_length,
      {.key = "reference_length", .unit = "m",
       .description = "length L_ref of the Reynolds number; 0 = Lx", .min = 0});
    v(&FhpParams::reference_velocity,
      {.key = "reference_velocity", .unit = "m/s",
       .description = "speed U_ref of the Reynolds number; 0 = |flow_velocity|, or if that is 0 "
                      "the fastest moving wall or roller rim", .min = 0});
    v(&FhpParams::max_lattice_velocity,
      {.key = "max_lattice_velocity",
       .description = "largest lattice speed (links per step) allowed for U_ref and the flow; "
                      "the sound speed is 1/sqrt(2) (fhp1) or sqrt(3/7) (fhp2, fhp3), and the "
                      "lattice gas departs from Navier-Stokes as (u / c_s)^2",
       .min = 0,
       .max = 0.4,
       .minExclusive = true});
    v(&FhpParams::flow_velocity,
      {.key = "flow_velocity", .unit = "m/s",
       .description = "[x, y] velocity of the initial state and of the inflow zone"});
    v(&FhpParams::inflow_width,
      {.key = "inflow_width",
       .description = "columns at x = 0 refilled every step with the equilibrium at "
                      "flow_velocity (a uniform inflow; the x sides must be periodic, so what "
                      "leaves at x = Lx is replaced); 0: none",
       .min = 0,
       .max = 1024});
    v(&FhpParams::body_force,
      {.key = "body_force", .unit = "m/s^2",
       .description = "uniform acceleration along x, by random momentum flips of the "
                      "particles moving against it (Wolf-Gladrow 2000, section 3.2)"});
    v(&FhpParams::density,
      {.key = "density", .unit = "kg/m^3",
       .description = "fluid density at the mean occupation (snapshots: density scaled by the "
                      "particles per node)", .min = 0, .minExclusive = true});
    v(&FhpParams::walls, {.key = "walls", .description = "boundary of each side of the box"});
    v(&FhpParams::obstacles,
      {.key = "obstacles", .description = "fixed solid discs (bounce-back nodes)"});
    v(&FhpParams::rollers,
      {.key = "rollers",
       .description = "solid discs turning about fixed centres, the LBM's rollers (the same "
                      "keys): the nodes inside are solid, those next to the fluid reflect "
                      "particles biased towards the local wall velocity omega x r (as a "
                      "moving_wall); boundary: staircase only. The rim's lattice speed may not "
                      "exceed max_lattice_velocity"});
    v(&FhpParams::end_time,
      {.key = "end_time", .unit = "s", .description = "simulated time", .min = 0,
       .minExclusive = true, .required = true});
    v(&FhpParams::max_steps, {.key = "max_steps", .description = "upper limit on time steps", .min = 1});
  }
};

/// Kinematic viscosity nu(d) in lattice units (links^2 per step; Frisch et al. 1987, eq. 5.29
/// with the coefficients of section 6): FHP-I 1/(12 d (1-d)^3) - 1/8, FHP-II
/// 1/(28 d (1-d)^3 (1 - 4d/7)) - 1/8, FHP-III 1/(28 d (1-d) (1 - 8 d (1-d)/7)) - 1/8.
double latticeViscosity(Model model, double d);
/// Galilean factor g(d): FHP-I (1-2d)/(2(1-d)), FHP-II and FHP-III 7(1-2d)/(12(1-d)).
double galileanFactor(Model model, double d);
/// Sound speed in links per step: 1/sqrt(2) (FHP-I) or sqrt(3/7) (FHP-II, FHP-III).
double soundSpeed(Model model);

/// The lattice a scene runs on and its units.
struct FhpUnits {
  int nx = 0, ny = 0;        ///< nodes along x, rows
  int blockX = 1, blockY = 1;  ///< nodes and rows of an averaging block
  double dx = 0.0;           ///< link length, m
  double dt = 0.0;           ///< duration of a step, s
  double nu = 0.0;           ///< lattice viscosity, links^2 / step
  double g = 0.0;            ///< Galilean factor
  double referenceSpeed = 0.0;  ///< lattice speed u of U_ref (links / step)
  std::array<double, 2> flowSpeed{0.0, 0.0};  ///< lattice particle velocity of flow_velocity
  double viscosity = 0.0;    ///< physical, m^2/s
  double forceProbability = 0.0;  ///< flip probability per fluid node and step
  int forceDirection = 0;    ///< 0 (+x) or 3 (-x)
  long long steps = 0;       ///< steps of the run

  /// Lattice particle velocity (links per step) -> snapshot velocity (m/s): g u dx / dt.
  double toPhysicalVelocity(double u) const { return g * u * dx / dt; }
  /// Snapshot velocity (m/s) -> lattice particle velocity: v dt / (g dx) (walls, rollers).
  double toLatticeVelocity(double v) const { return v * dt / (g * dx); }
};

/// Checks ranges and combinations (periodic sides in pairs, slip on y sides only, wall velocities
/// only on moving walls and along them, the inflow with periodic x sides, obstacles and rollers
/// inside the box, block_size dividing resolution). Throws
/// ParamError with the key relative to FhpParams.
void validateFhpParams(const FhpParams& p);

/// The units of a valid scene; throws ParamError ("reynolds") when the lattice speed needed for
/// the Reynolds number exceeds max_lattice_velocity, saying the largest reachable Re, and
/// ("body_force") when the force needs a flip probability above 1, and (the wall's "velocity", the
/// roller's "angular_velocity") when a moving wall or roller rim is faster than
/// max_lattice_velocity or than the biased reflection can follow (turn probability above 1).
FhpUnits computeFhpUnits(const FhpParams& p);

/// "FHP-III lattice 256 x 296 nodes, ..." for the log and `fluidviz check`.
std::string describeFhpUnits(const FhpUnits& u, const FhpParams& p);

}  // namespace fluidviz::fhp
