#pragma once
// Initial occupation of the lattice gas: each channel of each fluid node filled independently with
// the probability of the linearised equilibrium (Frisch et al. 1987, section 4: the Fermi-Dirac
// distribution to first order in u), N_i = d + (rho / 3) c_i . u with rho = b d the mean number of
// particles per node (b = 6 channels for FHP-I, 7 with the rest particle), so that the expected
// momentum per node is rho u. Solid nodes start empty.
#include <cstdint>
#include <functional>

#include "solvers/fhp/collision/CollisionTable.h"
#include "solvers/fhp/lattice/BitLattice.h"

namespace fluidviz::fhp {

/// Velocity (in links per step) wanted at node (x, y): {ux, uy}.
using VelocityAt = std::function<std::array<double, 2>(int x, int y)>;

/// Throws std::invalid_argument when a channel probability leaves [0, 1] (u too large for d).
void fillEquilibrium(BitLattice& lattice, Model model, double d, const VelocityAt& velocity,
                     std::uint64_t seed);

/// An inflow zone (after a step): the fluid nodes of columns 0 .. columns - 1 replaced by fresh
/// draws from the equilibrium at velocity u (links per step), independent at every step.
void refillEquilibrium(BitLattice& lattice, Model model, double d, const std::array<double, 2>& u,
                       std::uint64_t seed, int columns);

}  // namespace fluidviz::fhp
