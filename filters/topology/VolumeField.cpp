#include "filters/topology/VolumeField.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fluidviz::topology {

namespace {
constexpr std::array<std::array<int, 3>, 6> kPermutations = {
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
}  // namespace

std::array<KuhnTetrahedron, 6> kuhnTetrahedra(const std::array<int, 3>& cell) {
  std::array<KuhnTetrahedron, 6> out;
  for (int t = 0; t < 6; ++t) {
    const auto& p = kPermutations[t];
    Eigen::Vector3i c = Eigen::Vector3i::Zero();
    out[t].cell = cell;
    out[t].corner[0] = c;
    for (int m = 0; m < 3; ++m) {
      c[p[m]] = 1;
      out[t].corner[m + 1] = c;
    }
  }
  return out;
}

VolumeField::VolumeField(const VectorField& field) : grid_(field.grid) {
  for (int a = 0; a < 3; ++a)
    if (grid_.dims[a] < 2)
      throw std::invalid_argument("volume topology needs at least 2 nodes along every axis");
  if (field.values.size() != grid_.nodeCount())
    throw std::invalid_argument("vector field has " + std::to_string(field.values.size()) +
                                " values for " + std::to_string(grid_.nodeCount()) + " nodes");
  w_.reserve(field.values.size());
  for (const Vec3& v : field.values)
    w_.emplace_back(v.x() / grid_.spacing[0], v.y() / grid_.spacing[1], v.z() / grid_.spacing[2]);
  buildGradientTable();
}

std::array<int, 3> VolumeField::cellOf(const Vec3& q) const {
  std::array<int, 3> c;
  for (int a = 0; a < 3; ++a)
    c[a] = std::clamp(static_cast<int>(std::floor(q[a])), 0, grid_.dims[a] - 2);
  return c;
}

// Barycentric coordinates in the Kuhn tetrahedron: sort the local coordinates descending,
// s_a >= s_b >= s_c; the weights of 0, e_a, e_a + e_b, (1, 1, 1) are 1 - s_a, s_a - s_b,
// s_b - s_c, s_c.
Vec3 VolumeField::operator()(const Vec3& qIn) const {
  Vec3 q;
  for (int a = 0; a < 3; ++a) q[a] = std::clamp(qIn[a], 0.0, double(grid_.dims[a] - 1));
  const auto c = cellOf(q);
  const Vec3 s(q.x() - c[0], q.y() - c[1], q.z() - c[2]);
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return s[a] > s[b]; });
  Eigen::Vector3i p(c[0], c[1], c[2]);
  Vec3 value = (1.0 - s[order[0]]) * node(p);
  for (int m = 0; m < 3; ++m) {
    p[order[m]] += 1;
    const double weight = m < 2 ? s[order[m]] - s[order[m + 1]] : s[order[2]];
    value += weight * node(p);
  }
  return value;
}

Mat3 VolumeField::jacobianFiniteDifference(const Vec3& q) const {
  Mat3 j;
  for (int a = 0; a < 3; ++a) {
    Vec3 lo = q, hi = q;
    lo[a] = std::max(q[a] - 1.0, 0.0);
    hi[a] = std::min(q[a] + 1.0, double(grid_.dims[a] - 1));
    j.col(a) = ((*this)(hi) - (*this)(lo)) / (hi[a] - lo[a]);
  }
  return j;
}

Mat3 VolumeField::toWorldJacobian(const Mat3& j_index) const {
  Mat3 j;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) j(r, c) = j_index(r, c) * grid_.spacing[r] / grid_.spacing[c];
  return j;
}

void VolumeField::buildGradientTable() {
  const int nx = grid_.dims[0], ny = grid_.dims[1], nz = grid_.dims[2];
  const std::size_t sx = nx + 1, sy = ny + 1;
  table_.assign(sx * sy * (nz + 1), 0.0);
  auto at = [&](int i, int j, int k) -> double& { return table_[(std::size_t(k) * sy + j) * sx + i]; };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double g0 =
            toWorldJacobian(jacobianFiniteDifference(Vec3(i, j, k))).squaredNorm();
        const double g = std::isfinite(g0) ? g0 : 0.0;  // masked (NaN) nodes add nothing
        at(i + 1, j + 1, k + 1) = g + at(i, j + 1, k + 1) + at(i + 1, j, k + 1) +
                                  at(i + 1, j + 1, k) - at(i, j, k + 1) - at(i, j + 1, k) -
                                  at(i + 1, j, k) + at(i, j, k);
      }
}

double VolumeField::gradientScale(const Vec3& q, double radius) const {
  const int r = static_cast<int>(std::ceil(radius));
  std::array<int, 3> lo, hi;
  for (int a = 0; a < 3; ++a) {
    const int c = static_cast<int>(std::lround(std::clamp(q[a], 0.0, double(grid_.dims[a] - 1))));
    lo[a] = std::max(c - r, 0);
    hi[a] = std::min(c + r, grid_.dims[a] - 1) + 1;  // exclusive, table coordinates
  }
  const std::size_t sx = grid_.dims[0] + 1, sy = grid_.dims[1] + 1;
  auto at = [&](int i, int j, int k) { return table_[(std::size_t(k) * sy + j) * sx + i]; };
  const double sum = at(hi[0], hi[1], hi[2]) - at(lo[0], hi[1], hi[2]) - at(hi[0], lo[1], hi[2]) -
                     at(hi[0], hi[1], lo[2]) + at(lo[0], lo[1], hi[2]) + at(lo[0], hi[1], lo[2]) +
                     at(hi[0], lo[1], lo[2]) - at(lo[0], lo[1], lo[2]);
  const double count = double(hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  return std::sqrt(std::max(sum, 0.0) / count);
}

Vec3 VolumeField::toWorld(const Vec3& q) const {
  return {grid_.origin[0] + q.x() * grid_.spacing[0], grid_.origin[1] + q.y() * grid_.spacing[1],
          grid_.origin[2] + q.z() * grid_.spacing[2]};
}

double VolumeField::distanceToBoundary(const Vec3& q) const {
  double d = 1e300;
  for (int a = 0; a < 3; ++a) d = std::min({d, q[a], grid_.dims[a] - 1 - q[a]});
  return d;
}

}  // namespace fluidviz::topology
