#include "filters/resample/LinearResample.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "fieldviz/particles/UniformGridNeighborSearch.h"

namespace fluidviz::resample {

namespace {

// One particle within a node's support: its index, V_j W_j (then psi_j = V_j W_j c . p_j) and
// basis vector p_j.
template <int D>
struct Neighbour {
  std::size_t index;
  double weight;
  Eigen::Matrix<double, D + 1, 1> p;
};

// The particle positions the search sees: in 2D with z = 0, so that distances are in-plane (as
// the scatter's), whatever z the particles carry.
std::vector<Vec3> searchPositions(const detail::SortedParticles& sp, int dimension) {
  std::vector<Vec3> x(sp.x, sp.x + sp.order.size());
  if (dimension == 2)
    for (Vec3& v : x) v[2] = 0.0;
  return x;
}

particles::UniformGridNeighborSearch makeSearch(const std::vector<Vec3>& x, int dimension,
                                                double support) {
  Vec3 lower = x.front(), upper = x.front();
  for (const Vec3& v : x) lower = lower.cwiseMin(v), upper = upper.cwiseMax(v);
  // Grown by the support: the box must not be flat (particles on a line or plane).
  const Vec3 pad = Vec3::Constant(support);
  particles::UniformGridNeighborSearch search(dimension, lower - pad, upper + pad, support);
  search.build(x);
  return search;
}

// Gershgorin's discs bound the eigenvalues of M: lambda_min >= min_i (M_ii - R_i) and
// lambda_max <= max_i (M_ii + R_i), R_i = sum_{k != i} |M_ik|. When those bounds already give a
// ratio >= kMinMomentConditioning, so does the spectrum: the decomposition is skipped (most
// interior nodes, where M is nearly diagonal) and the decision is the same.
template <int D>
bool gershgorinConditioned(const Eigen::Matrix<double, D + 1, D + 1>& m) {
  double lower = m(0, 0), upper = 0.0;
  for (int i = 0; i <= D; ++i) {
    const double r = m.row(i).cwiseAbs().sum() - std::abs(m(i, i));
    lower = std::min(lower, m(i, i) - r);
    upper = std::max(upper, m(i, i) + r);
  }
  return lower > 0.0 && lower >= kMinMomentConditioning * upper;
}

// M of eq. (4) well enough conditioned for a linear fit: at least d+1 particles, and
// lambda_min / lambda_max >= kMinMomentConditioning.
template <int D>
bool supportsLinearFit(const Eigen::Matrix<double, D + 1, D + 1>& m, std::size_t neighbours) {
  if (neighbours < static_cast<std::size_t>(D + 1)) return false;
  if (gershgorinConditioned<D>(m)) return true;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D + 1, D + 1>> eigen(
      m, Eigen::EigenvaluesOnly);
  const auto& lambda = eigen.eigenvalues();  // ascending
  return lambda[D] > 0.0 && lambda[0] >= kMinMomentConditioning * lambda[D];
}

// Eq. (4) at node n (position x) for every resampled component; false (nothing written) where
// the neighbourhood does not support it.
template <int D, class Kernel>
bool firstOrderNode(const particles::UniformGridNeighborSearch& search, const Kernel& kernel,
                    const detail::SortedParticles& sp, const detail::OutputTargets& out,
                    std::size_t n, const Vec3& x, std::vector<Neighbour<D>>& near) {
  const double support = kernel.support(), invH = 2.0 / support;
  near.clear();
  search.forEachWithin(x, support, [&](int j, const Vec3& d, double r2) {
    const double w = kernel.W(std::sqrt(r2));
    if (w <= 0.0) return;
    const std::size_t i = static_cast<std::size_t>(j);
    Neighbour<D>& b = near.emplace_back();
    b.index = i;
    b.weight = (sp.volume ? sp.volume[i] : sp.uniformVolume) * w;
    b.p[0] = 1.0;
    for (int a = 0; a < D; ++a) b.p[a + 1] = -d[a] * invH;  // (x_j - x) / h
  });
  Eigen::Matrix<double, D + 1, D + 1> m = Eigen::Matrix<double, D + 1, D + 1>::Zero();
  for (const Neighbour<D>& b : near) m.noalias() += b.weight * b.p * b.p.transpose();
  if (!supportsLinearFit<D>(m, near.size())) return false;
  // e1^T M^-1 sum_j w_j p_j A_j = sum_j w_j (c . p_j) A_j with M c = e1 (M is symmetric).
  const Eigen::Matrix<double, D + 1, 1> c =
      m.ldlt().solve(Eigen::Matrix<double, D + 1, 1>::Unit(0));
  for (Neighbour<D>& b : near) b.weight *= c.dot(b.p);  // the corrected weight psi_j
  for (std::size_t s = 0; s < sp.columns.size(); ++s) {
    const detail::SortedParticles::Column& column = sp.columns[s];
    double value = 0.0;
    for (const Neighbour<D>& b : near) value += b.weight * column.data[b.index * column.stride];
    out.base[s][n * out.stride[s]] = value;
  }
  return true;
}

template <int D, class Kernel>
void correctNodes(const Grid& g, const Kernel& kernel, const detail::SortedParticles& sp,
                  const detail::OutputTargets& out, double* order) {
  const std::vector<Vec3> x = searchPositions(sp, D);
  const particles::UniformGridNeighborSearch search = makeSearch(x, D, kernel.support());
  const int layers = g.dims[D - 1];
  // Threads take whole layers of the slowest axis (z in 3D, y in 2D); nodes are independent.
#pragma omp parallel
  {
    std::vector<Neighbour<D>> near;
#pragma omp for schedule(dynamic, 1)
    for (int layer = 0; layer < layers; ++layer) {
      const int k = D == 3 ? layer : 0;
      const int jFirst = D == 3 ? 0 : layer, jLast = D == 3 ? g.dims[1] - 1 : layer;
      for (int j = jFirst; j <= jLast; ++j)
        for (int i = 0; i < g.dims[0]; ++i) {
          const std::size_t n = g.index(i, j, k);
          Vec3 node = g.position(i, j, k);
          if (D == 2) node[2] = 0.0;  // as the search positions
          const bool first =
              out.mask[n] == 1.0 && firstOrderNode<D>(search, kernel, sp, out, n, node, near);
          order[n] = first ? 1.0 : 0.0;
        }
    }
  }
}

}  // namespace

void correctToFirstOrder(const Grid& grid, int dimension, const InterpolationKernel& kernel,
                         const detail::SortedParticles& particles,
                         const detail::OutputTargets& out, double* order) {
  if (particles.order.empty()) return;
  std::visit(
      [&](const auto& k) {
        if (dimension == 2)
          correctNodes<2>(grid, k, particles, out, order);
        else
          correctNodes<3>(grid, k, particles, out, order);
      },
      kernel);
}

}  // namespace fluidviz::resample
