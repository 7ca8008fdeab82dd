#pragma once
// Lattice-Boltzmann solver: the interface the pipeline and the tests use, and the factory that
// picks the implementation the scene asks for.
//
//   LbmParams (physical units) --computeLatticeUnits--> LatticeUnits (dx, dt, tau)
//   lattice D2Q9 | D3Q19 x precision double | float  ->  LbmSolverImpl<L, T> (LbmSolverImpl.h)
//   collision BGK | TRT, Guo body force; boundaries: walls, moving walls, periodic sides,
//   Zou-He velocity inlets and pressure sides, rollers (staircase or Bouzidi interpolated)
//   fields(): density, velocity, speed in physical units on the node-centred grid
//
// Node (i, j, k) sits at ((i + 1/2) dx, (j + 1/2) dx, (k + 1/2) dx); the walls are on the box
// edges. Nothing is printed; problems are reported by ParamError (construction) and
// InstabilityError (while running).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/StateBytes.h"
#include "solvers/lbm/InstabilityError.h"
#include "solvers/lbm/LbmParams.h"
#include "solvers/lbm/boundaries/SolidBody.h"
#include "solvers/lbm/lattice/UnitConversion.h"

namespace fluidviz::lbm {

/// Why advance() returned.
enum class StopReason {
  ReachedTime,  ///< the requested time was reached
  EndTime,      ///< params.end_time reached
  MaxSteps,     ///< params.max_steps reached
  Steady,       ///< relative velocity change between checks < params.steady_tolerance
};

/// Hydrodynamic force the fluid exerts on one solid body, in SI: N per metre of depth in 2D
/// (force z = 0), N in 3D.
struct BodyForce {
  std::string name;  ///< SolidBody::name, e.g. "rollers[0]"
  Vec3 force;
};

class LbmSolver {
 public:
  virtual ~LbmSolver() = default;

  virtual const LbmParams& params() const = 0;
  virtual const LatticeUnits& units() const = 0;
  /// Node-centred grid of the fields: dims (nx, ny, nz), origin (dx/2, dx/2, dx/2 or 0),
  /// spacing dx; nz = 1 and origin z = 0 in 2D.
  virtual const Grid& grid() const = 0;

  /// Replaces the state by the equilibrium of the given fields (physical units, one value per
  /// node, x fastest; solid nodes are ignored), such that the moments after this call are
  /// exactly the given ones (except next to Bouzidi walls and open sides, whose rules already
  /// act on the first gather). Throws std::invalid_argument on a size mismatch.
  virtual void initialise(const std::vector<double>& density,
                          const std::vector<Vec3>& velocity) = 0;

  /// n fused stream-collide steps (no checks; see checkStability / advance).
  virtual void step(int n = 1) = 0;
  long long stepCount() const { return steps_; }
  double time() const { return static_cast<double>(steps_) * units().dt; }  ///< s

  /// Steps until time() >= targetTime (at most params.end_time and params.max_steps), checking
  /// stability every params.check_interval steps and, if params.steady_tolerance > 0, stopping
  /// early at steady state. Throws InstabilityError.
  StopReason advance(double targetTime);
  /// advance(params.end_time).
  StopReason run() { return advance(params().end_time); }

  /// Density (kg/m^3), velocity (m/s) and speed (m/s) of every node. Solid nodes carry the
  /// reference density and the velocity of their body.
  virtual FieldSet fields() const = 0;

  /// Sum of the lattice density over fluid nodes (conserved by collision, streaming and the
  /// halfway bounce-back rules; not by open sides and Bouzidi walls). Summed in long double,
  /// row by row.
  virtual double totalMass() const = 0;

  /// Throws InstabilityError at the first node (in x-fastest order) with a NaN, a non-positive
  /// density or a lattice speed above LatticeStabilityLimits::maxSpeed.
  virtual void checkStability() const = 0;

  /// max over fluid nodes of |u - u_prev| / max |u| (lattice units), u_prev being the velocity
  /// at the previous call; +infinity on the first call. The steady-state criterion.
  virtual double maxVelocityChange() = 0;

  /// The whole evolving state (populations, step count, steady-state reference velocity) for a
  /// checkpoint; restoreState on a solver built from the same params continues bit-identically.
  virtual void saveState(StateWriter& out) const = 0;
  /// Throws StateFormatError if the state was saved by a solver of another lattice, precision or
  /// size (LbmSolverState.cpp).
  virtual void restoreState(StateReader& in) = 0;

  /// Force on every solid body (params.rollers, then the extra bodies of createLbmSolver), by
  /// momentum exchange over the body's links (Ladd 1994 for bounce-back links; the same sum with
  /// the interpolated return population for Bouzidi links, Mei, Yu, Shyy & Luo 2002, Phys. Rev.
  /// E 65, 041203, eq. 15): the momentum the populations of the last step carry into the body
  /// minus what comes back for the next step. Computed on demand from the current populations;
  /// steps do not pay for it.
  virtual std::vector<BodyForce> bodyForces() const = 0;

  virtual bool isSolid(int i, int j, int k = 0) const = 0;
  virtual std::int64_t fluidNodeCount() const = 0;
  virtual std::int64_t boundaryNodeCount() const = 0;
  /// Bytes of population storage moved per fluid node update: 2 Q sizeof(T).
  virtual int bytesPerUpdate() const = 0;

 protected:
  long long steps_ = 0;
  bool steady_ = false;
};

/// The solver for params.lattice and params.precision. Validates params (throws ParamError
/// naming the key relative to LbmParams). `extraBodies` are solid bodies besides params.rollers
/// (e.g. a fixed outer cylinder); they are not checked against the box.
std::unique_ptr<LbmSolver> createLbmSolver(const LbmParams& params,
                                           std::vector<SolidBody> extraBodies = {});

/// The initial fields params.initial_flow asks for, on `grid` (density kg/m^3, velocity m/s);
/// empty vectors for "rest".
void initialFlowFields(const LbmParams& params, const LatticeUnits& units, const Grid& grid,
                       std::vector<double>& density, std::vector<Vec3>& velocity);

}  // namespace fluidviz::lbm
