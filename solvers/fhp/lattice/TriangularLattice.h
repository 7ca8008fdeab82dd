#pragma once
// Geometry of the FHP triangular lattice (Frisch, Hasslacher & Pomeau 1986): six unit velocities
// c_i = (cos(2 pi i / 6), sin(2 pi i / 6)), i = 0..5, and an optional rest particle (channel 6,
// FHP-II and FHP-III; Frisch et al. 1987, section 2).
//
// Nodes are stored in rows: node (x, y) sits at (x + (y odd ? 1/2 : 0), y sqrt(3)/2), so the
// lattice is a square array whose odd rows are shifted by half a link. A link in direction 1, 2,
// 4 or 5 changes the row, and its x offset depends on the parity of the row it starts from
// (Wolf-Gladrow 2000, section 3.2): from an even row the up-right neighbour is (x, y + 1), from an
// odd row it is (x + 1, y + 1). Periodic rows therefore need an even number of rows.
#include <array>
#include <cstdint>

namespace fluidviz::fhp {

constexpr int kMovingChannels = 6;
constexpr int kRestChannel = 6;
constexpr int kMaxChannels = 7;

/// Row spacing of the triangular lattice in units of the link length.
constexpr double kRowSpacing = 0.86602540378443864676;  // sqrt(3) / 2

/// Velocity c_i in units where the link length is 1 (channel 6, the rest particle: (0, 0)).
constexpr std::array<double, kMaxChannels> kCx{1.0, 0.5, -0.5, -1.0, -0.5, 0.5, 0.0};
constexpr std::array<double, kMaxChannels> kCy{0.0, kRowSpacing, kRowSpacing, 0.0,
                                               -kRowSpacing, -kRowSpacing, 0.0};

/// The same velocities on an integer basis, exact for conservation checks: (2 c_x, 2 c_y / sqrt 3).
constexpr std::array<int, kMaxChannels> kCx2{2, 1, -1, -2, -1, 1, 0};
constexpr std::array<int, kMaxChannels> kCyInt{0, 1, 1, 0, -1, -1, 0};

/// Row change of a link in direction i.
constexpr std::array<int, kMovingChannels> kDy{0, 1, 1, 0, -1, -1};

constexpr int opposite(int i) { return (i + 3) % kMovingChannels; }

/// x offset of the neighbour in direction i of a node in a row of the given parity.
constexpr int neighbourDx(int i, bool oddRow) {
  switch (i) {
    case 0: return 1;
    case 3: return -1;
    case 1: case 5: return oddRow ? 1 : 0;
    default: return oddRow ? 0 : -1;  // 2, 4
  }
}

}  // namespace fluidviz::fhp
