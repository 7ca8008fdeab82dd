#pragma once
// D2Q9 velocity set (Qian, d'Humieres & Lallemand 1992): compile-time data behind the interface
// every lattice offers (LatticeD3Q19.h is the other one): name, D, Q, velocities (cx, cy, cz),
// weights w, opposite(q), c_s^2. A 2D lattice has cz = 0 for every q, so that the kernels are
// written once for both dimensions (the zero terms vanish at compile time).
//
//   6  2  5      q:  0 rest, 1-4 axis (E N W S), 5-8 diagonals (NE NW SW SE)
//    \ | /
//   3--0--1
//    / | \ .
//   7  4  8
#include <array>

namespace fluidviz::lbm {

struct LatticeD2Q9 {
  static constexpr const char* name = "D2Q9";
  static constexpr int D = 2;
  static constexpr int Q = 9;
  static constexpr double cs2 = 1.0 / 3.0;  ///< squared lattice speed of sound
  static constexpr std::array<int, Q> cx{0, 1, 0, -1, 0, 1, -1, -1, 1};
  static constexpr std::array<int, Q> cy{0, 0, 1, 0, -1, 1, 1, -1, -1};
  static constexpr std::array<int, Q> cz{0, 0, 0, 0, 0, 0, 0, 0, 0};
  static constexpr std::array<double, Q> w{4.0 / 9,  1.0 / 9,  1.0 / 9,  1.0 / 9, 1.0 / 9,
                                           1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};
  static constexpr std::array<int, Q> opposite{0, 3, 4, 1, 2, 7, 8, 5, 6};
};

namespace detail {
// Isotropy conditions the second-order equilibrium relies on (Krueger et al. 2017, ch. 3):
// sum w = 1, sum w c_a = 0, sum w c_a c_b = cs2 delta_ab, and opposite(q) = -c_q; a 2D lattice
// has no z velocities.
template <class L>
constexpr bool isConsistentLattice() {
  auto near = [](double a, double b) { return a - b < 1e-15 && b - a < 1e-15; };
  double w = 0, first[3] = {0, 0, 0}, second[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int q = 0; q < L::Q; ++q) {
    const int c[3] = {L::cx[q], L::cy[q], L::cz[q]};
    w += L::w[q];
    for (int a = 0; a < 3; ++a) {
      first[a] += L::w[q] * c[a];
      for (int b = 0; b < 3; ++b) second[a][b] += L::w[q] * c[a] * c[b];
    }
    const int o = L::opposite[q];
    if (L::cx[o] != -L::cx[q] || L::cy[o] != -L::cy[q] || L::cz[o] != -L::cz[q]) return false;
    if (L::D == 2 && L::cz[q] != 0) return false;
  }
  if (!near(w, 1)) return false;
  for (int a = 0; a < 3; ++a) {
    if (!near(first[a], 0)) return false;
    for (int b = 0; b < 3; ++b) {
      const double expected = (a == b && a < L::D) ? L::cs2 : 0.0;
      if (!near(second[a][b], expected)) return false;
    }
  }
  return true;
}
}  // namespace detail

static_assert(detail::isConsistentLattice<LatticeD2Q9>(), "D2Q9 tables are inconsistent");

}  // namespace fluidviz::lbm
