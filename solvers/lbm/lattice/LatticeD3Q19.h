#pragma once
// D3Q19 velocity set (Qian, d'Humieres & Lallemand 1992): the rest velocity, the 6 axis
// neighbours (weight 1/18) and the 12 edge diagonals (weight 1/36), c_s^2 = 1/3. Same interface
// as LatticeD2Q9.h. Opposite directions are neighbours in the numbering (q odd, q + 1), so that
// the collision's pair split (CollisionBGK.h, CollisionTRT.h) visits them in order.
//
//   q:  0 rest;  1,2 = +-x;  3,4 = +-y;  5,6 = +-z;
//       7,8 = +-(1,1,0);  9,10 = +-(1,0,1);  11,12 = +-(0,1,1);
//       13,14 = +-(1,-1,0);  15,16 = +-(1,0,-1);  17,18 = +-(0,1,-1)
#include <array>

#include "solvers/lbm/lattice/LatticeD2Q9.h"

namespace fluidviz::lbm {

struct LatticeD3Q19 {
  static constexpr const char* name = "D3Q19";
  static constexpr int D = 3;
  static constexpr int Q = 19;
  static constexpr double cs2 = 1.0 / 3.0;
  static constexpr std::array<int, Q> cx{0, 1, -1, 0, 0, 0, 0, 1, -1, 1, -1, 0, 0, 1, -1, 1, -1, 0, 0};
  static constexpr std::array<int, Q> cy{0, 0, 0, 1, -1, 0, 0, 1, -1, 0, 0, 1, -1, -1, 1, 0, 0, 1, -1};
  static constexpr std::array<int, Q> cz{0, 0, 0, 0, 0, 1, -1, 0, 0, 1, -1, 1, -1, 0, 0, -1, 1, -1, 1};
  static constexpr std::array<double, Q> w{
      1.0 / 3,  1.0 / 18, 1.0 / 18, 1.0 / 18, 1.0 / 18, 1.0 / 18, 1.0 / 18,
      1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36,
      1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};
  static constexpr std::array<int, Q> opposite{0,  2,  1,  4,  3,  6,  5,  8,  7, 10,
                                               9, 12, 11, 14, 13, 16, 15, 18, 17};
};

static_assert(detail::isConsistentLattice<LatticeD3Q19>(), "D3Q19 tables are inconsistent");

}  // namespace fluidviz::lbm
