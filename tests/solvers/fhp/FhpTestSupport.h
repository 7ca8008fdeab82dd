#pragma once
// Shared by the FHP hydrodynamics tests: the Boltzmann-level transport coefficients of Frisch et
// al. 1987 (Complex Systems 1:649; d = mean occupation per channel, lattice units: link length 1,
// one step per time unit), and Fourier modes of the lattice gas along x.
#include <bit>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "solvers/fhp/collision/CollisionTable.h"
#include "solvers/fhp/lattice/BitLattice.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp::testing {

/// Kinematic shear viscosity (section 6).
inline double boltzmannViscosity(Model m, double d) {
  switch (m) {
    case Model::fhp1: return 1.0 / (12 * d * std::pow(1 - d, 3)) - 0.125;
    case Model::fhp2: return 1.0 / (28 * d * std::pow(1 - d, 3) * (1 - 4 * d / 7)) - 0.125;
    case Model::fhp3: return 1.0 / (28 * d * (1 - d) * (1 - 8 * d * (1 - d) / 7)) - 0.125;
  }
  return 0;
}

/// Sound speed: c_s^2 = 1/2 with six moving channels, 3/7 with the rest particle (section 4).
inline double soundSpeed(Model m) { return m == Model::fhp1 ? std::sqrt(0.5) : std::sqrt(3.0 / 7.0); }

/// Galilean factor g(d) of the advection term div(rho g(rho) u u) (section 4).
inline double galileanFactor(Model m, double d) {
  return m == Model::fhp1 ? (1 - 2 * d) / (2 * (1 - d)) : 7 * (1 - 2 * d) / (12 * (1 - d));
}

/// Mean current along x per node of each row of a lattice without solids: the sum over channels of
/// c_x times the row's particle count in the channel, over nx (what BlockAverager gives for blocks
/// of one row, at the cost of a popcount per word).
inline std::vector<double> rowCurrentX(const BitLattice& lattice) {
  std::vector<double> jx(lattice.ny(), 0.0);
  for (int y = 0; y < lattice.ny(); ++y) {
    for (int c = 0; c < kMovingChannels; ++c) {
      int count = 0;
      for (int w = 0; w < lattice.wordsPerRow(); ++w) count += std::popcount(lattice.word(c, y, w));
      jx[y] += kCx[c] * count;
    }
    jx[y] /= lattice.nx();
  }
  return jx;
}

/// What a Fourier mode sums per node.
enum class Moment { density, currentY };

/// (1 / N) sum over nodes of q(node) exp(-i k x), x the node's position (odd rows shifted by half
/// a link), k = 2 pi / nx: the lattice's longest wave along x. Sums per column first (bits of the
/// channel planes), then over columns.
inline std::complex<double> fourierModeX(const BitLattice& lattice, Moment moment) {
  const int nx = lattice.nx(), ny = lattice.ny(), nw = lattice.wordsPerRow();
  std::vector<double> column[2] = {std::vector<double>(nx, 0.0), std::vector<double>(nx, 0.0)};
  for (int y = 0; y < ny; ++y) {
    std::vector<double>& col = column[y % 2];
    for (int c = 0; c < kMaxChannels; ++c) {
      const double weight = moment == Moment::density ? 1.0 : kCy[c];
      if (weight == 0.0) continue;
      for (int w = 0; w < nw; ++w)
        for (std::uint64_t bits = lattice.word(c, y, w); bits != 0; bits &= bits - 1)
          col[64 * w + std::countr_zero(bits)] += weight;
    }
  }
  const double k = 2 * std::numbers::pi / nx;
  std::complex<double> sum = 0.0;
  for (int parity = 0; parity < 2; ++parity)
    for (int x = 0; x < nx; ++x)
      sum += column[parity][x] * std::polar(1.0, -k * (x + 0.5 * parity));
  return sum / (static_cast<double>(nx) * ny);
}

}  // namespace fluidviz::fhp::testing
