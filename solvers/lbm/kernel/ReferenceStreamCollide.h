#pragma once
// The LBM time step written as the equations: a plain reference for the optimised kernel
// (StreamCollidePull.h, driven by LbmSolverImpl.cpp), the same scheme and boundary rules with
// plain loops over nodes and directions on plain arrays, and nothing else. It is for reading and
// for testing the kernel against (tests/solvers/lbm/ReferenceStep_test.cpp); at a few thousand
// nodes per step it is far too slow for anything else.
//
// One step (the algorithm of Krueger et al. 2017, "The Lattice Boltzmann Method: Principles and
// Practice", sec. 3.2, "The lattice Boltzmann equation in a nutshell": collide, stream, then the
// boundary rules):
//   collide()             every fluid node: density and velocity, then BGK or TRT with the Guo
//                         body force, f -> f*
//   stream()              every fluid node pulls f_q(x) = f*_q(x - c_q) from its neighbour, or,
//                         where x - c_q is not a fluid node of the box, takes the bounce-back
//                         value (halfwayBounceBack: walls at rest, moving walls, bodies)
//   interpolateAtBodies() Bouzidi links replace the halfway ones of interpolated bodies
//   closeOpenSide()       Zou-He velocity inlets and pressure sides set their unknown populations
// The optimised kernel fuses the same four parts into one pull per node (the pull of step n + 1
// and the collision of step n), which is the same sequence cut at another place: here the state
// between steps is the pre-collision f (after streaming and boundaries), there the post-collision
// f*. postCollision() and populations() give both.
//
// Populations are stored shifted, g_q = f_q - w_q, like the solver's (Equilibrium.h): every
// rule below is linear and reads the same for g, and the moments are rho = 1 + sum g,
// rho u = sum g c. Arithmetic is in double, storage in T (the solver's population type).
//
// Reused, because they are plain formulas of one concept each: the lattice tables
// (LatticeD2Q9.h, LatticeD3Q19.h), the shifted equilibrium (Equilibrium.h), the Guo source term
// (GuoForcing.h), the moving-wall momentum (MovingWallBounceBack.h), the wall fraction of a link
// (BouzidiInterpolatedBounceBack.h), the Zou-He closures (ZouHeVelocityInlet.h,
// ZouHePressureOutlet.h), the periodic wrap (PeriodicBoundary.h), the side conditions in lattice
// units (BoxSides.h) and the scene's bodies (RotatingRoller.h). None of the kernel's data
// structures (link tables, runs, line vectors) is used.
#include <array>
#include <cstdint>
#include <vector>

#include "solvers/lbm/LbmParams.h"
#include "solvers/lbm/boundaries/BouzidiInterpolatedBounceBack.h"
#include "solvers/lbm/boundaries/BoxSides.h"
#include "solvers/lbm/boundaries/MovingWallBounceBack.h"
#include "solvers/lbm/boundaries/PeriodicBoundary.h"
#include "solvers/lbm/boundaries/RotatingRoller.h"
#include "solvers/lbm/boundaries/SolidBody.h"
#include "solvers/lbm/boundaries/ZouHePressureOutlet.h"
#include "solvers/lbm/boundaries/ZouHeVelocityInlet.h"
#include "solvers/lbm/collision/GuoForcing.h"
#include "solvers/lbm/lattice/Equilibrium.h"
#include "solvers/lbm/lattice/UnitConversion.h"

namespace fluidviz::lbm {

template <class L, class T>
class ReferenceStreamCollide {
 public:
  /// Plane q holds population q of every node, x fastest: node n = (k ny + j) nx + i.
  using Populations = std::array<std::vector<T>, L::Q>;

