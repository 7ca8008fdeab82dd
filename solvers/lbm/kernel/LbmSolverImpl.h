#pragma once
// The Lattice-Boltzmann solver for one lattice L (LatticeD2Q9, LatticeD3Q19) and one population
// type T (double, float); instantiated for the four combinations in LbmSolverImpl.cpp.
// createLbmSolver (LbmSolver.h) picks one from the scene; code that knows what it wants may use
// the aliases below (LbmSolverD2Q9 = 2D, double).
//
// Memory: two structure-of-arrays population arrays (PopulationArrays.h) holding shifted
// populations g = f - w (Equilibrium.h), 2 Q sizeof(T) bytes per node; a boundary link table
// (BoundaryLinkTable.h). Time step: fused pull stream-collide (StreamCollidePull.h) with BGK or
// TRT (CollisionBGK.h, CollisionTRT.h), row-parallel with OpenMP, compiled for three x86-64
// instruction sets and picked at load time.
#include <cstdint>
#include <vector>

#include "solvers/lbm/LbmSolver.h"
#include "solvers/lbm/collision/CollisionBGK.h"
#include "solvers/lbm/collision/CollisionTRT.h"
#include "solvers/lbm/kernel/BoundaryLinkTable.h"
#include "solvers/lbm/kernel/PopulationArrays.h"
#include "solvers/lbm/kernel/StreamCollidePull.h"
#include "solvers/lbm/lattice/LatticeD2Q9.h"
#include "solvers/lbm/lattice/LatticeD3Q19.h"

namespace fluidviz::lbm {

template <class L, class T>
class LbmSolverImpl final : public LbmSolver {
 public:
  using Lattice = L;
  using Real = T;

  /// Validates params (ParamError) and starts at rest with lattice density 1, or in the state
  /// params.initial_flow asks for. Throws std::invalid_argument if params.lattice or
  /// params.precision is not this class's (use createLbmSolver to pick by the scene).
  explicit LbmSolverImpl(const LbmParams& params, std::vector<SolidBody> extraBodies = {});

  const LbmParams& params() const override { return params_; }
  const LatticeUnits& units() const override { return units_; }
  const Grid& grid() const override { return grid_; }
  void initialise(const std::vector<double>& density, const std::vector<Vec3>& velocity) override;
  void step(int n = 1) override;
  FieldSet fields() const override;
  double totalMass() const override;
  void checkStability() const override;
  double maxVelocityChange() override;
  void saveState(StateWriter& out) const override;  // LbmSolverState.cpp
  void restoreState(StateReader& in) override;
  std::vector<BodyForce> bodyForces() const override;
  bool isSolid(int i, int j, int k = 0) const override {
    return table_.isSolid((std::int64_t(k) * units_.ny + j) * units_.nx + i);
  }
  std::int64_t fluidNodeCount() const override { return table_.fluidNodeCount(); }
  std::int64_t boundaryNodeCount() const override {
    return static_cast<std::int64_t>(table_.boundaryNodes().size());
  }
  int bytesPerUpdate() const override { return 2 * L::Q * static_cast<int>(sizeof(T)); }

 private:
  struct LatticeMoments {
    std::vector<double> rho, ux, uy, uz;  ///< lattice units; NaN at solid nodes
  };
  LatticeMoments latticeMoments() const;
  BoundaryGatherData<T> gatherData() const;
  void streamCollide(int steps);
  /// The open sides' rules for the step that brings the state to time `step` dt: the inlet
  /// velocities times their ramp factor (inletRampFactor).
  void setOpenSideRules(long long step);
  /// Steps until the last inlet ramp ends (0 without ramps).
  long long rampEndStep() const;
  void firstTouchAndRest();
  [[noreturn]] void throwInstability(std::int64_t node, const std::string& reason,
                                     const std::string& detail) const;

  LbmParams params_;
  LatticeUnits units_;
  Grid grid_;
  std::vector<SolidBody> bodies_;
  // The state a checkpoint saves (LbmSolverState.cpp): populations_[current_], steps_, steady_
  // and previousU*_; keep it in step when adding state.
  PopulationArraysOf<T> populations_[2];
  int current_ = 0;  ///< which of populations_ holds the post-collision state of the last step
  BoundaryLinkTable<L> table_;
  OpenSideRule openSides_[6];
  CollisionBGK bgk_;
  CollisionTRT trt_;
  bool useTrt_ = false;
  bool forced_ = false;
  std::vector<double> previousUx_, previousUy_, previousUz_;  ///< for maxVelocityChange
};

using LbmSolverD2Q9 = LbmSolverImpl<LatticeD2Q9, double>;
using LbmSolverD2Q9Float = LbmSolverImpl<LatticeD2Q9, float>;
using LbmSolverD3Q19 = LbmSolverImpl<LatticeD3Q19, double>;
using LbmSolverD3Q19Float = LbmSolverImpl<LatticeD3Q19, float>;

extern template class LbmSolverImpl<LatticeD2Q9, double>;
extern template class LbmSolverImpl<LatticeD2Q9, float>;
extern template class LbmSolverImpl<LatticeD3Q19, double>;
extern template class LbmSolverImpl<LatticeD3Q19, float>;

}  // namespace fluidviz::lbm
