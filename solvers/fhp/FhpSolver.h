#pragma once
// A scene's lattice gas: the multi-spin lattice (lattice/BitLattice.h) with the scene's walls and
// obstacles, its collision table, forcing and inflow zone, and the block/time averager whose
// fields are the snapshots (in physical units, FhpParams.h).
#include <cstdint>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/StateBytes.h"
#include "solvers/fhp/FhpParams.h"
#include "solvers/fhp/averaging/BlockAverager.h"
#include "solvers/fhp/lattice/BitLattice.h"

namespace fluidviz::fhp {

class FhpSolver {
 public:
  /// Throws ParamError (keys relative to FhpParams) for a scene that cannot run.
  explicit FhpSolver(const FhpParams& params);

  const FhpParams& params() const { return params_; }
  const FhpUnits& units() const { return units_; }
  const BitLattice& lattice() const { return lattice_; }
  long long stepCount() const { return static_cast<long long>(lattice_.time()); }
  double time() const { return static_cast<double>(stepCount()) * units_.dt; }

  /// n steps: collision (forcing), propagation, the inflow zone refilled.
  void step(long long n);

  /// Averaging window: clear, add the current state as one sample.
  void clearAverage() { averager_.clear(); }
  void sampleAverage() { averager_.add(lattice_); }
  int averageSamples() const { return averager_.samples(); }

  /// The averaged state on the grid of block centres (m): "density" (kg/m^3), "velocity" (m/s,
  /// v = g u, FhpParams.h), "speed" (m/s), "pressure" (Pa, gauge: c_s^2 (rho - rho0) in physical
  /// units). With no sample yet (the initial snapshot), the current state alone.
  FieldSet averagedFields() const;
  /// 1 for a block less than half of whose nodes are fluid (solid walls, obstacles).
  std::vector<std::uint8_t> solidBlocks() const;
  /// Grid of the averaged fields.
  Grid grid() const;

  /// Sum over all particles of 2 c_x and of 2 c_y / sqrt(3) (integers: exact momentum).
  long long momentumX2() const;
  long long momentumYInt() const;

  void saveState(StateWriter& out) const;
  void restoreState(StateReader& in);

 private:
  void buildGeometry();
  std::vector<WallNodeMotion> movingWallNodes() const;
  /// Position (m) of node (x, y): odd rows shifted by half a link.
  double nodeX(int x, int y) const;
  double nodeY(int y) const;
  /// Scales the flip probability so that the force stays the scene's as the flow grows.
  void adaptForcing(std::uint64_t flips);

  FhpParams params_;
  FhpUnits units_;
  BitLattice lattice_;
  CollisionTable table_;
  StepRules rules_;
  BlockAverager averager_;
  double fluidNodes_ = 0.0;
  double flipEfficiency_ = 0.0;  ///< flips per fluid node and unit probability (running mean)
};

}  // namespace fluidviz::fhp
