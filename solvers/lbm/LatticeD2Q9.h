#pragma once
// D2Q9 velocity set (Qian, d'Humieres & Lallemand 1992): compile-time data behind the interface
// every lattice offers (D3Q19 will add cz): Q, D, velocities c_q, weights w_q, opposite(q), c_s^2.
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
  static constexpr std::array<double, Q> w{4.0 / 9,  1.0 / 9,  1.0 / 9,  1.0 / 9, 1.0 / 9,
                                           1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};
  static constexpr std::array<int, Q> opposite{0, 3, 4, 1, 2, 7, 8, 5, 6};
};

namespace detail {
// Isotropy conditions the second-order equilibrium relies on (Krueger et al. 2017, ch. 3):
// sum w = 1, sum w c = 0, sum w c_a c_b = cs2 delta_ab, and opposite(q) = -c_q.
template <class L>
constexpr bool isConsistentLattice() {
  double w = 0, wx = 0, wy = 0, wxx = 0, wyy = 0, wxy = 0;
  for (int q = 0; q < L::Q; ++q) {
    w += L::w[q];
    wx += L::w[q] * L::cx[q];
    wy += L::w[q] * L::cy[q];
    wxx += L::w[q] * L::cx[q] * L::cx[q];
    wyy += L::w[q] * L::cy[q] * L::cy[q];
    wxy += L::w[q] * L::cx[q] * L::cy[q];
    const int o = L::opposite[q];
    if (L::cx[o] != -L::cx[q] || L::cy[o] != -L::cy[q]) return false;
  }
  auto near = [](double a, double b) { return a - b < 1e-15 && b - a < 1e-15; };
  return near(w, 1) && near(wx, 0) && near(wy, 0) && near(wxx, L::cs2) && near(wyy, L::cs2) &&
         near(wxy, 0);
}
}  // namespace detail

static_assert(detail::isConsistentLattice<LatticeD2Q9>(), "D2Q9 tables are inconsistent");

}  // namespace fluidviz::lbm
