#include "filters/sketch/grid/PlaneGrid.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fluidviz::sketch {

PlaneGrid PlaneGrid::of(const Grid& grid, SketchBoundary bx, SketchBoundary by) {
  grid.validate();
  if (!grid.is2D()) throw std::invalid_argument("sketched flows are 2D: the grid has dims[2] > 1");
  if (grid.dims[0] < 2 || grid.dims[1] < 2)
    throw std::invalid_argument("the sketch grid needs at least 2 nodes along x and y, has " +
                                std::to_string(grid.dims[0]) + " x " +
                                std::to_string(grid.dims[1]));
  return {grid.dims[0], grid.dims[1], grid.spacing[0], grid.spacing[1], bx, by};
}

namespace {
int wrapOrNone(int k, int n, SketchBoundary b) {
  if (k >= 0 && k < n) return k;
  if (b == SketchBoundary::zero_flux) return -1;
  return (k + n) % n;
}
}  // namespace

int PlaneGrid::neighbour(int i, int j, int di, int dj) const {
  const int a = wrapOrNone(i + di, nx, bx);
  const int b = wrapOrNone(j + dj, ny, by);
  return a < 0 || b < 0 ? -1 : index(a, b);
}

namespace {
/// Calls f(node, neighbour, 1 / h^2) once per face between two nodes: the face towards +x and
/// the face towards +y of every node that has such a neighbour.
template <class F>
void forEachFace(const PlaneGrid& g, F&& f) {
  const double wx = 1.0 / (g.hx * g.hx), wy = 1.0 / (g.hy * g.hy);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int n = g.index(i, j);
      if (const int e = g.neighbour(i, j, 1, 0); e >= 0) f(n, e, wx);
      if (const int north = g.neighbour(i, j, 0, 1); north >= 0) f(n, north, wy);
    }
}
}  // namespace

SparseMatrix laplacianMatrix(const PlaneGrid& g) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(g.size()) * 5);
  forEachFace(g, [&](int a, int b, double w) {
    t.emplace_back(a, b, w);
    t.emplace_back(b, a, w);
    t.emplace_back(a, a, -w);
    t.emplace_back(b, b, -w);
  });
  SparseMatrix l(g.size(), g.size());
  l.setFromTriplets(t.begin(), t.end());  // duplicates (periodic n = 2, diagonals) are summed
  return l;
}

std::vector<double> applyLaplacian(const PlaneGrid& g, const std::vector<double>& u) {
  std::vector<double> out(u.size(), 0.0);
  forEachFace(g, [&](int a, int b, double w) {
    const double flux = w * (u[b] - u[a]);
    out[a] += flux;
    out[b] -= flux;
  });
  return out;
}

double gradientEnergy(const PlaneGrid& g, const std::vector<double>& u) {
  double sum = 0.0;
  forEachFace(g, [&](int a, int b, double w) { sum += w * (u[b] - u[a]) * (u[b] - u[a]); });
  return sum;
}

SparseMatrix divergenceMatrix(const PlaneGrid& g) {
  std::vector<Eigen::Triplet<double>> t;
  const int n = g.size();
  // d/dx (column offset 0) and d/dy (column offset n) of node (i, j) along one axis.
  auto difference = [&](int row, int i, int j, int di, int dj, double h, int offset) {
    const int plus = g.neighbour(i, j, di, dj), minus = g.neighbour(i, j, -di, -dj);
    const int self = g.index(i, j);
    if (plus >= 0 && minus >= 0) {
      t.emplace_back(row, offset + plus, 0.5 / h);
      t.emplace_back(row, offset + minus, -0.5 / h);
    } else if (plus >= 0) {
      t.emplace_back(row, offset + plus, 1.0 / h);
      t.emplace_back(row, offset + self, -1.0 / h);
    } else if (minus >= 0) {
      t.emplace_back(row, offset + self, 1.0 / h);
      t.emplace_back(row, offset + minus, -1.0 / h);
    }
  };
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const int row = g.index(i, j);
      difference(row, i, j, 1, 0, g.hx, 0);
      difference(row, i, j, 0, 1, g.hy, n);
    }
  SparseMatrix d(n, 2 * n);
  d.setFromTriplets(t.begin(), t.end());
  return d;
}

namespace {
std::vector<double> gaussianKernel(double sigmaCells) {
  const int reach = static_cast<int>(std::ceil(4.0 * sigmaCells));
  std::vector<double> k(static_cast<std::size_t>(2 * reach + 1));
  double sum = 0.0;
  for (int m = -reach; m <= reach; ++m) {
    const double x = m / sigmaCells;
    sum += k[static_cast<std::size_t>(m + reach)] = std::exp(-0.5 * x * x);
  }
  for (double& w : k) w /= sum;
  return k;
}

/// Index read for position k on an axis of n nodes: wrapped, or reflected about the outer faces.
int readIndex(int k, int n, SketchBoundary b) {
  if (b == SketchBoundary::periodic) return ((k % n) + n) % n;
  const int period = 2 * n;
  int m = ((k % period) + period) % period;
  return m < n ? m : period - 1 - m;
}
}  // namespace

std::vector<double> gaussianSmooth(const PlaneGrid& g, const std::vector<double>& u,
                                   double sigmaCells) {
  if (sigmaCells < 0.0) throw std::invalid_argument("Gaussian sigma must be >= 0");
  if (sigmaCells == 0.0) return u;
  const std::vector<double> k = gaussianKernel(sigmaCells);
  const int reach = static_cast<int>(k.size() / 2);
  std::vector<double> alongX(u.size(), 0.0), out(u.size(), 0.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      double s = 0.0;
      for (int m = -reach; m <= reach; ++m)
        s += k[static_cast<std::size_t>(m + reach)] * u[g.index(readIndex(i + m, g.nx, g.bx), j)];
      alongX[g.index(i, j)] = s;
    }
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      double s = 0.0;
      for (int m = -reach; m <= reach; ++m)
        s += k[static_cast<std::size_t>(m + reach)] *
             alongX[g.index(i, readIndex(j + m, g.ny, g.by))];
      out[g.index(i, j)] = s;
    }
  return out;
}

}  // namespace fluidviz::sketch
