#include "solvers/fhp/lattice/Initialisation.h"

#include <stdexcept>
#include <string>

#include "solvers/fhp/kernel/RandomBits.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {

void fillEquilibrium(BitLattice& lattice, Model model, double d, const VelocityAt& velocity,
                     std::uint64_t seed) {
  const int b = channelCount(model);
  const double rho = b * d;
  for (int y = 0; y < lattice.ny(); ++y) {
    for (int x = 0; x < lattice.nx(); ++x) {
      if (lattice.isSolid(x, y)) {
        lattice.setNode(x, y, 0);
        continue;
      }
      const auto u = velocity(x, y);
      std::uint8_t s = 0;
      for (int c = 0; c < b; ++c) {
        const double p = d + rho / 3.0 * (kCx[c] * u[0] + kCy[c] * u[1]);
        if (p < 0.0 || p > 1.0)
          throw std::invalid_argument("FHP initial state: channel probability " +
                                      std::to_string(p) + " outside [0, 1] at node (" +
                                      std::to_string(x) + ", " + std::to_string(y) +
                                      "): velocity too large for the density");
        const std::uint64_t r = counterHash(seed, 0, static_cast<std::uint64_t>(y),
                                            static_cast<std::uint64_t>(x) * 8 + c, 2);
        if (r < probabilityThreshold(p)) s |= static_cast<std::uint8_t>(1u << c);
      }
      lattice.setNode(x, y, s);
    }
  }
}

}  // namespace fluidviz::fhp
