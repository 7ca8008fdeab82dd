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
  bool isOpen() const { return type == Type::VelocityInlet || type == Type::Pressure; }
};

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
