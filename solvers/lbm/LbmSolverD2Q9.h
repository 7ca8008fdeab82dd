#pragma once
// Lattice-Boltzmann solver, D2Q9 lattice, BGK collision, double precision, OpenMP.
//
//   LbmParams (physical units) --computeLatticeUnits--> LatticeUnits (dx, dt, tau)
//   BoundaryLinkTable: solid nodes, bulk runs, boundary links (walls, lids, periodic, rollers)
//   step(): fused pull stream-collide (StreamCollidePull.h) with CollisionBGK.h and Guo forcing
//   fields(): density, velocity, speed in physical units on the node-centred grid
//
// Node (i, j) sits at ((i + 1/2) dx, (j + 1/2) dx); the walls are on the box edges.
// Nothing is printed; problems are reported by ParamError (construction) and InstabilityError.
#include <cstdint>
#include <limits>
#include <vector>

#include "fieldviz/core/Field.h"
#include "solvers/lbm/BoundaryLinkTable.h"
#include "solvers/lbm/CollisionBGK.h"
#include "solvers/lbm/InstabilityError.h"
#include "solvers/lbm/LatticeD2Q9.h"
#include "solvers/lbm/LbmParams.h"
#include "solvers/lbm/PopulationArrays.h"
#include "solvers/lbm/SolidBody.h"
#include "solvers/lbm/UnitConversion.h"

namespace fluidviz::lbm {

/// Why advance() returned.
enum class StopReason {
  ReachedTime,  ///< the requested time was reached
  EndTime,      ///< params.end_time reached
  MaxSteps,     ///< params.max_steps reached
  Steady,       ///< relative velocity change between checks < params.steady_tolerance
};

class LbmSolverD2Q9 {
 public:
  using Lattice = LatticeD2Q9;
  using Collision = CollisionBGK;

  /// Validates params (throws ParamError naming the key relative to LbmParams) and starts at
  /// rest with lattice density 1. `extraBodies` are solid bodies besides params.rollers (e.g. a
  /// fixed outer cylinder); they are not checked against the box.
  explicit LbmSolverD2Q9(const LbmParams& params, std::vector<SolidBody> extraBodies = {});

  const LbmParams& params() const { return params_; }
  const LatticeUnits& units() const { return units_; }
  /// Node-centred grid of the fields: dims (nx, ny, 1), origin (dx/2, dx/2, 0), spacing dx.
  const Grid& grid() const { return grid_; }

  /// Replaces the state by the equilibrium of the given fields (physical units, one value per
  /// node, x fastest; solid nodes are ignored), such that the moments after this call are
  /// exactly the given ones. Throws std::invalid_argument on a size mismatch.
  void initialise(const std::vector<double>& density, const std::vector<Vec3>& velocity);

  /// n fused stream-collide steps (no checks; see checkStability / advance).
  void step(int n = 1);
  long long stepCount() const { return steps_; }
  double time() const { return static_cast<double>(steps_) * units_.dt; }  ///< s

  /// Steps until time() >= targetTime (at most params.end_time and params.max_steps), checking
  /// stability every params.check_interval steps and, if params.steady_tolerance > 0, stopping
  /// early at steady state. Throws InstabilityError.
  StopReason advance(double targetTime);
  /// advance(params.end_time).
  StopReason run() { return advance(params_.end_time); }

  /// Density (kg/m^3), velocity (m/s, z = 0) and speed (m/s) of every node. Solid nodes carry the
  /// reference density and the velocity of their body.
  FieldSet fields() const;

  /// Sum of the lattice density over fluid nodes (conserved by collision, streaming and the
  /// bounce-back rules used here; summed in long double, row by row).
  double totalMass() const;

  /// Throws InstabilityError at the first node (in x-fastest order) with a NaN, a non-positive
  /// density or a lattice speed above LatticeStabilityLimits::maxSpeed.
  void checkStability() const;

  /// max over fluid nodes of |u - u_prev| / max |u| (lattice units), u_prev being the velocity
  /// at the previous call; +infinity on the first call. The steady-state criterion.
  double maxVelocityChange();

  bool isSolid(int i, int j) const { return table_.isSolid(std::int64_t(j) * units_.nx + i); }
  std::int64_t fluidNodeCount() const { return table_.fluidNodeCount(); }
  std::int64_t boundaryNodeCount() const {
    return static_cast<std::int64_t>(table_.boundaryNodes().size());
  }

 private:
  struct LatticeMoments {
    std::vector<double> rho, ux, uy;  ///< lattice units; NaN at solid nodes
  };
  LatticeMoments latticeMoments() const;
  void streamCollide(int steps);
  void firstTouchAndRest();
  [[noreturn]] void throwInstability(std::int64_t node, const std::string& reason,
                                     const std::string& detail) const;

  LbmParams params_;
  LatticeUnits units_;
  Grid grid_;
  std::vector<SolidBody> bodies_;
  PopulationArrays populations_[2];
  int current_ = 0;  ///< which of populations_ holds the post-collision state of the last step
  BoundaryLinkTable table_;
  Collision collision_;
  bool forced_ = false;
  long long steps_ = 0;
  std::vector<double> previousUx_, previousUy_;  ///< for maxVelocityChange
  bool steady_ = false;
};

}  // namespace fluidviz::lbm
