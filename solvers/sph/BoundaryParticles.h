#pragma once
// Solids made of boundary particles: the walls of the domain box, solid boxes
// (obstacles) and rigid rollers turning at a given angular velocity (SPH N-roll mills).
//
// Boundary particles continue the fluid lattice (spacing dx) into the solid, in as many layers
// as the kernel support needs, so that a fluid particle next to a solid sees a full
// neighbourhood for the no-slip viscous term (Morris et al. 1997, sec. 3.3) and the nearest
// layer sits one spacing away for the Lennard-Jones repulsion (Monaghan 1994, sec. 4).
// Each particle remembers its solid (for the distance of a fluid particle from that solid's
// surface) and its depth below the surface.
#include <array>
#include <vector>

#include "fieldviz/core/Grid.h"
#include "solvers/sph/SphParams.h"

namespace fluidviz::sph {

/// The surface of one solid, seen from the fluid.
struct BoundarySurface {
  enum class Kind { DomainWalls, Box, Roller };
  Kind kind = Kind::Box;
  int dimension = 2;
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();  ///< DomainWalls: the domain; Box: the solid
  std::array<bool, 6> wallSide{};  ///< DomainWalls: x_min, x_max, y_min, y_max, z_min, z_max
  Vec3 center = Vec3::Zero();      ///< Roller: axis point (z = 0)
  double radius = 0.0;             ///< Roller: m
  double angularVelocity = 0.0;    ///< Roller: rad/s about +z

  /// Distance (m) of a fluid point from this solid's surface; <= 0 inside the solid.
  double fluidDistance(const Vec3& x) const;
  /// Velocity (m/s) of the solid's material at x (zero unless a roller).
  Vec3 velocityAt(const Vec3& x) const {
    return {-angularVelocity * (x[1] - center[1]), angularVelocity * (x[0] - center[0]), 0.0};
  }
};

struct BoundaryParticles {
  std::vector<Vec3> positions;     ///< m, current
  std::vector<Vec3> velocities;    ///< m/s, current (rigid motion of the solid)
  std::vector<int> surface;        ///< index into surfaces
  std::vector<double> depth;       ///< m, distance below the surface, > 0
  std::vector<Vec3> restPositions; ///< m, positions at t = 0 (rollers turn these)
  std::vector<BoundarySurface> surfaces;

  std::size_t size() const { return positions.size(); }
  /// Puts every roller particle at its position at time t (rigid rotation of restPositions).
  void moveTo(double t);
};

/// A scene's 3-component point or vector (domain corners, gravity, blocks) as a Vec3; in 2D its
/// z component is not used and is 0.
Vec3 sceneVector(const std::array<double, 3>& a, int dimension);

/// Builds the boundary particles of a validated SphParams: the domain's wall sides, obstacles
/// and rollers, each `layers` spacings thick.
BoundaryParticles makeBoundaryParticles(const SphParams& p, int layers);

/// Fluid particles of the blocks, on the lattice block.lower + (i + 1/2) dx, without the ones
/// closer than dx/2 to (or inside) an obstacle or roller.
std::vector<Vec3> makeFluidParticles(const SphParams& p, const BoundaryParticles& solids);

}  // namespace fluidviz::sph