  /// The scene of `params` for lattice L, with `extraBodies` besides params.rollers (as
  /// createLbmSolver). Starts at rest (g = 0 everywhere).
  explicit ReferenceStreamCollide(const LbmParams& params, std::vector<SolidBody> extraBodies = {})
      : units_(computeLatticeUnits(params)),
        sides_(BoxSides::fromParams(params.walls, units_)),
        trt_(params.collision == Collision::trt),
        nx_(units_.nx),
        ny_(units_.ny),
        nz_(L::D == 3 ? units_.nz : 1),
        bodies_(sceneBodies(params, std::move(extraBodies))) {
    for (int a = 0; a < 3; ++a) force_[a] = units_.latticeBodyForce[a];
    markSolidNodes();
    for (int q = 0; q < L::Q; ++q) {
      f_[q].assign(nodeCount(), T(0));
      post_[q].assign(nodeCount(), T(0));
    }
  }

  /// Starts from post-collision populations f* (e.g. a solver's state): streams them and applies
  /// the boundary rules, so that populations() holds the pre-collision f of the next step.
  void startFromPostCollision(const Populations& post) {
    post_ = post;
    streamAndApplyBoundaries();
  }

  /// One time step: collide, then stream and apply the boundary rules.
  void step() {
    collide();
    streamAndApplyBoundaries();
  }

  const Populations& populations() const { return f_; }     ///< pre-collision f
  const Populations& postCollision() const { return post_; }  ///< f* of the last collision
  const LatticeUnits& units() const { return units_; }
  std::int64_t nodeCount() const { return std::int64_t(nx_) * ny_ * nz_; }
  bool isSolid(std::int64_t n) const { return bodyAt_[n] >= 0; }

  /// Density and velocity of the pre-collision populations at node n (lattice units):
  /// rho = 1 + sum_q g_q, u = (sum_q g_q c_q + F/2) / rho with F = rho g (Guo et al. 2002).
  NodeMoments<double> moments(std::int64_t n) const {
    double g[L::Q];
    for (int q = 0; q < L::Q; ++q) g[q] = f_[q][n];
    return momentsOf(g);
  }

 private:
  // ---- collision -------------------------------------------------------------------------

  NodeMoments<double> momentsOf(const double* g) const {
    double drho = 0.0, j[3] = {0.0, 0.0, 0.0};
    for (int q = 0; q < L::Q; ++q) {
      drho += g[q];
      j[0] += L::cx[q] * g[q];
      j[1] += L::cy[q] * g[q];
      j[2] += L::cz[q] * g[q];
    }
    const double rho = 1.0 + drho;
    return {drho, rho, j[0] / rho + 0.5 * force_[0], j[1] / rho + 0.5 * force_[1],
            j[2] / rho + 0.5 * force_[2]};
  }

  void collide() {
    for (std::int64_t n = 0; n < nodeCount(); ++n)
      if (!isSolid(n)) collideNode(n);
  }

  /// Relaxation towards the equilibrium with the Guo body-force term S_q (Guo, Zheng & Shi 2002,
  /// GuoForcing.h; force density F = rho g), BGK or TRT.
  void collideNode(std::int64_t n) {
    double g[L::Q], eq[L::Q], source[L::Q];
    for (int q = 0; q < L::Q; ++q) g[q] = f_[q][n];
    const NodeMoments<double> m = momentsOf(g);
    for (int q = 0; q < L::Q; ++q) {
      eq[q] = shiftedEquilibrium<L>(q, m.rho, m.ux, m.uy, m.uz);
      source[q] = guoSourceTerm<L>(q, m.ux, m.uy, m.uz, m.rho * force_[0], m.rho * force_[1],
                                   m.rho * force_[2]);
    }
    for (int q = 0; q < L::Q; ++q)
      post_[q][n] = static_cast<T>(trt_ ? relaxTRT(q, g, eq, source) : relaxBGK(q, g, eq, source));
  }

  /// BGK (Bhatnagar, Gross & Krook 1954; Qian, d'Humieres & Lallemand 1992; CollisionBGK.h):
  ///   f*_q = f_q - omega (f_q - f_q^eq) + (1 - omega/2) S_q.
  double relaxBGK(int q, const double* g, const double* eq, const double* source) const {
    const double omega = units_.omega();
    return g[q] - omega * (g[q] - eq[q]) + (1.0 - 0.5 * omega) * source[q];
  }

