#pragma once
// Shared by the FHP hydrodynamics tests: Fourier modes and row currents of the lattice gas along x.
// The transport coefficients they compare with (Frisch et al. 1987, Complex Systems 1:649:
// latticeViscosity, soundSpeed, galileanFactor) are the solver's own, in solvers/fhp/FhpParams.h,
// checked against hand-computed values in FhpParams_test.cpp.
#include <bit>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "solvers/fhp/FhpParams.h"
#include "solvers/fhp/collision/CollisionTable.h"
#include "solvers/fhp/lattice/BitLattice.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp::testing {

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
