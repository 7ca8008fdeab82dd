#pragma once
// RMS of a nodal quantity over square windows of a 2D lattice in O(1) per query, from a
// summed-area table (Crow 1984, "Summed-area tables for texture mapping", SIGGRAPH). The
// classifiers judge a determinant against the local size of the field's derivatives (the
// Jacobian of a vector field, the Hessian of a scalar field) through it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace fluidviz::topology {

class WindowRms {
 public:
  WindowRms() = default;
  /// squares[j * nx + i] >= 0: the squared quantity at node (i, j).
  WindowRms(const std::vector<double>& squares, int nx, int ny)
      : nx_(nx), ny_(ny), table_(std::size_t(nx + 1) * (ny + 1), 0.0) {
    const std::size_t w = nx_ + 1;
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i)
        table_[(j + 1) * w + i + 1] = squares[std::size_t(j) * nx_ + i] + table_[j * w + i + 1] +
                                      table_[(j + 1) * w + i] - table_[j * w + i];
  }

  /// RMS over the nodes of the square window of half-width `radius` cells around the lattice
  /// point q (node coordinates), clipped to the lattice.
  double around(const Eigen::Vector2d& q, double radius) const {
    const int r = static_cast<int>(std::ceil(radius));
    const int ci = static_cast<int>(std::lround(std::clamp(q.x(), 0.0, double(nx_ - 1))));
    const int cj = static_cast<int>(std::lround(std::clamp(q.y(), 0.0, double(ny_ - 1))));
    const int i0 = std::max(ci - r, 0), i1 = std::min(ci + r, nx_ - 1);
    const int j0 = std::max(cj - r, 0), j1 = std::min(cj + r, ny_ - 1);
    const std::size_t w = nx_ + 1;
    const double sum = table_[(j1 + 1) * w + i1 + 1] - table_[j0 * w + i1 + 1] -
                       table_[(j1 + 1) * w + i0] + table_[j0 * w + i0];
    return std::sqrt(std::max(sum, 0.0) / (double(i1 - i0 + 1) * (j1 - j0 + 1)));
  }

 private:
  int nx_ = 0, ny_ = 0;
  std::vector<double> table_;  // (nx + 1) x (ny + 1), zero first row and column
};

}  // namespace fluidviz::topology