  /// TRT (Ginzburg, Verhaeghe & d'Humieres 2008; CollisionTRT.h): the parts even (+) and odd (-)
  /// under q -> opp(q), a+-_q = (a_q +- a_opp(q)) / 2, each relaxed at its own rate:
  ///   f*_q = f_q - omega+ (f+_q - f+eq_q) - omega- (f-_q - f-eq_q)
  ///          + (1 - omega+/2) S+_q + (1 - omega-/2) S-_q.
  double relaxTRT(int q, const double* g, const double* eq, const double* source) const {
    const int o = L::opposite[q];
    const double omegaPlus = units_.omega(), omegaMinus = units_.omegaMinus();
    const double plus = 0.5 * (g[q] + g[o]), minus = 0.5 * (g[q] - g[o]);
    const double eqPlus = 0.5 * (eq[q] + eq[o]), eqMinus = 0.5 * (eq[q] - eq[o]);
    const double sourcePlus = 0.5 * (source[q] + source[o]);
    const double sourceMinus = 0.5 * (source[q] - source[o]);
    return g[q] - omegaPlus * (plus - eqPlus) - omegaMinus * (minus - eqMinus) +
           (1.0 - 0.5 * omegaPlus) * sourcePlus + (1.0 - 0.5 * omegaMinus) * sourceMinus;
  }

  // ---- streaming and boundaries ----------------------------------------------------------

  void streamAndApplyBoundaries() {
    ++streamed_;
    for (std::int64_t n = 0; n < nodeCount(); ++n) {
      if (isSolid(n)) continue;
      double g[L::Q];
      for (int q = 0; q < L::Q; ++q) g[q] = stream(n, q);
      interpolateAtBodies(n, g);
      closeOpenSide(n, g);
      for (int q = 0; q < L::Q; ++q) f_[q][n] = static_cast<T>(g[q]);
    }
  }

  /// Where population q arriving at node n comes from: the neighbour x - c_q, its index taken
  /// modulo the node count along periodic axes (PeriodicBoundary.h); `crossed[a]` = -1 / +1 if
  /// the neighbour lies beyond the min / max side of a non-periodic axis a, else 0.
  struct Neighbour {
    int ijk[3];
    int crossed[3] = {0, 0, 0};
    bool outside() const { return crossed[0] != 0 || crossed[1] != 0 || crossed[2] != 0; }
  };
  Neighbour neighbour(std::int64_t n, int dx, int dy, int dz) const {
    const int dims[3] = {nx_, ny_, nz_}, d[3] = {dx, dy, dz};
    Neighbour s;
    for (int a = 0; a < 3; ++a) {
      s.ijk[a] = coordinate(n, a) + d[a];
      if (s.ijk[a] >= 0 && s.ijk[a] < dims[a]) continue;
      if (sides_.periodic(a))
        s.ijk[a] = wrapPeriodic(s.ijk[a], dims[a]);
      else
        s.crossed[a] = s.ijk[a] < 0 ? -1 : 1;
    }
    return s;
  }

  /// Pull streaming f_q(x, t+1) = f*_q(x - c_q, t), or bounce-back where x - c_q is not fluid.
  double stream(std::int64_t n, int q) const {
    const Neighbour s = neighbour(n, -L::cx[q], -L::cy[q], -L::cz[q]);
    if (s.outside()) return bounceBackFromSides(n, q, s.crossed);
    const std::int64_t source = index(s.ijk);
    if (isSolid(source)) return halfwayBounceBack(n, q, staircaseWallVelocity(n, q));
    return post_[q][source];
  }

  /// Halfway bounce-back (BounceBackWall.h) from a wall moving with u_w (MovingWallBounceBack.h,
  /// Ladd 1994): f_q(x, t+1) = f*_opp(q)(x, t) + 2 w_q (c_q . u_w) / cs2.
  double halfwayBounceBack(std::int64_t n, int q, const std::array<double, 3>& uWall) const {
    return post_[L::opposite[q]][n] + movingWallDelta<L>(q, uWall[0], uWall[1], uWall[2]);
  }

