#pragma once
// The 2D node grid the sketch filters work on, with what lies beyond each side, and the discrete
// operators they share: the face-flux Laplacian, the central-difference divergence, separable
// Gaussian smoothing. Component arrays are x fastest (Grid::index).
#include <vector>

#include <Eigen/SparseCore>

#include "fieldviz/core/Grid.h"
#include "filters/sketch/SketchParams.h"

namespace fluidviz::sketch {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct PlaneGrid {
  int nx = 0, ny = 0;
  double hx = 1.0, hy = 1.0;
  SketchBoundary bx = SketchBoundary::zero_flux;
  SketchBoundary by = SketchBoundary::zero_flux;

  /// Throws std::invalid_argument for a 3D grid or one with fewer than 2 nodes along x or y.
  static PlaneGrid of(const Grid& grid, SketchBoundary bx, SketchBoundary by);
  int size() const { return nx * ny; }
  int index(int i, int j) const { return j * nx + i; }
  /// Neighbour along x (di = +-1) or y (dj = +-1); -1 beyond a zero-flux side.
  int neighbour(int i, int j, int di, int dj) const;
  /// sum over axes of 1 / h^2.
  double inverseSquareSpacingSum() const { return 1.0 / (hx * hx) + 1.0 / (hy * hy); }
};

/// The 5-point Laplacian as a sum of face fluxes: (L u)_i = sum over faces (u_nb - u_i) / h^2,
/// a face across a zero-flux side carrying nothing. Symmetric and negative semi-definite, so
/// -mu L + diag(b) is symmetric positive definite once some b > 0.
SparseMatrix laplacianMatrix(const PlaneGrid& g);
/// The same operator applied matrix-free (the explicit GVF step).
std::vector<double> applyLaplacian(const PlaneGrid& g, const std::vector<double>& u);
/// sum over faces of (u_nb - u_i)^2 / h^2 (each face once) = -u^T L u: the discrete |grad u|^2
/// integral divided by the cell area.
double gradientEnergy(const PlaneGrid& g, const std::vector<double>& u);

/// Divergence of (u, v) by central differences, (u_{i+1} - u_{i-1}) / (2 hx) + ...; periodic
/// sides wrap, at a zero-flux side a one-sided difference (u_1 - u_0) / hx. Rows: nodes; columns:
/// the u components of every node, then the v components.
SparseMatrix divergenceMatrix(const PlaneGrid& g);

/// Separable Gaussian smoothing of a node array: the kernel exp(-k^2 h^2 / (2 sigma^2)) truncated
/// at 4 sigma and normalised to sum 1 along each axis; periodic sides wrap, zero-flux sides
/// reflect about the face half a cell outside the last node (node -1 reads node 0).
/// sigma in cells; 0 returns u.
std::vector<double> gaussianSmooth(const PlaneGrid& g, const std::vector<double>& u,
                                   double sigmaCells);

}  // namespace fluidviz::sketch
