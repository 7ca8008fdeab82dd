#pragma once
// Moving walls of the lattice gas by biased reflection (Wolf-Gladrow 2000, "Lattice-Gas Cellular
// Automata and Lattice Boltzmann Models", chapter 3: boundary conditions of LGCA): a solid node
// of a wall that slides with velocity U first bounces every particle back (no-slip at rest), then
// turns some of the reflected particles by 60 degrees towards U, each with a probability set by
// U. A turn moves one particle from channel j to the empty neighbouring channel k, so the number
// of particles is conserved exactly; the momentum c_k - c_j it adds is the wall's push.
//
// Probability of a turn j -> k. At a flat wall along x a reflected particle leaves along c_2 (it
// arrived along c_5) and turns to c_1 (its specular reflection) when c_1 is empty, i.e. when no
// particle arrived along c_4. For fluid arriving in the linearised equilibrium at the wall's own
// velocity U, N_i = d + alpha c_i . U with alpha = b d / 3 (b channels; Initialisation.h),
// bounce-back sends out N_1 - N_2 = -alpha U where the equilibrium wants +alpha U: the turns must
// move alpha U = alpha (c_1 - c_2) . U particles per node and step, and they happen at the rate
// q N_5 (1 - N_4). Hence, for any pair,
//   q = alpha (c_k - c_j) . U / ((d - alpha c_j . U) (1 - d + alpha c_k . U)),
// the incoming occupations at the wall's velocity (N_opp(j) = d - alpha c_j . U). A wall at U then
// leaves a fluid at U unchanged on average, as bounce-back leaves a fluid at rest unchanged: the
// no-slip condition at the moving wall. (Dropping the first-order terms of the denominator, i.e.
// q = alpha gain / (d (1 - d)), makes the wall drive the fluid about 15% too fast at U = 0.1.)
// At the stepped rim of a roller a reflected particle may have to pass through a middle channel
// (on a side whose normal is c_0, from c_5 via c_0 to c_1): each channel's shortfall
// 2 alpha c_j . U is carried by the turns along the run of fluid channels, so the pair rates follow
// from those flows (wallNodeMotion), with the local wall velocity omega x r.
#include <array>
#include <cstdint>

#include "solvers/fhp/collision/CollisionTable.h"

namespace fluidviz::fhp {

/// The turns of one moving wall node, set up from its wall velocity and its fluid neighbours.
struct WallNodeMotion {
  int x = 0, y = 0;
  std::array<std::int8_t, 6> turnTo{-1, -1, -1, -1, -1, -1};  ///< k for a particle leaving along j
  std::array<std::uint64_t, 6> threshold{};                    ///< q 2^64 (RandomBits.h)
};

/// The linearised equilibrium the turns are calibrated on: density d per channel, alpha = b d / 3.
struct WallEquilibrium {
  double d = 0.25;
  double alpha = 7.0 * 0.25 / 3.0;
};
WallEquilibrium wallEquilibrium(Model model, double d);

/// The turn probability of a flat wall along a lattice row at speed |u|:
/// alpha |u| / ((d + alpha |u| / 2) (1 - d + alpha |u| / 2)); callers refuse walls where it
/// exceeds 1 (elsewhere, at a staircase, probabilities above 1 are clipped).
double flatWallTurnProbability(const WallEquilibrium& e, double speed);

/// The turns at node (x, y) of a wall moving with velocity u (links per step), for each run of
/// consecutive fluid neighbours (bits of fluidNeighbours): the flow each pair of neighbouring
/// channels must carry (linkFlows in MovingWall.cpp; alpha (c_k - c_j) . u at a flat wall) divided
/// by the rate at which the pair can turn, (d - alpha c_j . u) (1 - d + alpha c_k . u); clipped
/// at 1. A channel with flows to both sides keeps the larger.
WallNodeMotion wallNodeMotion(int x, int y, const std::array<double, 2>& u,
                              unsigned fluidNeighbours, const WallEquilibrium& e);

/// The node rule after bounce-back, shared by both steppers: the particles of `bounced` are
/// tried in channel order j = 0..5, each turned to turnTo[j] if that channel was empty after the
/// bounce-back and still is (so each turn happens at the rate the calibration assumes) and its
/// random draw (stream 2 + j of the node's counter hash) falls below threshold[j].
std::uint8_t turnReflectedParticles(std::uint8_t bounced, const WallNodeMotion& m,
                                    std::uint64_t seed, std::uint64_t t);

}  // namespace fluidviz::fhp