  /// A link leaving the box through one side (or two, at an edge, or three at a corner): the
  /// velocity of every moving wall crossed adds up; a wall at rest adds nothing. Links through
  /// an open side get the halfway value too; the Zou-He closure replaces it (closeOpenSide).
  double bounceBackFromSides(std::int64_t n, int q, const int (&crossed)[3]) const {
    std::array<double, 3> u{0.0, 0.0, 0.0};
    for (int a = 0; a < 3; ++a) {
      if (crossed[a] == 0) continue;
      const SideCondition& side = sides_.side[2 * a + (crossed[a] > 0 ? 1 : 0)];
      if (side.type != SideCondition::Type::MovingWall) continue;
      for (int b = 0; b < 3; ++b) u[b] += side.velocity[b];
    }
    return halfwayBounceBack(n, q, u);
  }

  /// The ends (positions in m) of link q of fluid node n that pulls from a body: the solid node
  /// x - c_q and the fluid node x, taken from the solid end so that a link wrapped by a periodic
  /// side stays in the body's frame.
  struct BodyLink {
    int body;
    Vec2 solidEnd, fluidEnd;
  };
  BodyLink bodyLink(std::int64_t n, int q) const {
    const Neighbour s = neighbour(n, -L::cx[q], -L::cy[q], -L::cz[q]);
    const double dx = units_.dx;
    const Vec2 solidEnd((s.ijk[0] + 0.5) * dx, (s.ijk[1] + 0.5) * dx);
    return {bodyAt_[index(s.ijk)], solidEnd, solidEnd + Vec2(L::cx[q], L::cy[q]) * dx};
  }

  /// The wall velocity (lattice units) of a staircase body link: the body's velocity at the
  /// link mid-point, where halfway bounce-back puts the wall.
  std::array<double, 3> staircaseWallVelocity(std::int64_t n, int q) const {
    const BodyLink link = bodyLink(n, q);
    return latticeVelocity(bodies_[link.body].velocity(0.5 * (link.solidEnd + link.fluidEnd)));
  }

  /// Bouzidi, Firdaouss & Lallemand 2001, eq. 5 (BouzidiInterpolatedBounceBack.h): the links of
  /// node n into an interpolated body, wall at the fraction qw of the link from x, i' = q the
  /// direction returning from the wall and i = opp(q):
  ///   qw <  1/2:  f_q(x) = 2 qw f*_i(x) + (1 - 2 qw) f*_i(x + c_q) + delta
  ///   qw >= 1/2:  f_q(x) = f*_i(x) / (2 qw) + (2 qw - 1) / (2 qw) f*_q(x) + delta / (2 qw)
  /// delta = 2 w_q (c_q . u_w) / cs2 with u_w at the wall point; halfway bounce-back where
  /// x + c_q is not a fluid node. The difference from the halfway value (in g[q] on entry) goes
  /// to the rest population, so that the node keeps the mass of halfway bounce-back.
  void interpolateAtBodies(std::int64_t n, double* g) const {
    for (int q = 1; q < L::Q; ++q) {
      const Neighbour s = neighbour(n, -L::cx[q], -L::cy[q], -L::cz[q]);
      if (s.outside() || !isSolid(index(s.ijk))) continue;
      const BodyLink link = bodyLink(n, q);
      const SolidBody& body = bodies_[link.body];
      if (!body.interpolated) continue;
      const double qw = wallFraction(body, link.fluidEnd, link.solidEnd);
      const std::array<double, 3> uWall =
          latticeVelocity(body.velocity(link.fluidEnd + qw * (link.solidEnd - link.fluidEnd)));
      const double delta = movingWallDelta<L>(q, uWall[0], uWall[1], uWall[2]);
      const int i = L::opposite[q];
      const std::int64_t second = fluidNeighbourAlong(n, q);
      double interpolated;
      if (qw < 0.5 && second < 0)
        interpolated = post_[i][n] + delta;
      else if (qw < 0.5)
        interpolated = 2.0 * qw * post_[i][n] + (1.0 - 2.0 * qw) * post_[i][second] + delta;
      else
        interpolated = post_[i][n] / (2.0 * qw) + (2.0 * qw - 1.0) / (2.0 * qw) * post_[q][n] +
                       delta / (2.0 * qw);
      g[0] += g[q] - interpolated;
      g[q] = interpolated;
    }
  }

