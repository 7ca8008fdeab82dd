#include "solvers/fhp/lattice/Initialisation.h"

#include <stdexcept>
#include <string>

#include "solvers/fhp/kernel/RandomBits.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {

namespace {

// One node drawn from the linearised equilibrium; `stream` and t keep the draws independent.
std::uint8_t equilibriumNode(int b, double d, double rho, const std::array<double, 2>& u,
                             std::uint64_t seed, std::uint64_t t, std::uint64_t stream, int x,
                             int y) {
  std::uint8_t s = 0;
  for (int c = 0; c < b; ++c) {
    const double p = d + rho / 3.0 * (kCx[c] * u[0] + kCy[c] * u[1]);
    if (p < 0.0 || p > 1.0)
      throw std::invalid_argument("FHP initial state: channel probability " + std::to_string(p) +
                                  " outside [0, 1] at node (" + std::to_string(x) + ", " +
                                  std::to_string(y) + "): velocity too large for the density");
    const std::uint64_t r = counterHash(seed, t, static_cast<std::uint64_t>(y),
                                        static_cast<std::uint64_t>(x) * 8 + c, stream);
    if (r < probabilityThreshold(p)) s |= static_cast<std::uint8_t>(1u << c);
  }
  return s;
}

}  // namespace

void fillEquilibrium(BitLattice& lattice, Model model, double d, const VelocityAt& velocity,
                     std::uint64_t seed) {
  const int b = channelCount(model);
  for (int y = 0; y < lattice.ny(); ++y)
    for (int x = 0; x < lattice.nx(); ++x)
      lattice.setNode(x, y, lattice.isSolid(x, y)
                                ? 0
                                : equilibriumNode(b, d, b * d, velocity(x, y), seed, 0, 2, x, y));
}

void refillEquilibrium(BitLattice& lattice, Model model, double d, const std::array<double, 2>& u,
                       std::uint64_t seed, int columns) {
  const int b = channelCount(model);
  for (int y = 0; y < lattice.ny(); ++y)
    for (int x = 0; x < columns; ++x)
      if (!lattice.isSolid(x, y))
        lattice.setNode(x, y, equilibriumNode(b, d, b * d, u, seed, lattice.time(), 3, x, y));
}

}  // namespace fluidviz::fhp
