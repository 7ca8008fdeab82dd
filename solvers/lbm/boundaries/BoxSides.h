#pragma once
// The boundary condition of each side of the box in lattice units (from the scene's
// WallsParams): wall at rest, moving wall, periodic, Zou-He velocity inlet or pressure side.
// Read by the boundary link table of the kernel (BoundaryLinkTable.h) and by the reference step
// (ReferenceStreamCollide.h).
#include <array>

#include "solvers/lbm/LbmParams.h"
#include "solvers/lbm/lattice/UnitConversion.h"

namespace fluidviz::lbm {

/// One side of the box in lattice units.
struct SideCondition {
  enum class Type { Wall, MovingWall, Periodic, VelocityInlet, Pressure };
  Type type = Type::Wall;
  std::array<double, 3> velocity{0.0, 0.0, 0.0};  ///< lattice velocity (moving wall, inlet)
  double density = 1.0;                           ///< lattice density (pressure side)
  bool parabolic = false;  ///< inlet: velocity is the centre value of a Poiseuille profile
  double rampSteps = 0.0;  ///< inlet: steps over which it starts (WallParams::ramp_time / dt)
  bool isOpen() const { return type == Type::VelocityInlet || type == Type::Pressure; }
};

/// Factor of an inlet's velocity at node ijk of a dims lattice, the side's normal along
/// `axis`: 1 for a uniform inlet; for a parabolic one the product over the other axes of
/// 4 s (1 - s), s = (n + 1/2) / dims the node's place between the halfway walls (an axis of one
/// node, z in 2D, gives 1).
double inletProfileFactor(const SideCondition& side, int axis, const int (&ijk)[3],
                          const int (&dims)[3]);

/// Factor of an inlet's velocity in the time step that brings the populations to time `step` dt:
/// sin^2(pi step / (2 rampSteps)) during the ramp, else 1.
double inletRampFactor(const SideCondition& side, long long step);

/// The six sides, indexed 2 axis + (0 for min, 1 for max): x_min, x_max, y_min, y_max, z_min,
/// z_max. A 2D lattice never crosses the z sides.
struct BoxSides {
  std::array<SideCondition, 6> side;
  const SideCondition& lower(int axis) const { return side[2 * axis]; }
  bool periodic(int axis) const { return side[2 * axis].type == SideCondition::Type::Periodic; }
  /// From the scene parameters (velocities converted with u.dt / u.dx, pressures to densities).
  static BoxSides fromParams(const WallsParams& w, const LatticeUnits& u);
};

}  // namespace fluidviz::lbm
