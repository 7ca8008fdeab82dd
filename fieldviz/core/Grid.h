#pragma once
// Regular (image) grid: node-centred samples on an axis-aligned lattice.
// 2D grids have dims[2] == 1. No VTK here: this is the field model every solver and filter shares.
#include <array>
#include <cstddef>
#include <string>

#include <Eigen/Core>

namespace fluidviz {

using Vec3 = Eigen::Vector3d;

struct Grid {
  std::array<int, 3> dims{1, 1, 1};          ///< nodes along x, y, z; each >= 1
  std::array<double, 3> origin{0.0, 0.0, 0.0};  ///< position of node (0,0,0), in scene units (m)
  std::array<double, 3> spacing{1.0, 1.0, 1.0}; ///< node distance along x, y, z (m); each > 0

  std::size_t nodeCount() const {
    return static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
  }
  bool is2D() const { return dims[2] == 1; }
  std::size_t index(int i, int j, int k = 0) const {
    return (static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i;
  }
  Vec3 position(int i, int j, int k = 0) const {
    return {origin[0] + i * spacing[0], origin[1] + j * spacing[1], origin[2] + k * spacing[2]};
  }
  /// Continuous index coordinates of a point (node i sits at coordinate i).
  Vec3 toIndexSpace(const Vec3& p) const {
    return {(p[0] - origin[0]) / spacing[0], (p[1] - origin[1]) / spacing[1],
            (p[2] - origin[2]) / spacing[2]};
  }
  Vec3 upperCorner() const { return position(dims[0] - 1, dims[1] - 1, dims[2] - 1); }
  bool contains(const Vec3& p) const;
  bool sameShape(const Grid& other) const;

  /// Throws std::invalid_argument naming the offending member when dims or spacing are invalid.
  void validate() const;
  std::string describe() const;
};

}  // namespace fluidviz