  /// The node x + c_q if it is a fluid node of the box, else -1.
  std::int64_t fluidNeighbourAlong(std::int64_t n, int q) const {
    const Neighbour s = neighbour(n, L::cx[q], L::cy[q], L::cz[q]);
    if (s.outside() || isSolid(index(s.ijk))) return -1;
    return index(s.ijk);
  }

  /// Zou & He 1997 on a node of an open side: velocity inlet (the node gets the side's
  /// velocity times its profile and ramp, inletProfileFactor and inletRampFactor) or pressure
  /// side (density 1 + drho, no tangential velocity); the unknown populations are closed by
  /// non-equilibrium bounce-back (ZouHeVelocityInlet.h). Open sides never meet at an edge (validateLbmParams), so a node
  /// lies on one at most.
  void closeOpenSide(std::int64_t n, double* g) const {
    for (int a = 0; a < L::D; ++a) {
      const int last = (a == 0 ? nx_ : (a == 1 ? ny_ : nz_)) - 1;
      for (int end = 0; end < 2; ++end) {
        const SideCondition& side = sides_.side[2 * a + end];
        if (!side.isOpen() || coordinate(n, a) != (end == 0 ? 0 : last)) continue;
        const OpenSideGeometry geometry{a, end == 0 ? 1 : -1};
        if (side.type == SideCondition::Type::Pressure)
          zouHePressure<L, double>(g, geometry, side.density - 1.0, force_[0], force_[1],
                                   force_[2]);
        else {
          const int ijk[3] = {coordinate(n, 0), coordinate(n, 1), coordinate(n, 2)};
          const int dims[3] = {nx_, ny_, nz_};
          const double factor =
              inletProfileFactor(side, a, ijk, dims) * inletRampFactor(side, streamed_);
          zouHeVelocity<L, double>(g, geometry, side.velocity[0] * factor,
                                   side.velocity[1] * factor, side.velocity[2] * factor, force_[0],
                                   force_[1], force_[2]);
        }
      }
    }
  }

  // ---- geometry --------------------------------------------------------------------------

  /// A node is solid if its centre lies in a body (the first one listed); bodies are 2D shapes,
  /// extruded along z in 3D (SolidBody.h).
  void markSolidNodes() {
    bodyAt_.assign(nodeCount(), -1);
    for (std::int64_t n = 0; n < nodeCount(); ++n) {
      const Vec2 centre(units_.nodeX(coordinate(n, 0)), units_.nodeY(coordinate(n, 1)));
      for (std::size_t b = 0; b < bodies_.size() && bodyAt_[n] < 0; ++b)
        if (bodies_[b].contains(centre)) bodyAt_[n] = static_cast<int>(b);
    }
  }

  std::array<double, 3> latticeVelocity(const Vec2& u) const {
    return {units_.toLatticeVelocity(u.x()), units_.toLatticeVelocity(u.y()), 0.0};
  }
  int coordinate(std::int64_t n, int axis) const {
    if (axis == 0) return static_cast<int>(n % nx_);
    if (axis == 1) return static_cast<int>(n / nx_ % ny_);
    return static_cast<int>(n / (std::int64_t(nx_) * ny_));
  }
  std::int64_t index(const int (&ijk)[3]) const {
    return (std::int64_t(ijk[2]) * ny_ + ijk[1]) * nx_ + ijk[0];
  }

  LatticeUnits units_;
  BoxSides sides_;
  bool trt_;
  int nx_, ny_, nz_;
  double force_[3];  ///< lattice body acceleration g dt^2 / dx
  std::vector<SolidBody> bodies_;
  std::vector<int> bodyAt_;  ///< body owning each node, -1 for fluid nodes
  long long streamed_ = 0;   ///< streaming steps done: the time (in steps) the populations reach
  Populations f_, post_;
};

}  // namespace fluidviz::lbm
